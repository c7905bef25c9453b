#!/usr/bin/env python3
"""Generates src/candela/materials/metal_table.h: per-RGB-channel eta and k of measured metals,
reduced from their spectra (tools/metals/data/, sources in tools/metals/README.md).

    make_metal_table.py [--out src/candela/materials/metal_table.h]
                        [--spectra-out FILE]   # also the spectra themselves, as C++ arrays
                        [--check]              # print how well the RGB values reproduce the metal

Method. What a metal's eta and k decide is its Fresnel reflectance F(cos, lambda), and what an
RGB renderer shows of it is that reflectance in linear sRGB. So, per metal:
  1. the target: for cosines mu on a grid over (0, 1], the spectral reflectance F(mu, lambda) of
     the measured eta(lambda) + i k(lambda) (exact unpolarized Fresnel), reduced to linear sRGB as
     a reflectance is (integrated against the CIE 1931 2-degree matching functions under
     illuminant D65, normalized so that F = 1 is Y = 1, then XYZ -> linear sRGB with the white
     point of that same D65 data, so a constant spectrum is exactly grey);
  2. per channel, the (eta, k) whose Fresnel curve F(mu; eta, k) is closest to the target in
     least squares over the grid (Levenberg-Marquardt in log eta, log k, started from the
     D65-weighted averages of the eta and k spectra).
A reflectance outside the sRGB gamut is clipped to [0, 1] first: gold's red near normal
incidence is 1.022 in sRGB, which no RGB lobe can reflect without creating energy, so gold's red
channel becomes the near-perfect reflector closest to the clipped curve (k about 13).
Averaging eta and k themselves over each channel's matching function (what Mitsuba 3's RGB
variants do, under equal energy: spectrum_list_to_srgb(..., d65=false)) reproduces the
reflectance less well because F is far from linear in eta and k: --check prints both errors.
A metal of constant eta and k comes out exactly as those (test_constant_spectrum_is_kept).
Standard library only; deterministic.
"""
import argparse
import cmath
import csv
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data")
REPO = os.path.dirname(os.path.dirname(HERE))
DEFAULT_OUT = os.path.join(REPO, "src", "candela", "materials", "metal_table.h")

# Order of the table, and so of enum class Metal and of the scene file's names (scene/enum_names.cpp).
METALS = ["Au", "Ag", "Cu", "Al", "Cr", "Fe", "Ti", "CuZn"]
DESCRIPTIONS = {"Au": "gold", "Ag": "silver", "Cu": "copper", "Al": "aluminium", "Cr": "chromium",
                "Fe": "iron", "Ti": "titanium", "CuZn": "brass (70% Cu, 30% Zn)"}
# sRGB (Rec. 709) primaries, CIE xy.
SRGB_PRIMARIES = [(0.64, 0.33), (0.30, 0.60), (0.15, 0.06)]
LAMBDA_MIN, LAMBDA_MAX = 360, 830
# Cosines where the Fresnel curves are compared: midpoints of 64 equal steps of (0, 1].
FIT_COSINES = [(j + 0.5) / 64.0 for j in range(64)]


def read_rows(path):
    with open(path, encoding="ascii") as f:
        lines = [line for line in f if not line.startswith("#")]
    rows = list(csv.reader(lines))
    return rows[0], [[float(v) for v in row] for row in rows[1:] if row]


def interpolate(xs, ys, x):
    """Piecewise-linear ys(x), held constant beyond the ends."""
    if x <= xs[0]:
        return ys[0]
    if x >= xs[-1]:
        return ys[-1]
    lo, hi = 0, len(xs) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xs[mid] <= x:
            lo = mid
        else:
            hi = mid
    t = (x - xs[lo]) / (xs[hi] - xs[lo])
    return ys[lo] * (1.0 - t) + ys[hi] * t


def solve3(m, v):
    """m^-1 v for a 3x3 matrix (Cramer's rule)."""
    def det(a):
        return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
                - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    d = det(m)
    out = []
    for col in range(3):
        a = [row[:] for row in m]
        for r in range(3):
            a[r][col] = v[r]
        out.append(det(a) / d)
    return out


