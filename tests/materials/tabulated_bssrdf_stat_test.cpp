// Chi-square fits (tests/support/chi2.h) of the tabulated BSSRDF's sampling: radii from
// sample_sr against the radial density 2 pi r pdf_sr(r) of the sampled channel; the exit points
// where probe segments from sample_sp cross a plane tilted against the normal (so that all three
// projection axes reach it) against pdf_sp; and the exit lobe's cosine sampling.
//
// Controls, run once each (1,000,000 samples, both sources of random numbers reject every time):
// - radii against the density of a medium with 5% more extinction: p < 1e-180 in all four;
// - radii drawn with pbrt-v4's absolute tolerance 1e-6 in the spline inversion (before the
//   change in math/catmull_rom.cpp): the low-albedo case rejects at p = 5e-17, its far tail
//   piled onto a node (53 and 37 samples where 14 are expected, 0 in the next cells);
// - probe axes drawn with probabilities 1/3 each instead of 1/4, 1/4, 1/2: chi2 = 8792 and 19999
//   on 1439 degrees of freedom;
// - the exit lobe's directions against f cos (which integrates to 1 too): chi2 = 27784 on 2449.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "candela/materials/tabulated_bssrdf.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr int kChi2Tests = 7;  // in this file, for the Sidak correction

const BssrdfTable& table_133() {
    static const BssrdfTable table = make_beam_diffusion_table(0.0f, 1.33f);
    return table;
}

// Radii r in [0, inf) as q = r / (r + length) in [0, q_max] (the table ends at 203.4 optical
// radii: q_max = 0.996 holds it for length = 1 / sigma_t), times a second, uniform coordinate
// y in [0, 1] that the harness's 2D grid needs. Point: (r, y).
struct RadialDomain {
    using Point = Vec2f;
    double length = 1.0;
    double q_max = 0.996;

    Vec2d param_min() const { return {0.0, 0.0}; }
    Vec2d param_max() const { return {q_max, 1.0}; }
    Vec2d to_param(Vec2f p) const {
        const auto r = static_cast<double>(p.x);
        return {r / (r + length), static_cast<double>(p.y)};
    }
    Vec2f from_param(Vec2d q) const {
        return {static_cast<float>(length * q.x / (1.0 - q.x)), static_cast<float>(q.y)};
    }
    double jacobian(Vec2d q) const { return length / ((1.0 - q.x) * (1.0 - q.x)); }
};

