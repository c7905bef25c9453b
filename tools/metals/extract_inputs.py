#!/usr/bin/env python3
"""Writes the measured spectra that make_metal_table.py reads (tools/metals/data/*.csv) from
their published sources, so that every number in the data folder can be traced and re-extracted.

    extract_inputs.py --pbrt-spectrum-cpp spectrum.cpp --refractiveindex-db DIR [--out DIR]

--pbrt-spectrum-cpp: pbrt-v4's src/pbrt/util/spectrum.cpp (Apache-2.0), e.g.
    git -C pbrt-v4 show HEAD:src/pbrt/util/spectrum.cpp > spectrum.cpp
  It holds the CIE 1931 2-degree matching functions (1 nm, 360-830 nm), CIE illuminant D65
  (5 nm) and the measured eta/k of Ag, Al, Au, Cu (luxpop.com, after Palik) and CuZn (brass,
  Querry 1985, via refractiveindex.info): the spectra pbrt-v4 renders "metal-Au-eta" etc. with.
--refractiveindex-db: a checkout of github.com/polyanskiy/refractiveindex.info-database (CC0),
  for Cr, Fe and Ti: Johnson & Christy 1974, "Optical constants of transition metals: Ti, V, Cr,
  Mn, Fe, Co, Ni, and Pd", Phys. Rev. B 9, 5056 (database/data/main/<metal>/nk/Johnson.yml).
Standard library only.
"""
import argparse
import os
import re

PBRT_METALS = ["Ag", "Al", "Au", "Cu", "CuZn"]
JOHNSON_CHRISTY_METALS = ["Cr", "Fe", "Ti"]


def pbrt_array(source, name):
    """The numbers of `const Float name[] = {...};` in pbrt-v4's spectrum.cpp."""
    m = re.search(r"const Float " + re.escape(name) + r"\[[^\]]*\]\s*=\s*\{(.*?)\};", source, re.S)
    if not m:
        raise SystemExit(f"extract_inputs: {name} not found in spectrum.cpp")
    body = re.sub(r"//[^\n]*", "", m.group(1))
    return [float(t) for t in body.replace("\n", " ").split(",") if t.strip()]


def pairs(values):
    return list(zip(values[0::2], values[1::2]))


def write_csv(path, header_lines, columns, rows):
    with open(path, "w", encoding="ascii") as f:
        for line in header_lines:
            f.write(f"# {line}\n")
        f.write(",".join(columns) + "\n")
        for row in rows:
            f.write(",".join(f"{v:.9g}" for v in row) + "\n")


def extract_pbrt(source, out):
    lam = pbrt_array(source, "CIE_lambda")
    x, y, z = (pbrt_array(source, n) for n in ("CIE_X", "CIE_Y", "CIE_Z"))
    assert len(lam) == len(x) == len(y) == len(z) == 471
    write_csv(os.path.join(out, "cie_1931_2deg.csv"),
              ["CIE 1931 2-degree colour matching functions, 1 nm, 360-830 nm (CIE 15:2004),",
               "as tabulated in pbrt-v4 src/pbrt/util/spectrum.cpp (CIE_X, CIE_Y, CIE_Z)."],
              ["nm", "x", "y", "z"], zip(lam, x, y, z))
    write_csv(os.path.join(out, "cie_d65.csv"),
              ["CIE standard illuminant D65, relative spectral power (100 at 560 nm), 5 nm,",
               "as tabulated in pbrt-v4 src/pbrt/util/spectrum.cpp (CIE_Illum_D6500)."],
              ["nm", "power"], pairs(pbrt_array(source, "CIE_Illum_D6500")))
    for metal in PBRT_METALS:
        eta = pairs(pbrt_array(source, metal + "_eta"))
        k = pairs(pbrt_array(source, metal + "_k"))
        assert [w for w, _ in eta] == [w for w, _ in k]
        origin = ("Querry 1985 (70% Cu, 30% Zn) via refractiveindex.info" if metal == "CuZn"
                  else "luxpop.com database (Palik, Handbook of Optical Constants of Solids)")
        write_csv(os.path.join(out, metal + ".csv"),
                  [f"{metal}: complex index of refraction eta + i k against wavelength in nm.",
                   f"pbrt-v4 src/pbrt/util/spectrum.cpp ({metal}_eta, {metal}_k); data: {origin}."],
                  ["nm", "eta", "k"], [(w, e, kk) for (w, e), (_, kk) in zip(eta, k)])


def extract_johnson_christy(db, out):
    for metal in JOHNSON_CHRISTY_METALS:
        path = os.path.join(db, "database", "data", "main", metal, "nk", "Johnson.yml")
        with open(path, encoding="utf-8") as f:
            text = f.read()
        block = text.split("data: |", 1)[1]
        rows = []
        for line in block.splitlines()[1:]:
            fields = line.split()
            if len(fields) != 3:
                break
            um, n, k = map(float, fields)
            rows.append((um * 1000.0, n, k))
        write_csv(os.path.join(out, metal + ".csv"),
                  [f"{metal}: complex index of refraction eta + i k against wavelength in nm.",
                   "P. B. Johnson and R. W. Christy, Optical constants of transition metals, Phys. Rev.",
                   "B 9, 5056 (1974); refractiveindex.info database (CC0),",
                   f"database/data/main/{metal}/nk/Johnson.yml."],
                  ["nm", "eta", "k"], rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pbrt-spectrum-cpp", required=True)
    parser.add_argument("--refractiveindex-db", required=True)
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "data"))
    args = parser.parse_args()
    with open(args.pbrt_spectrum_cpp, encoding="utf-8") as f:
        extract_pbrt(f.read(), args.out)
    extract_johnson_christy(args.refractiveindex_db, args.out)


if __name__ == "__main__":
    main()
