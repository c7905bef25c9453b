// Computes the directional-albedo tables of materials/microfacet_albedo.h and writes them as
// src/candela/materials/microfacet_albedo_tables.cpp:
//
//     build/tools/make_microfacet_albedo src/candela/materials/microfacet_albedo_tables.cpp [--check]
//
// (a few minutes on two cores; --check as long again)
//
// Each entry E(mu, alpha[, eta]) is the integral over wi of the single-scattering lobe's
// f |cos wi|, written as an integral over the visible normals wm of wo (D_wo, Heitz 2014), the
// density the lobes sample: reflection through wm carries F G(wo, wi) / G1(wo) and, for the
// dielectric, refraction through wm (1 - F) G(wo, wt) / G1(wo) (importance transport: the power
// fraction), where a direction ending on the wrong side carries nothing (the same terms as
// DielectricLobe::evaluate; microfacet_albedo.h has the references). The integral is over the
// unit square that TrowbridgeReitz::sample_wm maps onto the visible normals, by the midpoint rule
// on kQuadrature^2 points (graded towards the rim of the normals, see albedo()), in double.
// --check also integrates at the centres of the table's cells and prints how far the interpolated
// table is from them (the tables' interpolation error).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "candela/materials/fresnel.h"
#include "candela/materials/microfacet_albedo.h"
#include "candela/materials/trowbridge_reitz.h"

namespace candela {
namespace {

constexpr int kQuadrature = 256;
// Node mu = 0 stands for the limit at grazing incidence, where wo itself is degenerate.
constexpr float kGrazingMu = 1e-4f;

// The direction at cos theta = mu (>= kGrazingMu) above the surface, or below it if `below`.
Vec3f direction(float mu, bool below) {
    mu = std::max(mu, kGrazingMu);
    return {safe_sqrt(1.0f - mu * mu), 0.0f, below ? -mu : mu};
}

// E(mu) of the white conductor (eta < 0: none) or of the dielectric of index ratio eta (wo on
// the outside, mu > 0, for eta > 1; inside for eta < 1, the lobe's index being 1 / eta then).
double albedo(float mu, float alpha, float eta) {
    if (alpha == 0.0f) return 1.0;  // a smooth interface loses nothing
    TrowbridgeReitz tr(alpha);
    const bool dielectric = eta > 0.0f;
    const float lobe_eta = dielectric && eta < 1.0f ? 1.0f / eta : eta;
    const Vec3f wo = direction(mu, dielectric && eta < 1.0f);
    const double g1 = tr.g1(wo);
    double sum = 0.0;
    for (int a = 0; a < kQuadrature; ++a) {
        for (int b = 0; b < kQuadrature; ++b) {
            // u.y = 1 - (1 - v)^4 with v on the midpoint grid: u.y -> 1 is the rim of the
            // spherical cap, the normals that tilt most, where the light that leaves the lobe
            // (reflected below the horizon) is found; a uniform grid in u.y steps over it at small
            // alpha (256^2 points miss 8e-4 of E at alpha 0.026, mu 0.82; these miss 1e-5).
            double rest = 1.0 - (b + 0.5) / kQuadrature;
            double jacobian = 4.0 * rest * rest * rest;
            Vec2f u((float(a) + 0.5f) / kQuadrature, float(1.0 - sqr(sqr(rest))));
            Vec3f wm = tr.sample_wm(wo, u);
            float fresnel = dielectric ? fresnel_dielectric(dot(wo, wm), lobe_eta) : 1.0f;
            Vec3f wr = reflect(wo, wm);
            if (wr.z * wo.z > 0.0f) sum += jacobian * double(fresnel) * double(tr.g(wo, wr)) / g1;
            Vec3f wt;
            if (dielectric && fresnel < 1.0f && refract(wo, wm, lobe_eta, &wt) && wt.z * wo.z < 0.0f)
                sum += jacobian * double(1.0f - fresnel) * double(tr.g(wo, wt)) / g1;
        }
    }
    return sum / (double(kQuadrature) * kQuadrature);
}

// Runs body(i) for i in [0, n) on a few threads.
void parallel_for(int n, const std::function<void(int)>& body) {
    int threads = int(std::max(1u, std::min(8u, std::thread::hardware_concurrency())));
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            for (int i = t; i < n; i += threads) body(i);
        });
    for (auto& th : pool) th.join();
}

struct Tables {
    std::vector<float> conductor = std::vector<float>(kAlbedoAlphaCount * kAlbedoMuCount);
    std::vector<float> conductor_avg = std::vector<float>(kAlbedoAlphaCount);
    std::vector<float> dielectric = std::vector<float>(2 * kAlbedoEtaCount * kAlbedoAlphaCount * kAlbedoMuCount);
    std::vector<float> dielectric_avg = std::vector<float>(2 * kAlbedoEtaCount * kAlbedoAlphaCount);
};

