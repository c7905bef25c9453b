// Monte Carlo estimates of irradiance with LightSet::sample, E = mean(Le cos theta / pdf), against
// closed forms: a sphere fully above the horizon gives E = pi L (r/d)^2 cos beta; a polygon gives
// Lambert's formula E = L/2 sum_i theta_i (n . gamma_i). The bound is 5 standard errors of the
// estimate (from its sample variance), so a correct sampler fails with probability < 1e-6.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/sampling/rng.h"
#include "lights/light_test_scene.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr int kSamples = 200'000;

struct Estimate {
    double mean = 0.0;
    double standard_error = 0.0;
};

// Irradiance (luminance channel g, emission is grey here) at x with unit normal n.
Estimate estimate_irradiance(const LightSet& lights, const Vec3f& x, const Vec3f& n, uint64_t seed) {
    Rng rng(seed, 17);
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < kSamples; ++i) {
        float uc = rng.next_float();
        Vec2f u = rng.next_vec2f();
        double f = 0.0;
        if (std::optional<LightSample> s = lights.sample(x, uc, u)) {
            double cos_theta = static_cast<double>(dot(n, normalize(s->p - x)));
            if (cos_theta > 0.0) f = static_cast<double>(s->Le[1]) * cos_theta / static_cast<double>(s->pdf);
        }
        sum += f;
        sum2 += f * f;
    }
    Estimate e;
    e.mean = sum / kSamples;
    double variance = std::max(0.0, sum2 / kSamples - e.mean * e.mean) * kSamples / (kSamples - 1.0);
    e.standard_error = std::sqrt(variance / kSamples);
    return e;
}

void expect_matches(const Estimate& e, double exact) {
    EXPECT_NEAR(e.mean, exact, 5.0 * e.standard_error) << "relative error " << (e.mean - exact) / exact;
    // A bound that says something: the estimator is precise to well under a percent.
    EXPECT_LT(e.standard_error, 0.005 * exact);
}

// Lambert's formula for the irradiance at x (normal n) from a polygon of radiance L with vertices
// `polygon`, entirely above x's horizon: each edge (v_i, v_i+1), seen from x, subtends the angle
// theta_i in the plane with unit normal gamma_i = v_i x v_i+1 / |v_i x v_i+1|.
double polygon_irradiance(const std::vector<Vec3d>& polygon, const Vec3d& x, const Vec3d& n, double L) {
    double sum = 0.0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        Vec3d a = normalize(polygon[i] - x);
        Vec3d b = normalize(polygon[(i + 1) % polygon.size()] - x);
        Vec3d c = cross(a, b);
        double theta = std::atan2(length(c), dot(a, b));
        sum += theta * dot(n, c / length(c));
    }
    return 0.5 * L * std::abs(sum);
}

TEST(LightIrradiance, SphereFacingThePoint) {
    LightTestScene scene;
    scene.add_sphere({Vec3d(0.0, 0.0, 3.0), 1.0, false}, Rgb(2.0f));
    LightSet lights = scene.light_set();
    expect_matches(estimate_irradiance(lights, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 1), kPiD * 2.0 / 9.0);
}

TEST(LightIrradiance, NearSphereTiltedButAboveTheHorizon) {
    // sin theta_max = 1 / 1.25 (53 degrees), normal tilted 30 degrees from the centre's direction.
    LightTestScene scene;
    scene.add_sphere({Vec3d(0.0, 0.0, 1.25), 1.0, false}, Rgb(1.0f));
    LightSet lights = scene.light_set();
    const double beta = kPiD / 6.0;
    Vec3f n(static_cast<float>(std::sin(beta)), 0.0f, static_cast<float>(std::cos(beta)));
    expect_matches(estimate_irradiance(lights, {0.0f, 0.0f, 0.0f}, n, 2), kPiD / (1.25 * 1.25) * std::cos(beta));
}

TEST(LightIrradiance, SmallptLightOnTheFloor) {
    LightTestScene scene;
    const Vec3d centre(50.0, 681.6 - 0.27, 81.6);
    scene.add_sphere({centre, 600.0, false}, Rgb(12.0f));
    LightSet lights = scene.light_set();
    const Vec3f x(50.0f, 0.0f, 81.6f);
    double d = centre.y;
    expect_matches(estimate_irradiance(lights, x, {0.0f, 1.0f, 0.0f}, 3), kPiD * 12.0 * (600.0 / d) * (600.0 / d));
}

TEST(LightIrradiance, QuadMatchesLambertsFormula) {
    // A tilted quad facing the point, above its horizon.
    const Vec3f corner(-0.5f, -0.3f, 1.0f), e1(1.2f, 0.0f, 0.2f), e2(0.0f, 0.9f, 0.3f);
    LightTestScene scene;
    scene.add_mesh(make_quad(corner, e2, e1), Rgb(1.5f));  // normal cross(e2, e1): towards -z
    LightSet lights = scene.light_set();
    std::vector<Vec3d> polygon{Vec3d(corner), Vec3d(corner + e1), Vec3d(corner + e1 + e2), Vec3d(corner + e2)};
    for (Vec3f n : {Vec3f(0.0f, 0.0f, 1.0f), normalize(Vec3f(0.3f, -0.2f, 1.0f))}) {
        double exact = polygon_irradiance(polygon, Vec3d(0.0, 0.0, 0.0), Vec3d(n), 1.5);
        expect_matches(estimate_irradiance(lights, {0.0f, 0.0f, 0.0f}, n, 4), exact);
    }
}

