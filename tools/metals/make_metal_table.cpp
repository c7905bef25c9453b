// Computes the measured-metal table of RGB mode (kMetalIors, materials/metal_table.h): per RGB
// channel, the complex index of refraction eta + i k of each metal, reduced from its measured
// spectra, the ones spectral mode uses (src/candela/spectrum/: named_spectra_data.cpp for Au,
// Ag, Cu, Al and CuZn, johnson_christy_data.cpp for Cr, Fe and Ti) under the CIE 1931 observer
// and D65 of cie_tables.cpp. Every build runs it (src/candela/materials/CMakeLists.txt):
//
//     make_metal_table OUT.cpp [--check]     # --check also prints each metal's fit error
//
// Method. What a metal's eta and k decide is its Fresnel reflectance F(cos, lambda), and what an
// RGB renderer shows of it is that reflectance in linear sRGB. So, per metal:
//   1. the target: for cosines mu on a grid over (0, 1], the spectral reflectance F(mu, lambda)
//      of the measured eta(lambda) + i k(lambda) (exact unpolarized Fresnel), reduced to linear
//      sRGB as a reflectance is (integrated against the CIE 1931 2-degree matching functions
//      under illuminant D65, normalized so that F = 1 is Y = 1, then XYZ -> linear sRGB with the
//      white point of that same D65 data, so a constant spectrum is exactly grey);
//   2. per channel, the (eta, k) whose Fresnel curve F(mu; eta, k) is closest to the target in
//      least squares over the grid (Levenberg-Marquardt in log eta, log k, started from the
//      D65-weighted averages of the eta and k spectra).
// A reflectance outside the sRGB gamut is clipped to [0, 1] first: gold's red near normal
// incidence is 1.022 in sRGB, which no RGB lobe can reflect without creating energy, so gold's
// red channel becomes the near-perfect reflector closest to the clipped curve (k about 13).
// Averaging eta and k themselves over each channel (what Mitsuba 3's RGB variants do)
// reproduces the reflectance less well because F is far from linear in eta and k: --check
// prints both errors. A metal of constant eta and k comes out exactly as those (checked on
// every run). The values are written to 6 significant digits, in double throughout, so that
// they do not depend on the compiler's float evaluation. This is the computation the Python
// generator this replaces (tools/metals/make_metal_table.py, before issue 23) did; it gives the
// same table, bit for bit.
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "candela/materials/metal_table.h"
#include "candela/spectrum/cie_tables.h"
#include "candela/spectrum/johnson_christy_data.h"
#include "candela/spectrum/named_spectra_data.h"