// The eta of table side s (0 entering, 1 leaving) at node k; node 0 is the limit eta -> 1.
float side_eta(int side, int k) {
    float eta = k == 0 ? 1.0001f : albedo_eta_node(k);
    return side == 0 ? eta : 1.0f / eta;
}

// The value as written to the table (5 decimals), so that the averages are those of the table.
float written(double e) { return float(std::round(e * 1e5) / 1e5); }

Tables compute() {
    Tables t;
    parallel_for(kAlbedoAlphaCount, [&](int i) {
        for (int j = 0; j < kAlbedoMuCount; ++j)
            t.conductor[i * kAlbedoMuCount + j] = written(albedo(albedo_mu_node(j), albedo_alpha_node(i), -1.0f));
        t.conductor_avg[i] = albedo_average(&t.conductor[i * kAlbedoMuCount]);
    });
    parallel_for(2 * kAlbedoEtaCount * kAlbedoAlphaCount, [&](int row) {
        int side = row / (kAlbedoEtaCount * kAlbedoAlphaCount);
        int k = row / kAlbedoAlphaCount % kAlbedoEtaCount, i = row % kAlbedoAlphaCount;
        float* e = &t.dielectric[row * kAlbedoMuCount];
        for (int j = 0; j < kAlbedoMuCount; ++j)
            e[j] = written(albedo(albedo_mu_node(j), albedo_alpha_node(i), side_eta(side, k)));
        t.dielectric_avg[row] = albedo_average(e);
    });
    return t;
}

// Linear interpolation in the computed tables, as microfacet_albedo.h does in the generated ones.
double interpolated(const Tables& t, float mu, float alpha, float eta) {
    AxisPosition m = albedo_mu_position(mu);
    AxisPosition a = axis_position(std::sqrt(alpha) * float(kAlbedoAlphaCount - 1), kAlbedoAlphaCount);
    auto row_value = [&](const float* row) {
        return double(row[m.i0]) + double(m.t) * (double(row[m.i0 + 1]) - double(row[m.i0]));
    };
    auto alpha_value = [&](const float* rows) {
        return (1.0 - double(a.t)) * row_value(rows + a.i0 * kAlbedoMuCount) +
               double(a.t) * row_value(rows + (a.i0 + 1) * kAlbedoMuCount);
    };
    if (eta < 0.0f) return alpha_value(t.conductor.data());
    int side = eta >= 1.0f ? 0 : 1;
    AxisPosition z = albedo_eta_position(eta >= 1.0f ? eta : 1.0f / eta);
    const float* base = &t.dielectric[side * kAlbedoEtaCount * kAlbedoAlphaCount * kAlbedoMuCount];
    return (1.0 - double(z.t)) * alpha_value(base + z.i0 * kAlbedoAlphaCount * kAlbedoMuCount) +
           double(z.t) * alpha_value(base + (z.i0 + 1) * kAlbedoAlphaCount * kAlbedoMuCount);
}