TEST(LightIrradiance, QuadAndSphereSelectedByPowerAddUp) {
    const Vec3f corner(-2.0f, -0.5f, 1.0f), e1(1.0f, 0.0f, 0.0f), e2(0.0f, 1.0f, 0.0f);
    LightTestScene scene;
    scene.add_mesh(make_quad(corner, e2, e1), Rgb(3.0f));
    scene.add_sphere({Vec3d(2.0, 0.0, 2.0), 0.5, false}, Rgb(1.0f));
    for (LightSelection selection : {LightSelection::kPower, LightSelection::kUniform}) {
        LightSet lights = scene.light_set(selection);
        std::vector<Vec3d> polygon{Vec3d(corner), Vec3d(corner + e1), Vec3d(corner + e1 + e2), Vec3d(corner + e2)};
        double quad = polygon_irradiance(polygon, Vec3d(0.0, 0.0, 0.0), Vec3d(0.0, 0.0, 1.0), 3.0);
        // The sphere: d^2 = 8, its centre 45 degrees off the normal (and its cone of 10 degrees
        // entirely above the horizon).
        double sphere = kPiD * 0.25 / 8.0 * std::cos(kPiD / 4.0);
        expect_matches(estimate_irradiance(lights, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 5), quad + sphere);
    }
}

// The irradiance at a point from a uniform disk of radius r and radiance L in a parallel plane at
// height h, its centre offset by a from the point's normal line: E = pi L F with the
// differential-element-to-parallel-disk form factor (Howell's catalogue of configuration factors)
// F = (1/2) (1 - (Z - 2 R^2) / sqrt(Z^2 - 4 R^2)), H = h / a, R = r / a, Z = 1 + H^2 + R^2; on
// the axis (a = 0), F = r^2 / (h^2 + r^2).
double parallel_disk_irradiance(double h, double r, double a, double L) {
    if (a == 0.0) return kPiD * L * r * r / (h * h + r * r);
    const double H = h / a, R = r / a, Z = 1.0 + H * H + R * R;
    return kPiD * L * 0.5 * (1.0 - (Z - 2.0 * R * R) / std::sqrt(Z * Z - 4.0 * R * R));
}

// The disk as a polygon of n vertices on its rim (the closed form's independent check; the
// polygon's missing area, (2 pi / n)^2 / 6 of the whole, is 1e-7 at n = 8192).
std::vector<Vec3d> rim_polygon(const Disk& d, int n) {
    std::vector<Vec3d> polygon;
    for (int i = 0; i < n; ++i) {
        double phi = 2.0 * kPiD * i / n;
        polygon.push_back(d.point(std::cos(phi), std::sin(phi)));
    }
    return polygon;
}

TEST(LightIrradiance, DiskClosedFormMatchesLambertsFormulaForItsRim) {
    for (double a : {0.0, 0.3, 1.0, 2.5}) {
        Disk d = make_round_disk({a, 0.0, 1.2}, {0.0, 0.0, -1.0}, 0.7);
        double polygon = polygon_irradiance(rim_polygon(d, 8192), {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0);
        EXPECT_NEAR(parallel_disk_irradiance(1.2, 0.7, a, 1.0) / polygon, 1.0, 1e-6) << "offset " << a;
    }
}

TEST(LightIrradiance, DiskMatchesTheClosedFormOnAndOffItsAxis) {
    for (double a : {0.0, 0.9}) {
        LightTestScene scene;
        scene.add_disk(make_round_disk({a, 0.0, 1.5}, {0.0, 0.0, -1.0}, 0.8), Rgb(2.5f));
        LightSet lights = scene.light_set();
        expect_matches(estimate_irradiance(lights, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 6 + uint64_t(a > 0.0)),
                       parallel_disk_irradiance(1.5, 0.8, a, 2.5));
    }
}

TEST(LightIrradiance, TiltedEllipseMatchesLambertsFormulaForItsRim) {
    LightTestScene scene;
    Disk d = transform_disk(make_round_disk({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0),
                            Transform::translate({0.4, -0.3, 1.6}) * Transform::rotate({1.0, 1.0, 0.0}, 2.7) *
                                Transform::scale({0.9, 0.35, 1.0}),
                            false);
    ASSERT_LT(d.normal.z, 0.0);  // faces the point
    scene.add_disk(d, Rgb(1.5f));
    LightSet lights = scene.light_set();
    Vec3f n = normalize(Vec3f(0.2f, -0.1f, 1.0f));
    expect_matches(estimate_irradiance(lights, {0.0f, 0.0f, 0.0f}, n, 8),
                   polygon_irradiance(rim_polygon(d, 8192), {0.0, 0.0, 0.0}, Vec3d(n), 1.5));
}

}  // namespace
}  // namespace candela::test