class Colorimetry:
    """Reflectance spectra (sampled at 1 nm, 360-830) to linear sRGB under D65."""

    def __init__(self):
        _, cie = read_rows(os.path.join(DATA, "cie_1931_2deg.csv"))
        _, d65 = read_rows(os.path.join(DATA, "cie_d65.csv"))
        self.wavelengths = [row[0] for row in cie]
        assert self.wavelengths[0] == LAMBDA_MIN and self.wavelengths[-1] == LAMBDA_MAX
        power = [interpolate([r[0] for r in d65], [r[1] for r in d65], w) for w in self.wavelengths]
        norm = sum(p * row[2] for p, row in zip(power, cie))
        # XYZ of a reflectance s: sum_lambda s(lambda) * weights[lambda] (Y of s = 1 is 1).
        self.weights = [(p * row[1] / norm, p * row[2] / norm, p * row[3] / norm)
                        for p, row in zip(power, cie)]
        white = [sum(w[i] for w in self.weights) for i in range(3)]
        # RGB -> XYZ: columns are the primaries' XYZ (Y = 1), scaled so that RGB (1, 1, 1) is the
        # white point (the standard construction, e.g. SMPTE RP 177); we need its inverse.
        prim = [[x / y, 1.0, (1.0 - x - y) / y] for x, y in SRGB_PRIMARIES]
        m = [[prim[c][r] for c in range(3)] for r in range(3)]
        scale = solve3(m, white)
        rgb_to_xyz = [[m[r][c] * scale[c] for c in range(3)] for r in range(3)]
        self.xyz_to_rgb_columns = [solve3(rgb_to_xyz, e) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]

    def rgb(self, spectrum):
        """Linear sRGB of a reflectance given at self.wavelengths."""
        xyz = [sum(s * w[i] for s, w in zip(spectrum, self.weights)) for i in range(3)]
        c = self.xyz_to_rgb_columns
        return [c[0][r] * xyz[0] + c[1][r] * xyz[1] + c[2][r] * xyz[2] for r in range(3)]


def fresnel_complex(cos_i, eta, k):
    """Unpolarized Fresnel reflectance of a conductor of index eta + i k (as fresnel.h)."""
    n = complex(eta, k)
    cos_t = cmath.sqrt(1.0 - (1.0 - cos_i * cos_i) / (n * n))
    r_par = (n * cos_i - cos_t) / (n * cos_i + cos_t)
    r_perp = (cos_i - n * cos_t) / (cos_i + n * cos_t)
    return 0.5 * (abs(r_par) ** 2 + abs(r_perp) ** 2)


def read_metal(name):
    _, rows = read_rows(os.path.join(DATA, name + ".csv"))
    return [r[0] for r in rows], [r[1] for r in rows], [r[2] for r in rows]


def sampled(metal, wavelengths):
    nm, eta, k = metal
    return ([interpolate(nm, eta, w) for w in wavelengths],
            [interpolate(nm, k, w) for w in wavelengths])


def averaged_ior(colorimetry, eta_s, k_s):
    """eta and k reduced as if they were reflectances: the D65-weighted channel averages."""
    return colorimetry.rgb(eta_s), colorimetry.rgb(k_s)


def target_curves(colorimetry, eta_s, k_s):
    """target[c][j]: channel c of the sRGB reflectance at FIT_COSINES[j], clipped to [0, 1]."""
    per_cos = [colorimetry.rgb([fresnel_complex(mu, e, kk) for e, kk in zip(eta_s, k_s)])
               for mu in FIT_COSINES]
    return [[min(max(rgb[c], 0.0), 1.0) for rgb in per_cos] for c in range(3)]


def fit_channel(target, eta0, k0):
    """(eta, k) minimizing sum_j (F(mu_j; eta, k) - target_j)^2 (Levenberg-Marquardt in logs)."""
    p = [math.log(max(eta0, 1e-3)), math.log(max(k0, 1e-3))]

    def residuals(q):
        e, kk = math.exp(q[0]), math.exp(q[1])
        return [fresnel_complex(mu, e, kk) - t for mu, t in zip(FIT_COSINES, target)]

    damping = 1e-3
    r = residuals(p)
    cost = sum(x * x for x in r)
    for _ in range(200):
        h = 1e-6
        cols = []
        for i in range(2):
            q = p[:]
            q[i] += h
            cols.append([(a - b) / h for a, b in zip(residuals(q), r)])
        jtj = [[sum(a * b for a, b in zip(cols[i], cols[j])) for j in range(2)] for i in range(2)]
        jtr = [sum(a * b for a, b in zip(cols[i], r)) for i in range(2)]
        improved = False
        while damping < 1e12:
            a = [[jtj[0][0] * (1 + damping), jtj[0][1]], [jtj[1][0], jtj[1][1] * (1 + damping)]]
            d = a[0][0] * a[1][1] - a[0][1] * a[1][0]
            step = [-(a[1][1] * jtr[0] - a[0][1] * jtr[1]) / d,
                    -(a[0][0] * jtr[1] - a[1][0] * jtr[0]) / d]
            q = [p[0] + step[0], p[1] + step[1]]
            rq = residuals(q)
            cq = sum(x * x for x in rq)
            if cq < cost:
                p, r, cost, damping, improved = q, rq, cq, damping * 0.3, True
                break
            damping *= 10.0
        if not improved or max(abs(s) for s in step) < 1e-12:
            break
    return math.exp(p[0]), math.exp(p[1])


def max_error(target, eta, k):
    return max(abs(fresnel_complex(mu, eta, k) - t) for mu, t in zip(FIT_COSINES, target))


def reduce_metal(colorimetry, eta_s, k_s):
    """Per-channel (eta, k) fitted to the metal's sRGB reflectance, and the targets."""
    eta_avg, k_avg = averaged_ior(colorimetry, eta_s, k_s)
    target = target_curves(colorimetry, eta_s, k_s)
    fitted = [fit_channel(target[c], eta_avg[c], k_avg[c]) for c in range(3)]
    return [f[0] for f in fitted], [f[1] for f in fitted], target, (eta_avg, k_avg)