// Several albedos and extinctions, each channel of a different medium; the hero channel is
// sampled and its density checked.
void expect_radii_fit(const Color& sigma_a, const Color& sigma_s, int hero) {
    const TabulatedBssrdf b(Vec3f(0.0f), Vec3f(0, 0, 1), 1.33f, sigma_a, sigma_s, &table_133(), hero);
    RadialDomain domain;
    domain.length = 1.0 / static_cast<double>(sigma_a[hero] + sigma_s[hero]);
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.res_x = 200;
    opt.res_y = 2;
    opt.integral_tolerance = 2e-4;  // the spline's integral is the table's rho_eff (float sums)
    auto sampler = [&](Sampler& rng) -> std::optional<Vec2f> {
        std::optional<float> r = b.sample_sr(rng.next_float());
        if (!r) return std::nullopt;
        return Vec2f(*r, rng.next_float());
    };
    auto pdf = [&](Vec2f p) { return 2.0f * kPi * p.x * b.pdf_sr(p.x)[hero]; };
    Chi2Result r = chi2_test(domain, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(TabulatedBssrdfChi2, RadiiFollowTheProfileAtHighAlbedo) {
    expect_radii_fit(Color::from_channels(0.01f, 1.0f, 1.0f, 1.0f),
                     Color::from_channels(0.99f, 1.0f, 1.0f, 1.0f), 0);
}
TEST(TabulatedBssrdfChi2, RadiiFollowTheProfileOfADenseMedium) {
    expect_radii_fit(Color::from_channels(1.0f, 2.0f, 0.5f, 1.0f),
                     Color::from_channels(1.0f, 18.0f, 0.5f, 1.0f), 1);
}
TEST(TabulatedBssrdfChi2, RadiiFollowTheProfileAtLowAlbedo) {
    expect_radii_fit(Color(0.14f, 0.14f, 0.14f), Color(0.06f, 0.06f, 0.06f), 2);
}
TEST(TabulatedBssrdfChi2, RadiiFollowTheProfileBetweenTableAlbedos) {
    expect_radii_fit(Color::from_channels(1.0f, 1.0f, 1.0f, 0.43f),
                     Color::from_channels(1.0f, 1.0f, 1.0f, 2.57f), 3);
}

// Points of the plane through po with unit normal n, as polar coordinates about po in the
// plane's frame: q = rho / (rho + length) in [0, q_max] and phi in [-pi, pi].
struct PlaneDomain {
    using Point = Vec3f;
    Vec3f po;
    Frame frame;
    double length = 1.0;
    double q_max = 0.5;

    Vec2d param_min() const { return {0.0, -kPiD}; }
    Vec2d param_max() const { return {q_max, kPiD}; }
    Vec2d to_param(Vec3f p) const {
        Vec3f d = frame.to_local(p - po);
        double rho = std::hypot(static_cast<double>(d.x), static_cast<double>(d.y));
        return {rho / (rho + length), std::atan2(static_cast<double>(d.y), static_cast<double>(d.x))};
    }
    Vec3f from_param(Vec2d q) const {
        double rho = length * q.x / (1.0 - q.x);
        return po + frame.to_world(Vec3f(Vec3d(rho * std::cos(q.y), rho * std::sin(q.y), 0.0)));
    }
    // Area per unit (q, phi): rho d rho d phi.
    double jacobian(Vec2d q) const { return length * q.x / (1.0 - q.x) * length / ((1.0 - q.x) * (1.0 - q.x)); }
};

// The exit points of probe segments on a plane through po tilted against ns, against pdf_sp.
// A segment is the part inside the sphere of radius r_max about po of a line along its axis,
// so it reaches the plane exactly where the plane lies within r_max of po: the density of hits
// is pdf_sp there and 0 beyond. The domain ends at r_max, so a hit beyond it fails at once.
// The pdf integrates over the disk to the probability that a probe finds the plane (0.991 and
// 0.977 here: r_max holds 99.9% of the radii, and oblique probes reach beyond r_max).
void expect_probe_hits_fit(const Vec3f& plane_normal, const Color& sigma_a, const Color& sigma_s) {
    const Vec3f po(0.5f, -1.0f, 2.0f), ns = normalize(Vec3f(0.2f, 0.1f, 1.0f));
    const int hero = 0;
    const TabulatedBssrdf b(po, ns, 1.33f, sigma_a, sigma_s, &table_133(), hero);
    const float r_max = *b.sample_sr(0.999f);
    PlaneDomain domain{po, Frame::from_normal(plane_normal)};
    domain.length = 1.0 / static_cast<double>(sigma_a[hero] + sigma_s[hero]);
    domain.q_max = static_cast<double>(r_max) / (static_cast<double>(r_max) + domain.length);
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.res_x = 60;
    opt.res_y = 24;
    opt.expected_integral = std::nullopt;
    auto sampler = [&](Sampler& rng) -> std::optional<Vec3f> {
        const float u1 = rng.next_float(), u2a = rng.next_float(), u2b = rng.next_float();
        std::optional<BssrdfProbeSegment> seg = b.sample_sp(u1, u2a, u2b);
        if (!seg) return std::nullopt;
        const Vec3f d = seg->p1 - seg->p0;
        const float denom = dot(plane_normal, d);
        if (denom == 0.0f) return std::nullopt;
        const float t = dot(plane_normal, po - seg->p0) / denom;
        if (!(t >= 0.0f && t <= 1.0f)) return std::nullopt;
        return seg->p0 + d * t;
    };
    auto pdf = [&](Vec3f p) {
        return length(p - po) <= r_max ? b.pdf_sp(p, plane_normal)[hero] : 0.0f;
    };
    Chi2Result r = chi2_test(domain, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_GT(r.pdf_integral, 0.95);
    EXPECT_LT(r.pdf_integral, 1.0);
}

TEST(TabulatedBssrdfChi2, ProbeHitsOnATiltedPlaneFollowPdfSp) {
    expect_probe_hits_fit(normalize(Vec3f(0.6f, -0.5f, 0.62f)), Color(0.3f), Color(2.7f));
}
TEST(TabulatedBssrdfChi2, ProbeHitsOnASteepPlaneFollowPdfSp) {
    expect_probe_hits_fit(normalize(Vec3f(0.9f, 0.3f, 0.3f)), Color(0.02f, 0.5f, 0.5f),
                          Color(0.98f, 0.5f, 0.5f));
}

// pdf_sp integrates to 1 over a whole plane through po that every projection axis crosses
// (each axis's term is pdf_sr of the projected radius times the projection's Jacobian |n . axis|),
// and to 1/2 over the tangent plane, which only probes along ns reach; the table's radii end at
// 203 mean free paths, which the domain (to 2,000) contains. Sampling truncates at r_max
// (above: 0.991 and 0.977 of it is found). Quadrature to 1e-6 per cell; 30 x 12 cells.
TEST(TabulatedBssrdfChi2, PdfSpIntegratesToOneOverAPlane) {
    const Vec3f po(0.5f, -1.0f, 2.0f), ns = normalize(Vec3f(0.2f, 0.1f, 1.0f));
    const TabulatedBssrdf b(po, ns, 1.33f, Color(0.3f), Color(2.7f), &table_133(), 0);
    for (const Vec3f& n : {normalize(Vec3f(0.6f, -0.5f, 0.62f)), ns}) {
        PlaneDomain domain{po, Frame::from_normal(n)};
        domain.length = 1.0 / 3.0;
        domain.q_max = 2000.0 / 2001.0;
        auto pdf = [&](Vec3f p) { return b.pdf_sp(p, n)[0]; };
        double integral = 0.0;
        for (double cell : integrate_cells(domain, pdf, 30, 12, 1.0, 1e-6)) integral += cell;
        EXPECT_NEAR(integral, n == ns ? 0.5 : 1.0, 1e-3);
    }
}

TEST(TabulatedBssrdfChi2, ExitLobeSamplesItsPdf) {
    const NormalizedFresnel lobe{1.33f};
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    const Vec3f wo = normalize(Vec3f(0.3f, 0.1f, 0.9f));
    auto sampler = [&](Sampler& rng) -> std::optional<Vec3f> {
        std::optional<BsdfSample> s = lobe.sample(wo, rng.next_float(), rng.next_vec2f(), TransportMode::kRadiance);
        if (!s) return std::nullopt;
        return s->wi;
    };
    Chi2Result r = chi2_test(SphericalDomain{}, sampler, [&](Vec3f wi) { return lobe.pdf(wo, wi); }, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace CANDELA_UNITY_ID
}  // namespace candela::test