namespace {

using namespace candela;
using Vec = std::vector<double>;
using Row3 = std::array<double, 3>;

// Each entry of the table, in the order of enum Metal.
struct MetalSource {
    Metal metal;
    const char* symbol;
    const char* name;
    std::span<const float> eta, k;  // (nm, value) pairs, at the same wavelengths
};

const MetalSource kSources[] = {
    {Metal::kAu, "Au", "gold", kMetalAuEta, kMetalAuK},
    {Metal::kAg, "Ag", "silver", kMetalAgEta, kMetalAgK},
    {Metal::kCu, "Cu", "copper", kMetalCuEta, kMetalCuK},
    {Metal::kAl, "Al", "aluminium", kMetalAlEta, kMetalAlK},
    {Metal::kCr, "Cr", "chromium", kMetalCrEta, kMetalCrK},
    {Metal::kFe, "Fe", "iron", kMetalFeEta, kMetalFeK},
    {Metal::kTi, "Ti", "titanium", kMetalTiEta, kMetalTiK},
    {Metal::kCuZn, "CuZn", "brass (70% Cu, 30% Zn)", kMetalCuZnEta, kMetalCuZnK},
};
static_assert(std::size(kSources) == size_t(kMetalCount), "a source for every metal");

// sRGB (Rec. 709) primaries, CIE xy.
constexpr double kPrimaries[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
constexpr int kCosines = 64;  // where the Fresnel curves are compared: midpoints of 64 steps of (0, 1]

double fit_cosine(int j) { return (j + 0.5) / 64.0; }

// A piecewise-linear function from (x, y) pairs.
struct Curve {
    Vec x, y;
    explicit Curve(std::span<const float> pairs) {
        for (size_t i = 0; i + 1 < pairs.size(); i += 2) {
            x.push_back(double(pairs[i]));
            y.push_back(double(pairs[i + 1]));
        }
    }
    // Linear between samples, held constant beyond the ends.
    double operator()(double at) const {
        if (at <= x.front()) return y.front();
        if (at >= x.back()) return y.back();
        size_t lo = 0, hi = x.size() - 1;
        while (hi - lo > 1) {
            const size_t mid = (lo + hi) / 2;
            (x[mid] <= at ? lo : hi) = mid;
        }
        const double t = (at - x[lo]) / (x[hi] - x[lo]);
        return y[lo] * (1.0 - t) + y[hi] * t;
    }
};

double det3(const std::array<Row3, 3>& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// m^-1 v (Cramer's rule).
Row3 solve3(const std::array<Row3, 3>& m, const Row3& v) {
    const double d = det3(m);
    Row3 out;
    for (int col = 0; col < 3; ++col) {
        std::array<Row3, 3> a = m;
        for (int r = 0; r < 3; ++r) a[r][col] = v[r];
        out[col] = det3(a) / d;
    }
    return out;
}

// Reflectance spectra, sampled at every nm of the CIE table, to linear sRGB under D65.
class Colorimetry {
  public:
    Colorimetry() {
        const Curve d65(kCieIllumD65);
        Vec power(kCieSamples);
        double norm = 0.0;
        for (int i = 0; i < kCieSamples; ++i) {
            wavelengths_.push_back(double(kCieLambdaMin) + i);
            power[i] = d65(wavelengths_[i]);
            norm += power[i] * double(kCieY[i]);
        }
        // XYZ of a reflectance s: sum over lambda of s(lambda) weights[lambda] (Y of s = 1 is 1).
        Row3 white{0.0, 0.0, 0.0};
        for (int i = 0; i < kCieSamples; ++i) {
            weights_.push_back({power[i] * double(kCieX[i]) / norm, power[i] * double(kCieY[i]) / norm,
                                power[i] * double(kCieZ[i]) / norm});
            for (int c = 0; c < 3; ++c) white[c] += weights_.back()[c];
        }
        // RGB -> XYZ: columns are the primaries' XYZ (Y = 1), scaled so that RGB (1, 1, 1) is
        // the white point (the standard construction, e.g. SMPTE RP 177); we need its inverse.
        std::array<Row3, 3> m;
        for (int c = 0; c < 3; ++c) {
            const double x = kPrimaries[c][0], y = kPrimaries[c][1];
            const Row3 xyz{x / y, 1.0, (1.0 - x - y) / y};
            for (int r = 0; r < 3; ++r) m[r][c] = xyz[r];
        }
        const Row3 scale = solve3(m, white);
        std::array<Row3, 3> rgb_to_xyz;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) rgb_to_xyz[r][c] = m[r][c] * scale[c];
        for (int e = 0; e < 3; ++e) {
            Row3 unit{0.0, 0.0, 0.0};
            unit[e] = 1.0;
            xyz_to_rgb_columns_[e] = solve3(rgb_to_xyz, unit);
        }
    }

    const Vec& wavelengths() const { return wavelengths_; }

    // Linear sRGB of a reflectance given at wavelengths().
    Row3 rgb(const Vec& spectrum) const {
        Row3 xyz{0.0, 0.0, 0.0};
        for (int c = 0; c < 3; ++c)
            for (size_t i = 0; i < spectrum.size(); ++i) xyz[c] += spectrum[i] * weights_[i][c];
        const auto& m = xyz_to_rgb_columns_;
        Row3 out;
        for (int r = 0; r < 3; ++r) out[r] = m[0][r] * xyz[0] + m[1][r] * xyz[1] + m[2][r] * xyz[2];
        return out;
    }

  private:
    Vec wavelengths_;
    std::vector<Row3> weights_;
    std::array<Row3, 3> xyz_to_rgb_columns_;
};

// Unpolarized Fresnel reflectance of a conductor of index eta + i k (as materials/fresnel.h).
double fresnel_complex(double cos_i, double eta, double k) {
    const std::complex<double> n(eta, k);
    const std::complex<double> cos_t = std::sqrt(1.0 - (1.0 - cos_i * cos_i) / (n * n));
    const std::complex<double> r_par = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    const std::complex<double> r_perp = (cos_i - n * cos_t) / (cos_i + n * cos_t);
    const double a = std::abs(r_par), b = std::abs(r_perp);
    return 0.5 * (a * a + b * b);
}

using Target = std::array<Vec, 3>;  // per channel, the reflectance at each fit cosine

// The sRGB reflectance of eta(lambda) + i k(lambda) at the fit cosines, clipped to [0, 1].
Target target_curves(const Colorimetry& colorimetry, const Vec& eta, const Vec& k) {
    Target target;
    for (int j = 0; j < kCosines; ++j) {
        Vec f(eta.size());
        for (size_t i = 0; i < eta.size(); ++i) f[i] = fresnel_complex(fit_cosine(j), eta[i], k[i]);
        const Row3 rgb = colorimetry.rgb(f);
        for (int c = 0; c < 3; ++c) target[c].push_back(std::min(std::max(rgb[c], 0.0), 1.0));
    }
    return target;
}

double squared_norm(const Vec& r) {
    double sum = 0.0;
    for (double x : r) sum += x * x;
    return sum;
}

// The (eta, k) minimizing sum_j (F(mu_j; eta, k) - target_j)^2: Levenberg-Marquardt in
// (log eta, log k) with a forward-difference Jacobian.
std::array<double, 2> fit_channel(const Vec& target, double eta0, double k0) {
    std::array<double, 2> p{std::log(std::max(eta0, 1e-3)), std::log(std::max(k0, 1e-3))};
    auto residuals = [&](const std::array<double, 2>& q) {
        const double e = std::exp(q[0]), kk = std::exp(q[1]);
        Vec r(kCosines);
        for (int j = 0; j < kCosines; ++j) r[j] = fresnel_complex(fit_cosine(j), e, kk) - target[j];
        return r;
    };
    double damping = 1e-3;
    Vec r = residuals(p);
    double cost = squared_norm(r);
    for (int iteration = 0; iteration < 200; ++iteration) {
        const double h = 1e-6;
        std::array<Vec, 2> cols;
        for (int i = 0; i < 2; ++i) {
            std::array<double, 2> q = p;
            q[i] += h;
            const Vec rq = residuals(q);
            for (int j = 0; j < kCosines; ++j) cols[i].push_back((rq[j] - r[j]) / h);
        }
        double jtj[2][2], jtr[2];
        for (int i = 0; i < 2; ++i) {
            for (int m = 0; m < 2; ++m) {
                jtj[i][m] = 0.0;
                for (int j = 0; j < kCosines; ++j) jtj[i][m] += cols[i][j] * cols[m][j];
            }
            jtr[i] = 0.0;
            for (int j = 0; j < kCosines; ++j) jtr[i] += cols[i][j] * r[j];
        }
        bool improved = false;
        std::array<double, 2> step{0.0, 0.0};
        while (damping < 1e12) {
            const double a00 = jtj[0][0] * (1 + damping), a01 = jtj[0][1], a10 = jtj[1][0],
                         a11 = jtj[1][1] * (1 + damping);
            const double d = a00 * a11 - a01 * a10;
            step = {-(a11 * jtr[0] - a01 * jtr[1]) / d, -(a00 * jtr[1] - a10 * jtr[0]) / d};
            const std::array<double, 2> q{p[0] + step[0], p[1] + step[1]};
            Vec rq = residuals(q);
            const double cq = squared_norm(rq);
            if (cq < cost) {
                p = q;
                r = std::move(rq);
                cost = cq;
                damping *= 0.3;
                improved = true;
                break;
            }
            damping *= 10.0;
        }
        if (!improved || std::max(std::abs(step[0]), std::abs(step[1])) < 1e-12) break;
    }
    return {std::exp(p[0]), std::exp(p[1])};
}

struct Reduced {
    Row3 eta, k;            // the table's values
    Target target;          // what they fit
    Row3 eta_avg, k_avg;    // eta and k averaged as if they were reflectances (the fit's start)
};

Reduced reduce_metal(const Colorimetry& colorimetry, const Vec& eta, const Vec& k) {
    Reduced out;
    out.eta_avg = colorimetry.rgb(eta);
    out.k_avg = colorimetry.rgb(k);
    out.target = target_curves(colorimetry, eta, k);
    for (int c = 0; c < 3; ++c) {
        const std::array<double, 2> fitted = fit_channel(out.target[c], out.eta_avg[c], out.k_avg[c]);
        out.eta[c] = fitted[0];
        out.k[c] = fitted[1];
    }
    return out;
}

double max_error(const Vec& target, double eta, double k) {
    double worst = 0.0;
    for (int j = 0; j < kCosines; ++j) worst = std::max(worst, std::abs(fresnel_complex(fit_cosine(j), eta, k) - target[j]));
    return worst;
}

// The method's own check: a constant spectrum stays grey, a constant eta and k stay themselves.
bool constant_spectrum_is_kept(const Colorimetry& colorimetry) {
    const size_t n = colorimetry.wavelengths().size();
    const Reduced r = reduce_metal(colorimetry, Vec(n, 0.9), Vec(n, 2.5));
    const Row3 grey = colorimetry.rgb(Vec(n, 1.0));
    for (int c = 0; c < 3; ++c)
        if (!(std::abs(r.eta[c] - 0.9) < 1e-6 && std::abs(r.k[c] - 2.5) < 1e-6 && std::abs(grey[c] - 1.0) < 1e-9))
            return false;
    return true;
}

// A value to 6 significant digits as a float literal.
std::string float_literal(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.6g", v);
    std::string s = text;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s + "f";
}

std::string rgb_literal(const Row3& v) {
    return "Rgb(" + float_literal(v[0]) + ", " + float_literal(v[1]) + ", " + float_literal(v[2]) + ")";
}

}  // namespace

int main(int argc, char** argv) {
    const bool check = argc == 3 && std::strcmp(argv[2], "--check") == 0;
    if (argc < 2 || (argc == 3 && !check) || argc > 3) {
        std::fprintf(stderr, "usage: make_metal_table OUT.cpp [--check]\n");
        return 2;
    }
    const Colorimetry colorimetry;
    if (!constant_spectrum_is_kept(colorimetry)) {
        std::fprintf(stderr, "make_metal_table: a constant spectrum does not reduce to itself\n");
        return 1;
    }
    std::string rows;
    for (int m = 0; m < kMetalCount; ++m) {
        const MetalSource& source = kSources[m];
        if (int(source.metal) != m) {
            std::fprintf(stderr, "make_metal_table: kSources is not in the order of enum Metal\n");
            return 1;
        }
        const Curve eta(source.eta), k(source.k);
        Vec eta_s, k_s;
        for (double w : colorimetry.wavelengths()) {
            eta_s.push_back(eta(w));
            k_s.push_back(k(w));
        }
        const Reduced r = reduce_metal(colorimetry, eta_s, k_s);
        rows += std::string("    // ") + source.symbol + ": " + source.name + "\n    MetalIor{" + rgb_literal(r.eta) +
                ", " + rgb_literal(r.k) + "},\n";
        if (check) {
            double fit_err = 0.0, avg_err = 0.0;
            for (int c = 0; c < 3; ++c) {
                fit_err = std::max(fit_err, max_error(r.target[c], r.eta[c], r.k[c]));
                avg_err = std::max(avg_err, max_error(r.target[c], r.eta_avg[c], r.k_avg[c]));
            }
            std::printf("%-5s eta %s  k %s  F(cos %.3f) %s  max |dF|: fitted %.2e, averaged eta/k %.2e\n",
                        source.symbol, rgb_literal(r.eta).c_str(), rgb_literal(r.k).c_str(), fit_cosine(kCosines - 1),
                        rgb_literal({r.target[0].back(), r.target[1].back(), r.target[2].back()}).c_str(), fit_err,
                        avg_err);
        }
    }
    std::FILE* out = std::fopen(argv[1], "w");
    if (!out) {
        std::fprintf(stderr, "make_metal_table: cannot write %s\n", argv[1]);
        return 1;
    }
    std::fprintf(out,
                 "// Generated by tools/metals/make_metal_table from the measured spectra in src/candela/spectrum/\n"
                 "// (the method is described there); do not edit.\n"
                 "#include \"candela/materials/metal_table.h\"\n\n"
                 "namespace candela {\n\n"
                 "const std::array<MetalIor, kMetalCount> kMetalIors = {{\n%s}};\n\n"
                 "}  // namespace candela\n",
                 rows.c_str());
    return std::fclose(out) == 0 ? 0 : 1;
}
