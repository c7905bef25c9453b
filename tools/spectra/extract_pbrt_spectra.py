#!/usr/bin/env python3
"""Writes the spectral data of src/candela/spectrum/ from the tables in pbrt-v4's
src/pbrt/util/spectrum.cpp (mmp/pbrt-v4, Apache-2.0), which carries measured data published by
others; each table's original source is named in the generated files:

  cie_tables.cpp           the CIE 1931 matching functions and illuminant D65
  named_spectra_data.h/cpp the named spectra (metals, glasses, standard illuminants) and the
                           CIE daylight basis S0, S1, S2

Usage: python3 tools/spectra/extract_pbrt_spectra.py PATH/TO/pbrt-v4/src/pbrt/util/spectrum.cpp
  e.g. git -C /work/.mirror/mmp+pbrt-v4/repo show HEAD:src/pbrt/util/spectrum.cpp > spectrum.cpp

Only numbers are taken (data, not code); rerunning on the same file rewrites the same bytes."""
import pathlib
import re
import sys
import textwrap

PBRT = "pbrt-v4's src/pbrt/util/spectrum.cpp (mmp/pbrt-v4 at 5f7a6068)"

# (name in pbrt-v4's file, C++ name, comment naming the data's source)
CIE = [
    ("CIE_X", "kCieX", "CIE 1931 2-degree colour matching function x-bar"),
    ("CIE_Y", "kCieY", "CIE 1931 2-degree colour matching function y-bar"),
    ("CIE_Z", "kCieZ", "CIE 1931 2-degree colour matching function z-bar"),
]
PAIRS = [
    ("CIE_Illum_D6500", "kCieIllumD65", "CIE standard illuminant D65 (CIE 15:2004, table T.1), 5 nm"),
]

PALIK = ("luxpop.com's database, after E. D. Palik (ed.), Handbook of Optical Constants of "
         "Solids (Academic Press, 1985); pbrt-v3 and Mitsuba 0.6 carry the same numbers")
QUERRY = ("brass (70% Cu, 30% Zn): M. R. Querry, Optical constants, report CRDC-CR-85034 "
          "(1985), via refractiveindex.info")
UNNAMED = "pbrt-v4 names no source"
SCHOTT = ("the SCHOTT optical glass catalogue (Sellmeier formula) as tabulated by "
          "refractiveindex.info, public domain (CC0), the source pbrt-v4's THIRD_PARTY.md names")
CIE15 = "CIE 15:2004, Colorimetry, 3rd edition"

# The named spectra, as (nm, value) pairs: (name in pbrt-v4's file, C++ name, source).
NAMED = [
    ("Ag_eta", "kMetalAgEta", "silver, eta; " + PALIK),
    ("Ag_k", "kMetalAgK", "silver, k; " + PALIK),
    ("Al_eta", "kMetalAlEta", "aluminium, eta; " + PALIK),
    ("Al_k", "kMetalAlK", "aluminium, k; " + PALIK),
    ("Au_eta", "kMetalAuEta", "gold, eta; " + PALIK),
    ("Au_k", "kMetalAuK", "gold, k; " + PALIK),
    ("Cu_eta", "kMetalCuEta", "copper, eta; " + PALIK),
    ("Cu_k", "kMetalCuK", "copper, k; " + PALIK),
    ("CuZn_eta", "kMetalCuZnEta", QUERRY + "; eta"),
    ("CuZn_k", "kMetalCuZnK", QUERRY + "; k"),
    ("MgO_eta", "kMetalMgOEta", "magnesium oxide (a dielectric, k = 0), eta; " + UNNAMED),
    ("MgO_k", "kMetalMgOK", "magnesium oxide, k; " + UNNAMED),
    ("TiO2_eta", "kMetalTiO2Eta", "titanium dioxide, eta; pbrt-v4 names no source"),
    ("TiO2_k", "kMetalTiO2K", "titanium dioxide, k; pbrt-v4 names no source"),
    ("GlassBK7_eta", "kGlassBk7Eta", "SCHOTT N-BK7 borosilicate crown, index; " + SCHOTT),
    ("GlassBAF10_eta", "kGlassBaf10Eta", "SCHOTT N-BAF10 barium flint, index; " + SCHOTT),
    ("GlassFK51A_eta", "kGlassFk51aEta", "SCHOTT N-FK51A fluorite crown, index; " + SCHOTT),
    ("GlassLASF9_eta", "kGlassLasf9Eta", "SCHOTT N-LASF9 lanthanum dense flint, index; " + SCHOTT),
    ("GlassSF5_eta", "kGlassSf5Eta", "SCHOTT SF5 dense flint, index; " + SCHOTT),
    ("GlassSF10_eta", "kGlassSf10Eta", "SCHOTT SF10 dense flint, index; " + SCHOTT),
    ("GlassSF11_eta", "kGlassSf11Eta", "SCHOTT SF11 dense flint, index; " + SCHOTT),
    ("CIE_Illum_A", "kIllumA", "CIE standard illuminant A (a Planckian radiator at about "
     "2856 K), relative spectral power, 100 at 560 nm; " + CIE15),
    ("CIE_Illum_D5000", "kIllumD50", "CIE illuminant D50 (daylight, correlated colour "
     "temperature about 5003 K), relative spectral power, 100 at 560 nm; " + CIE15),
    ("ACES_Illum_D60", "kIllumAcesD60", "the white of ACES, a CIE daylight illuminant of about "
     "6000 K from S0, S1, S2, relative spectral power, 100 at 560 nm; computed by A. Forsythe "
     "(gist aforsythe/4df4e5377853df76a5a83a3c001c7eeb), as pbrt-v4 says"),
] + [
    (f"CIE_Illum_F{i}", f"kIllumF{i}", f"CIE illuminant F{i} (typical fluorescent lamp), "
     f"relative spectral power; {CIE15}") for i in range(1, 13)
]
# The CIE daylight basis: one wavelength array, three value arrays (pbrt-v4's layout).
DAYLIGHT = [
    ("CIE_S_lambda", "kCieSLambda", "wavelengths (nm) of the CIE daylight basis, 300-830 nm in 5 nm steps"),
    ("CIE_S0", "kCieS0", "CIE daylight basis S0 (mean daylight; Judd, MacAdam and Wyszecki 1964); " + CIE15),
    ("CIE_S1", "kCieS1", "CIE daylight basis S1 (yellow-blue variation); " + CIE15),
    ("CIE_S2", "kCieS2", "CIE daylight basis S2 (pink-green variation); " + CIE15),
]


