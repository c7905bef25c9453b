// Computes candela's sRGB-to-spectrum table (spectrum/rgb_to_spectrum_table.h; Jakob & Hanika
// 2019) with candela's own optimizer (spectrum/rgb_sigmoid_fit.h) and writes it as C++. Every
// build runs it (src/candela/spectrum/CMakeLists.txt):
//
//     make_rgb_to_spectrum_table 72 BUILD/src/candela/spectrum/rgb_to_spectrum_table_data.cpp
//
// By hand, with --check after the file name, it also prints the round trip's error (rgb -> table
// -> spectrum -> XYZ under D65 -> sRGB, largest channel difference, as
// tests/spectrum/rgb_to_spectrum_test.cpp computes it) at the nodes, over a 47^3 grid between
// them ("grid") and at 1.28M random colours pushed to the cube's faces, edges and corners, each
// channel u^4, 1 - u^4 or u ("edges").
//
// The method is pbrt-v4's rgb2spec_opt (written by Jakob): each column of nodes (slice, x, y) is
// solved along z from nodes[res / 5] upwards, then from there downwards, each Gauss-Newton
// starting from the neighbour's solution. Ours: the forward model is candela's own 1-nm CIE and
// D65 sums, so nodes round-trip to 2e-5; an analytic Jacobian; steps halved until the residual
// falls; a coefficient cap of 1e6 instead of 200 (which leaves dark saturated and near-white
// nodes unsolved: pbrt-v4's own table misses (1, 1, 0.984) by 3.6e-2 at its node).
//
// Choices, from --check runs (grid / edges):
//   pbrt-v4's table (its rgb2spec_opt, res 64)                         2.1e-3 / 3.8e-2
//   its scheme with our optimizer (uniform x, y, raw coefficients)     2.4e-3 / 1.5e-2  res 64
//   + coefficients stored times sqrt(w (1 - w))                        2.3e-3 / 1.5e-2  res 64
//   + x, y on nodes smoothstep(k / (res - 1))                          6.4e-4 / 2.7e-3  res 64
//   + x, y on the z nodes, smoothstep(smoothstep(k / (res - 1))): ours 1.2e-3 / 1.7e-3  res 48
//                                                                      6.5e-4 / 1.0e-3  res 64
//                                                                      5.4e-4 / 7.7e-4  res 72
//   tricubic (Catmull-Rom) instead of trilinear, this table's nodes    7.9e-3 / 4.3e-2  res 16
//                                                                      3.3e-3 / 2.2e-2  res 24
// The error falls as 1 / res^2 (trilinear interpolation of a smooth function; the worst colours
// are within 0.3% of white and in the yellow-to-white face). Res 72, the first we tried with every
// colour within 1e-3: 3 x 72^3 x 3 floats = 13.4 MB, far over what is worth committing as source
// (46 MB as C++), so the build computes it: 18 s of one core here (the generator uses them all),
// plus 1 s (GCC, 0.2 GB) or 2 s (clang, 1.2 GB) to compile it. The coefficients are written as
// one string literal of their bytes: 2.4M float literals took GCC over 10 s and 1.2 GB at res 64.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "candela/spectrum/dense_spectrum.h"
#include "candela/spectrum/rgb_sigmoid_fit.h"
#include "candela/spectrum/rgb_to_spectrum_table.h"
#include "candela/spectrum/spectrum_rgb.h"

namespace candela {
namespace {

double smoothstep(double x) { return x * x * (3.0 - 2.0 * x); }

struct Table {
    int res = 0;
    std::vector<float> nodes;
    std::vector<float> coefficients;  // 3 res^3 (c0, c1, c2), stored times rgb_table_normalization
    std::vector<double> residuals;    // the fit's Delta E at each node
    double largest_coefficient = 0.0;

    RgbToSpectrumTable view() const {
        return RgbToSpectrumTable{res, nodes.data(), reinterpret_cast<const unsigned char*>(coefficients.data())};
    }
};

// Runs body(i) for i in [0, n) on the machine's threads.
template <class F>
void parallel_for(int n, F body) {
    const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
    std::atomic<int> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (int i = next++; i < n; i = next++) body(i);
        });
    for (auto& t : pool) t.join();
}