// The largest |table - integral| at the centres of the table's cells (every other one in mu and
// every third in alpha for the dielectric, to save time), over all cells and over those with
// mu >= 0.01 and alpha >= 0.01 (grazing incidence on nearly smooth surfaces is where E changes
// fastest: a peak of width about alpha at mu = 0).
void check(const Tables& t) {
    auto cell_mu = [](int j) { return 0.5f * (albedo_mu_node(j) + albedo_mu_node(j + 1)); };
    auto cell_alpha = [](int i) { return sqr((float(i) + 0.5f) / float(kAlbedoAlphaCount - 1)); };
    struct Worst {
        double all = 0.0, away = 0.0;
        float mu = 0.0f, alpha = 0.0f, away_mu = 0.0f, away_alpha = 0.0f;
        void add(double d, float m, float a) {
            if (d > all) all = d, mu = m, alpha = a;
            if (m >= 0.01f && a >= 0.01f && d > away) away = d, away_mu = m, away_alpha = a;
        }
    };
    auto report = [](const char* what, const Worst& w) {
        std::printf("%s: max |interpolated - integral| %.2e (at mu %.3f alpha %.4f), "
                    "%.2e where mu and alpha >= 0.01 (at mu %.3f alpha %.4f)\n",
                    what, w.all, double(w.mu), double(w.alpha), w.away, double(w.away_mu), double(w.away_alpha));
    };
    std::vector<Worst> conductor(kAlbedoAlphaCount);
    parallel_for(kAlbedoAlphaCount - 1, [&](int i) {
        for (int j = 0; j + 1 < kAlbedoMuCount; ++j)
            conductor[i].add(std::abs(interpolated(t, cell_mu(j), cell_alpha(i), -1.0f) -
                                      albedo(cell_mu(j), cell_alpha(i), -1.0f)),
                             cell_mu(j), cell_alpha(i));
    });
    for (int i = 1; i < kAlbedoAlphaCount - 1; ++i) {
        conductor[0].add(conductor[i].all, conductor[i].mu, conductor[i].alpha);
        conductor[0].add(conductor[i].away, conductor[i].away_mu, conductor[i].away_alpha);
    }
    report("conductor", conductor[0]);
    for (int side = 0; side < 2; ++side) {
        std::vector<Worst> worst(kAlbedoEtaCount);
        parallel_for(kAlbedoEtaCount - 1, [&](int k) {
            float zc = (float(k) + 0.5f) / float(kAlbedoEtaCount - 1) * kAlbedoZMax;
            float eta = (1.0f + zc) / (1.0f - zc);
            if (side == 1) eta = 1.0f / eta;
            for (int i = 2; i + 1 < kAlbedoAlphaCount; i += 3)
                for (int j = 0; j + 1 < kAlbedoMuCount; j += 2)
                    worst[k].add(std::abs(interpolated(t, cell_mu(j), cell_alpha(i), eta) -
                                          albedo(cell_mu(j), cell_alpha(i), eta)),
                                 cell_mu(j), cell_alpha(i));
        });
        for (int k = 0; k + 1 < kAlbedoEtaCount; ++k) {
            char what[96];
            std::snprintf(what, sizeof what, "dielectric %s, eta' %.3f-%.3f", side == 0 ? "entering" : "leaving",
                          double(albedo_eta_node(k)), double(albedo_eta_node(k + 1)));
            report(what, worst[k]);
        }
    }
}

// Values to `digits` decimals, `row` to a line (the albedos are written() values: 5 decimals
// are exact; the averages get 9 significant digits, which a float reads back unchanged).
void write_array(std::FILE* f, const char* declaration, const std::vector<float>& v, int row, bool exact) {
    std::fprintf(f, "%s = {", declaration);
    for (size_t n = 0; n < v.size(); ++n) {
        if (n % size_t(row) == 0) std::fprintf(f, "\n   ");
        char text[32];
        std::snprintf(text, sizeof text, exact ? "%.9g" : "%.5f", double(v[n]));
        // 0.98700 as 0.987 and 1.00000 as 1: the same number, a smaller file.
        std::string s = text;
        if (!exact && s.find('.') != std::string::npos) {
            s.erase(s.find_last_not_of('0') + 1);
            if (s.back() == '.') s.pop_back();
        }
        std::fprintf(f, " %s,", s.c_str());
    }
    std::fprintf(f, "\n};\n\n");
}

void write(const Tables& t, const char* path) {
    std::FILE* f = std::fopen(path, "w");
    if (!f) {
        std::perror(path);
        std::exit(1);
    }
    std::fprintf(f,
                 "// GENERATED by tools/microfacet_albedo/make_microfacet_albedo.cpp; do not edit.\n"
                 "// The directional albedo tables declared and described in microfacet_albedo.h.\n"
                 "#include \"candela/materials/microfacet_albedo.h\"\n\n"
                 "namespace candela {\n\n"
                 "// clang-format off\n");
    write_array(f, "const float kConductorAlbedo[kAlbedoAlphaCount][kAlbedoMuCount]", t.conductor, 16, false);
    write_array(f, "const float kConductorAlbedoAvg[kAlbedoAlphaCount]", t.conductor_avg, 8, true);
    write_array(f, "const float kDielectricAlbedo[2][kAlbedoEtaCount][kAlbedoAlphaCount][kAlbedoMuCount]",
                t.dielectric, 16, false);
    write_array(f, "const float kDielectricAlbedoAvg[2][kAlbedoEtaCount][kAlbedoAlphaCount]", t.dielectric_avg, 8,
                true);
    std::fprintf(f, "// clang-format on\n\n}  // namespace candela\n");
    std::fclose(f);
}

}  // namespace
}  // namespace candela

int main(int argc, char** argv) {
    if (argc < 2 || (argc == 3 && std::strcmp(argv[2], "--check") != 0) || argc > 3) {
        std::fprintf(stderr, "usage: make_microfacet_albedo OUT.cpp [--check]\n");
        return 2;
    }
    candela::Tables t = candela::compute();
    candela::write(t, argv[1]);
    if (argc == 3) candela::check(t);
    return 0;
}
