// Chi-square goodness of fit of every warp against its pdf (tests/support/chi2.h), 1M samples
// each. Supports are inside the domains and, where possible, their edges are cell edges.
#include <gtest/gtest.h>

#include "candela/sampling/normal.h"
#include "candela/sampling/warps.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

// The chi-square tests in this file, for the Sidak correction.
constexpr int kChi2Tests = 11;

Chi2Options options() {
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    return opt;
}

// Runs the harness and prints its diagnostics on failure.
template <class Domain, class Sampler, class Pdf>
void expect_fits(const Domain& domain, Sampler sampler, Pdf pdf, Chi2Options opt = options()) {
    Chi2Result r = chi2_test(domain, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(WarpsChi2, UniformSphereMatchesPdf) {
    expect_fits(SphericalDomain{}, [](Sampler& rng) { return sample_uniform_sphere(rng.next_vec2f()); },
                uniform_sphere_pdf);
}

TEST(WarpsChi2, UniformHemisphereMatchesPdf) {
    // The whole sphere, so that a sample below the horizon fails in a zero cell (the horizon
    // cos theta = 0 is a row edge of the 50 rows).
    expect_fits(SphericalDomain{},
                [](Sampler& rng) { return sample_uniform_hemisphere(rng.next_vec2f()); },
                uniform_hemisphere_pdf);
}

TEST(WarpsChi2, CosineHemisphereMatchesPdf) {
    expect_fits(SphericalDomain{},
                [](Sampler& rng) { return sample_cosine_hemisphere(rng.next_vec2f()); },
                cosine_hemisphere_pdf);
}

// Cones: wider than a hemisphere, with its edge through the cells, and narrow in a domain that
// covers cos theta in [0.9, 1] (edge at row 25).
void expect_cone_fits(float cos_theta_max, SphericalDomain domain) {
    expect_fits(domain,
                [=](Sampler& rng) { return sample_uniform_cone(rng.next_vec2f(), cos_theta_max); },
                [=](Vec3f w) { return uniform_cone_pdf(w, cos_theta_max); });
}
TEST(WarpsChi2, WideConeMatchesPdf) { expect_cone_fits(-0.3f, SphericalDomain{}); }
TEST(WarpsChi2, MediumConeMatchesPdf) { expect_cone_fits(0.5f, SphericalDomain{}); }
TEST(WarpsChi2, NarrowConeMatchesPdf) { expect_cone_fits(0.95f, SphericalDomain{0.9, 1.0}); }

TEST(WarpsChi2, ConcentricDiskMatchesPdf) {
    Chi2Options opt = options();
    opt.res_x = opt.res_y = 64;
    expect_fits(PlanarDomain{{-1.0, -1.0}, {1.0, 1.0}},
                [](Sampler& rng) { return sample_concentric_disk(rng.next_vec2f()); },
                concentric_disk_pdf, opt);
}

TEST(WarpsChi2, TriangleMatchesPdf) {
    // Barycentrics placed on a fixed scalene triangle in the unit square.
    const Vec2f p0(0.1f, 0.2f), p1(0.9f, 0.35f), p2(0.3f, 0.95f);
    auto edge = [](Vec2f a, Vec2f b, Vec2f p) {  // twice the signed area of (a, b, p)
        return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    };
    const float area = 0.5f * edge(p0, p1, p2);
    auto sampler = [=](Sampler& rng) {
        Vec3f b = sample_uniform_triangle(rng.next_vec2f());
        return p0 * b.x + p1 * b.y + p2 * b.z;
    };
    auto pdf = [=](Vec2f p) {
        bool inside = edge(p0, p1, p) >= 0.0f && edge(p1, p2, p) >= 0.0f && edge(p2, p0, p) >= 0.0f;
        return inside ? uniform_triangle_pdf(area) : 0.0f;
    };
    Chi2Options opt = options();
    opt.res_x = opt.res_y = 64;
    expect_fits(PlanarDomain{}, sampler, pdf, opt);
}

// 1D warps: the value along x, an independent uniform along y (so a 2D histogram of 100 x 10).
template <class Sample1d, class Pdf1d>
void expect_1d_fits(double lo, double hi, Sample1d sample, Pdf1d pdf) {
    Chi2Options opt = options();
    opt.res_x = 100;
    opt.res_y = 10;
    expect_fits(PlanarDomain{{lo, 0.0}, {hi, 1.0}},
                [=](Sampler& rng) {
                    float x = sample(rng.next_float());
                    return Vec2f(x, rng.next_float());
                },
                [=](Vec2f p) { return p.y >= 0.0f && p.y <= 1.0f ? pdf(p.x) : 0.0f; }, opt);
}

TEST(WarpsChi2, TentMatchesPdf) {
    expect_1d_fits(-0.7, 0.7, [](float u) { return sample_tent(u, 0.7f); },
                   [](float x) { return tent_pdf(x, 0.7f); });
}

TEST(WarpsChi2, StandardNormalMatchesPdf) {
    // Inversion of u >= 2^-24 reaches about 5.4 sigma; [-6, 6] holds every sample.
    expect_1d_fits(-6.0, 6.0, sample_standard_normal, standard_normal_pdf);
}

TEST(WarpsChi2, TruncatedNormalMatchesPdf) {
    expect_1d_fits(-2.0, 2.0, [](float u) { return sample_truncated_normal(u, 0.8f, 2.0f); },
                   [](float x) { return truncated_normal_pdf(x, 0.8f, 2.0f); });
}

}  // namespace
}  // namespace candela::test