Table compute_table(int res) {
    Table table;
    table.res = res;
    for (int k = 0; k < res; ++k) table.nodes.push_back(float(smoothstep(smoothstep(k / double(res - 1)))));
    table.coefficients.resize(size_t(9) * size_t(res * res * res));
    table.residuals.resize(size_t(3) * size_t(res * res * res));
    std::vector<double> largest(size_t(3 * res * res), 0.0);
    const RgbSigmoidFit fit;
    parallel_for(3 * res * res, [&](int column) {
        const int slice = column / (res * res), j = column / res % res, i = column % res;
        const double x = double(table.nodes[size_t(i)]), y = double(table.nodes[size_t(j)]);
        auto store = [&](int k, const SigmoidCoefficients& normalized, double residual) {
            const size_t node = (size_t(slice * res + k) * size_t(res) + size_t(j)) * size_t(res) + size_t(i);
            const RgbSigmoid s = sigmoid_in_nm(normalized);
            table.coefficients[3 * node + 0] = s.c0;
            table.coefficients[3 * node + 1] = s.c1;
            table.coefficients[3 * node + 2] = s.c2;
            table.residuals[node] = residual;
        };
        auto solve = [&](int k, SigmoidCoefficients& c) {
            const double z = double(table.nodes[size_t(k)]);
            if (i == res - 1 && j == res - 1) {
                // The grey axis, exactly: c = (0, 0, (z - 1/2) / sqrt(z (1 - z))), normalized.
                c = z > 0.0 && z < 1.0 ? SigmoidCoefficients(0.0, 0.0, (z - 0.5) / std::sqrt(z * (1.0 - z)))
                                       : SigmoidCoefficients();
                store(k, SigmoidCoefficients(0.0, 0.0, z - 0.5), 0.0);
                return;
            }
            const Rgb rgb = [&] {
                float v[3];
                v[slice] = float(z);
                v[(slice + 1) % 3] = float(x * z);
                v[(slice + 2) % 3] = float(y * z);
                return Rgb(v[0], v[1], v[2]);
            }();
            const double residual = fit.solve(rgb, c);
            largest[size_t(column)] = std::max(largest[size_t(column)], max_component(abs(c)));
            const double w = (double(rgb.r) + double(rgb.g) + double(rgb.b)) / 3.0;
            store(k, c * std::sqrt(w * (1.0 - w)), residual);
        };
        const int start = res / 5;
        SigmoidCoefficients c;
        for (int k = start; k < res; ++k) solve(k, c);
        c = SigmoidCoefficients();
        for (int k = start - 1; k >= 1; --k) solve(k, c);
        // Black (z = 0) is the limit of the normalized coefficients at fixed x, y, which node 1
        // (z ~ 1e-6 at res 64) has reached: there s ~ 1 / (4 x^2) and scaling the colour by a
        // factor scales x by its inverse square root.
        const size_t node1 = 3 * ((size_t(slice * res + 1) * size_t(res) + size_t(j)) * size_t(res) + size_t(i));
        const size_t node0 = 3 * ((size_t(slice * res) * size_t(res) + size_t(j)) * size_t(res) + size_t(i));
        for (int a = 0; a < 3; ++a) table.coefficients[node0 + size_t(a)] = table.coefficients[node1 + size_t(a)];
        table.residuals[node0 / 3] = 0.0;
    });
    table.largest_coefficient = *std::max_element(largest.begin(), largest.end());
    return table;
}

// The largest channel error of the round trip of rgb through the table.
double round_trip_error(const RgbToSpectrumTable& table, const Rgb& rgb) {
    const RgbSigmoid s = table(rgb);
    DenseSpectrum reflectance;
    for (int i = 0; i < kDenseSamples; ++i) reflectance.v[size_t(i)] = s(float(kDenseLambdaMin + i));
    const Rgb back = reflectance_rgb(reflectance);
    return double(std::max({std::abs(back.r - rgb.r), std::abs(back.g - rgb.g), std::abs(back.b - rgb.b)}));
}

// The worst round trip over the colours colour(i), i in [0, n), and how many exceed 1e-3.
template <class F>
void report_worst(const char* what, const Table& table, int n, F colour) {
    constexpr int kParts = 64;
    struct Worst {
        double error = 0.0;
        Rgb rgb;
        int over = 0;
    };
    std::vector<Worst> worst(kParts);
    parallel_for(kParts, [&](int part) {
        for (int i = part; i < n; i += kParts) {
            const Rgb rgb = colour(i);
            const double e = round_trip_error(table.view(), rgb);
            Worst& w = worst[size_t(part)];
            w.over += e > 1e-3 ? 1 : 0;
            if (e > w.error) w = Worst{e, rgb, w.over};
        }
    });
    Worst all;
    for (const Worst& w : worst) {
        all.over += w.over;
        if (w.error > all.error) all = Worst{w.error, w.rgb, all.over};
    }
    std::printf("%s: largest error %.3g at (%.9g, %.9g, %.9g); %d of %d over 1e-3\n", what, all.error, double(all.rgb.r),
                double(all.rgb.g), double(all.rgb.b), all.over, n);
}