def test_constant_spectrum_is_kept(colorimetry):
    n = len(colorimetry.wavelengths)
    eta, k, _, _ = reduce_metal(colorimetry, [0.9] * n, [2.5] * n)
    assert all(abs(e - 0.9) < 1e-6 and abs(kk - 2.5) < 1e-6 for e, kk in zip(eta, k)), (eta, k)
    grey = colorimetry.rgb([1.0] * n)
    assert all(abs(g - 1.0) < 1e-9 for g in grey), grey


def floats(values):
    return ", ".join(f"{v:.6g}f" for v in values)


def write_table(path, rows):
    lines = [
        "#pragma once",
        "// GENERATED by tools/metals/make_metal_table.py from tools/metals/data/; do not edit.",
        "// Measured metals as per-RGB-channel complex indices of refraction eta + i k (relative to",
        "// vacuum), for the conductor lobe's Fresnel term. Sources (tools/metals/README.md): Au, Ag,",
        "// Cu, Al: luxpop.com (after Palik), CuZn: Querry 1985, both as tabulated in pbrt-v4's",
        "// spectrum.cpp; Cr, Fe, Ti: Johnson & Christy 1974 (refractiveindex.info database).",
        "// Reduction: per channel, the (eta, k) whose Fresnel curve over cos in (0, 1] best matches,",
        "// in least squares, the metal's spectral Fresnel reflectance rendered to linear sRGB under",
        "// D65 (CIE 1931 2-degree observer); see the generator's docstring and docs/SCENE_FORMAT.md.",
        "// RGB values only: spectral rendering will use the spectra themselves.",
        "#include <array>",
        "",
        '#include "candela/math/color.h"',
        "",
        "namespace candela {",
        "",
        "// The scene file names them by symbol (\"Au\", ...): scene/enum_names.cpp, in this order.",
        "enum class Metal { " + ", ".join("k" + name for name, _, _ in rows) + " };",
        f"inline constexpr int kMetalCount = {len(rows)};",
        "",
        "struct MetalIor {",
        "    Rgb eta;",
        "    Rgb k;",
        "};",
        "",
        f"inline constexpr std::array<MetalIor, kMetalCount> kMetalIors = {{{{",
    ]
    for name, eta, k in rows:
        lines.append(f"    // {name}: {DESCRIPTIONS[name]}")
        lines.append(f"    MetalIor{{Rgb({floats(eta)}), Rgb({floats(k)})}},")
    lines += [
        "}};",
        "",
        "// The RGB complex index of a measured metal.",
        "constexpr const MetalIor& metal_ior(Metal metal) { return kMetalIors[static_cast<int>(metal)]; }",
        "",
        "}  // namespace candela",
        "",
    ]
    with open(path, "w", encoding="ascii") as f:
        f.write("\n".join(lines))


def write_spectra(path, metals):
    """The measured spectra as C++ arrays (wavelength nm, eta, k), for spectral rendering."""
    lines = ["#pragma once",
             "// GENERATED by tools/metals/make_metal_table.py --spectra-out; do not edit.",
             "// Measured eta + i k of each metal at its tabulated wavelengths (nm); sources in",
             "// tools/metals/README.md. Piecewise linear between samples.",
             "",
             "namespace candela {", ""]
    for name, (nm, eta, k) in metals:
        n = len(nm)
        lines.append(f"inline constexpr float k{name}SpectrumNm[{n}] = {{{floats(nm)}}};")
        lines.append(f"inline constexpr float k{name}SpectrumEta[{n}] = {{{floats(eta)}}};")
        lines.append(f"inline constexpr float k{name}SpectrumK[{n}] = {{{floats(k)}}};")
        lines.append("")
    lines += ["}  // namespace candela", ""]
    with open(path, "w", encoding="ascii") as f:
        f.write("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=DEFAULT_OUT)
    parser.add_argument("--spectra-out")
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()

    colorimetry = Colorimetry()
    test_constant_spectrum_is_kept(colorimetry)
    rows, metals = [], []
    for name in METALS:
        metal = read_metal(name)
        metals.append((name, metal))
        eta_s, k_s = sampled(metal, colorimetry.wavelengths)
        eta, k, target, (eta_avg, k_avg) = reduce_metal(colorimetry, eta_s, k_s)
        rows.append((name, eta, k))
        if args.check:
            fit_err = max(max_error(target[c], eta[c], k[c]) for c in range(3))
            avg_err = max(max_error(target[c], eta_avg[c], k_avg[c]) for c in range(3))
            f0 = [target[c][-1] for c in range(3)]
            print(f"{name:5s} eta {floats(eta)}  k {floats(k)}  F(cos {FIT_COSINES[-1]:.3f}) "
                  f"{floats(f0)}  max |dF|: fitted {fit_err:.2e}, averaged eta/k {avg_err:.2e}")
    write_table(args.out, rows)
    if args.spectra_out:
        write_spectra(args.spectra_out, metals)


if __name__ == "__main__":
    main()