def table(src: str, name: str) -> list[str]:
    m = re.search(r"const Float " + re.escape(name) + r"\[[^\]]*\]\s*=\s*\{(.*?)\};", src, re.S)
    if not m:
        sys.exit(f"{name}: not found")
    body = re.sub(r"//[^\n]*", "", m.group(1))
    return [v.strip() for v in body.split(",") if v.strip()]


def comment_lines(text: str) -> list[str]:
    return ["// " + line for line in textwrap.wrap(text, 97)]


def emit(name: str, values: list[str], comment: str) -> str:
    lines = comment_lines(comment + ".") + [f"extern const float {name}[{len(values)}];", f"const float {name}[{len(values)}] = {{"]
    for i in range(0, len(values), 8):
        lines.append("    " + ", ".join(f"{float(v)!r}f" for v in values[i:i + 8]) + ",")
    lines.append("};")
    return "\n".join(lines)


def check_pairs(name: str, values: list[str]) -> None:
    assert len(values) % 2 == 0 and len(values) >= 4, name
    nm = [float(v) for v in values[0::2]]
    assert all(a < b for a, b in zip(nm, nm[1:])), f"{name}: wavelengths not increasing"


def header(what: str) -> str:
    return "\n".join(comment_lines(
        f"Generated by tools/spectra/extract_pbrt_spectra.py from the tables in {PBRT}. {what} "
        "Do not edit.")) + "\n"


def write_cie(src: str, root: pathlib.Path) -> None:
    parts = []
    for pbrt, ours, comment in CIE:
        values = table(src, pbrt)
        assert len(values) == 471, (pbrt, len(values))
        parts.append(emit(ours, values, comment + ", 360-830 nm in 1 nm steps"))
    for pbrt, ours, comment in PAIRS:
        values = table(src, pbrt)
        check_pairs(pbrt, values)
        parts.append(emit(ours, values, comment + "; (nm, value) pairs"))
    out = root / "src/candela/spectrum/cie_tables.cpp"
    out.write_text(
        "// Generated by tools/spectra/extract_pbrt_spectra.py from the tables in pbrt-v4's\n"
        "// src/pbrt/util/spectrum.cpp (mmp/pbrt-v4 at 5f7a6068). Do not edit.\n"
        "// clang-format off\n"
        '#include "candela/spectrum/cie_tables.h"\n\nnamespace candela {\n\n'
        + "\n\n".join(parts) + "\n\n}  // namespace candela\n")
    print(f"wrote {out}")


def write_named(src: str, root: pathlib.Path) -> None:
    decls, parts = [], []
    for pbrt, ours, comment in NAMED:
        values = table(src, pbrt)
        check_pairs(pbrt, values)
        decls.append(f"extern const float {ours}[{len(values)}];")
        parts.append(emit(ours, values, comment + "; (nm, value) pairs"))
    n = len(table(src, DAYLIGHT[0][0]))
    decls.append(f"inline constexpr int kCieSSamples = {n};")
    for pbrt, ours, comment in DAYLIGHT:
        values = table(src, pbrt)
        assert len(values) == n, (pbrt, len(values))
        decls.append(f"extern const float {ours}[kCieSSamples];")
        parts.append(emit(ours, values, comment))
    h = root / "src/candela/spectrum/named_spectra_data.h"
    h.write_text(
        "#pragma once\n"
        + header("The tables of named_spectra_data.cpp, each with its source named beside it; "
                 "named_spectra.cpp gives them pbrt-v4's names (D65 is in cie_tables.h).")
        + "// clang-format off\n\nnamespace candela {\n\n"
        + "\n".join(decls) + "\n\n}  // namespace candela\n")
    cpp = root / "src/candela/spectrum/named_spectra_data.cpp"
    cpp.write_text(
        header("Each table's original source is named beside it.")
        + "// clang-format off\n"
        '#include "candela/spectrum/named_spectra_data.h"\n\nnamespace candela {\n\n'
        + "\n\n".join(parts) + "\n\n}  // namespace candela\n")
    print(f"wrote {h}\nwrote {cpp}")


def main() -> None:
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    src = pathlib.Path(sys.argv[1]).read_text()
    root = pathlib.Path(__file__).resolve().parents[2]
    write_cie(src, root)
    write_named(src, root)


if __name__ == "__main__":
    main()