void check(const Table& table) {
    const int res = table.res;
    std::printf("largest Delta E of a node's fit: %.3g; largest |coefficient| (normalized lambda): %.4g\n",
                *std::max_element(table.residuals.begin(), table.residuals.end()), table.largest_coefficient);
    report_worst("round trip at the nodes", table, 3 * res * res * res, [&](int n) {
        const int slice = n / (res * res * res), k = n / (res * res) % res, j = n / res % res, i = n % res;
        const double z = double(table.nodes[size_t(k)]);
        float v[3];
        v[slice] = float(z);
        v[(slice + 1) % 3] = float(double(table.nodes[size_t(i)]) * z);
        v[(slice + 2) % 3] = float(double(table.nodes[size_t(j)]) * z);
        return Rgb(v[0], v[1], v[2]);
    });
    constexpr int kGrid = 47;
    report_worst("round trip over a 47^3 grid between the nodes", table, kGrid * kGrid * kGrid, [](int n) {
        auto at = [](int i) { return float((i + 0.5) / kGrid); };
        return Rgb(at(n / (kGrid * kGrid)), at(n / kGrid % kGrid), at(n % kGrid));
    });
    report_worst("round trip at 1.28M colours near faces, edges, corners", table, 1280000, [](int n) {
        uint64_t state = 0x9E3779B97F4A7C15ull * uint64_t(n + 1);
        auto uniform = [&] {  // a PCG-style LCG step; the high 53 bits
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            return double(state >> 11) * 0x1.0p-53;
        };
        float c[3];
        for (float& v : c) {
            const double kind = uniform(), u = uniform(), u4 = u * u * u * u;
            v = float(kind < 1.0 / 3.0 ? u4 : (kind < 2.0 / 3.0 ? 1.0 - u4 : u));
        }
        return Rgb(c[0], c[1], c[2]);
    });
}

// Writes the table as C++: the nodes as float literals and the coefficients' bytes as one string
// literal (3-digit octal escapes, except for characters that stand for themselves).
bool write_table(const Table& table, const char* path) {
    FILE* f = std::fopen(path, "w");
    if (!f) return false;
    std::fprintf(f,
                 "// Generated by tools/rgb2spec/make_rgb_to_spectrum_table %d; the layout is in\n"
                 "// spectrum/rgb_to_spectrum_table.h. Do not edit.\n"
                 "#include \"candela/spectrum/rgb_to_spectrum_table.h\"\n\n"
                 "namespace candela {\n\nnamespace {\n\nconstexpr int kRes = %d;\n\nconst float kNodes[kRes] = {",
                 table.res, table.res);
    for (int k = 0; k < table.res; ++k)
        std::fprintf(f, "%s%.9g,", k % 6 == 0 ? "\n    " : " ", double(table.nodes[size_t(k)]));
    const size_t bytes = table.coefficients.size() * sizeof(float);
    std::fprintf(f, "\n};\n\n// 3 x %d^3 x (c0, c1, c2), float, host byte order.\nalignas(16) const unsigned char kCoefficientBytes[%zu] =",
                 table.res, bytes + 1);
    const auto* data = reinterpret_cast<const unsigned char*>(table.coefficients.data());
    for (size_t b = 0; b < bytes; ++b) {
        if (b % 64 == 0) std::fputs(b ? "\"\n    \"" : "\n    \"", f);
        const unsigned char c = data[b];
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == ' ';
        if (plain)
            std::fputc(c, f);
        else
            std::fprintf(f, "\\%03o", unsigned(c));
    }
    std::fprintf(f,
                 "\";\n\n}  // namespace\n\n"
                 "CANDELA_HD const RgbToSpectrumTable& srgb_to_spectrum_table() {\n"
                 "    static constexpr RgbToSpectrumTable kTable{kRes, kNodes, kCoefficientBytes};\n"
                 "    return kTable;\n}\n\n}  // namespace candela\n");
    return std::fclose(f) == 0;
}

}  // namespace
}  // namespace candela

int main(int argc, char** argv) {
    using namespace candela;
    const bool check_table = argc == 4 && std::strcmp(argv[3], "--check") == 0;
    if (argc < 3 || (argc > 3 && !check_table) || std::atoi(argv[1]) < 2) {
        std::fprintf(stderr, "usage: %s RES OUTPUT.cpp [--check]\n", argv[0]);
        return 2;
    }
    const Table table = compute_table(std::atoi(argv[1]));
    if (!write_table(table, argv[2])) {
        std::fprintf(stderr, "%s: cannot write %s\n", argv[0], argv[2]);
        return 1;
    }
    if (check_table) check(table);
    return 0;
}
