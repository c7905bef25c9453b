// Point, spot, directional and disk lights against closed forms (DESIGN.md, "Correctness"), as
// analytic_render_test.cpp does for quads: a diffuse floor of albedo rho under irradiance E
// renders rho E / pi with max_depth = 1, for every estimator that can see the light.
//   point:        E = I cos theta / r^2
//   spot:         E = I s(cos alpha) cos theta / r^2, s pbrt-v4's smoothstep falloff of the angle
//                 alpha from the spot's axis (lights/spot_light.h)
//   directional:  E = E0 cos theta everywhere it is not shadowed, however far the occluder
//   disk:         E = pi L F, F the form factor of a parallel disk (Howell's catalogue)
// Each z-test has a control that must fail: the same render against the closed form times 1.05,
// and for the spot against a falloff linear in the angle instead of the smoothstep.
// With delta lights the only randomness left (one light, no bounce) is the position in the pixel,
// so the samples barely vary where E is smooth; the z-tests then allow for the float rounding of
// the renderer (1e-5 of the value, about a hundred float steps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <ostream>
#include <string>

#include "candela/geometry/disk_intersection.h"
#include "candela/render/renderer.h"
#include "support/plane_irradiance.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 32;
constexpr int kBlock = 4;
constexpr double kRounding = 1e-5;
const Rgb kAlbedo(0.8f, 0.6f, 0.4f);

// A large diffuse floor y = 0 facing up, seen obliquely from above, lit directly (max_depth 1).
Scene lit_floor() {
    Scene s;
    s.materials = {make_diffuse(kAlbedo), make_diffuse(Rgb(0.0f))};
    s.material_names = {"floor", "black"};
    test::add_quad(s, {-50, 0, -50}, {0, 0, 100}, {100, 0, 0}, 0);
    test::set_camera(s, {0.0f, 1.1f, -1.6f}, {0.0f, 0.0f, 0.15f}, 60, kSize, kSize);
    s.sampler.seed = 13;
    s.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    s.integrator.max_depth = 1;
    return s;
}

void add_light(Scene& s, const DeltaLight& light) { s.delta_lights.push_back({light, std::nullopt}); }

struct EstimatorCase {
    std::string name;
    IntegratorType type;
    bool mis;
};
void PrintTo(const EstimatorCase& c, std::ostream* os) { *os << c.name; }

Scene with_estimator(Scene s, const EstimatorCase& c, int spp) {
    s.integrator.type = c.type;
    s.integrator.mis = c.mis;
    s.sampler.spp = spp;
    return s;
}

// Renders `scene` and z-tests the floor within `plane` against `irradiance`; the control (the
// closed form x 1.05) must reject in at least a quarter of the blocks where light arrives.
template <class Irradiance>
test::RenderMoments expect_closed_form(const Scene& scene, const test::ReceiverPlane& plane,
                                       const Irradiance& irradiance, const std::string& name) {
    test::RenderMoments m = test::render_moments(scene);
    EXPECT_EQ(m.dropped, 0u);
    test::ExpectedImage e = test::expected_plane_image(scene, plane, irradiance);
    EXPECT_GT(test::valid_blocks(e, kBlock), (kSize / kBlock) * (kSize / kBlock) / 4);
    test::ZTestFamily family = test::test_plane_image(m, e, kAlbedo, 1.0, kBlock, kRounding);
    EXPECT_TRUE(family.passed()) << family.summary();
    test::ZTestFamily wrong = test::test_plane_image(m, e, kAlbedo, 1.05, kBlock, kRounding);
    EXPECT_GE(wrong.rejected(), test::lit_block_tests(e, kBlock) / 4) << wrong.summary();
    if (!family.passed()) test::write_diagnostic(m, "delta_light_" + name);
    return m;
}

// ---- point light

const Vec3d kPointPosition(0.15, 0.7, 0.25);
constexpr float kPointIntensity = 1.5f;

double point_irradiance(const Vec3d& p) {
    Vec3d d = kPointPosition - p;
    double r = length(d);
    return double(kPointIntensity) * std::max(0.0, d.y) / (r * r * r);  // I cos theta / r^2, n = +y
}

class DeltaLightIrradiance : public ::testing::TestWithParam<EstimatorCase> {};

TEST_P(DeltaLightIrradiance, PointLightFollowsTheInverseSquareCosineLaw) {
    Scene s = lit_floor();
    add_light(s, PointLight{Vec3f(kPointPosition), Color(kPointIntensity)});
    expect_closed_form(with_estimator(s, GetParam(), 64), {0.0f, 1.0f, 0.15, 0.25, 1.2}, point_irradiance,
                       "point_" + GetParam().name);
}

// ---- spot light: from 0.7 above the floor, tilted, cone 40 degrees falling off from 25.

const Vec3d kSpotPosition(-0.1, 0.7, 0.3);
const Vec3d kSpotAxis = normalize(Vec3d(0.15, -1.0, 0.1));
constexpr double kConeAngle = 40.0, kConeDelta = 15.0;

SpotLight test_spot() {
    SpotLight light;
    light.position = Vec3f(kSpotPosition);
    light.axis = Vec3f(kSpotAxis);
    light.intensity = Color(2.0f);
    light.cos_falloff_start = std::cos(radians(float(kConeAngle - kConeDelta)));
    light.cos_falloff_end = std::cos(radians(float(kConeAngle)));
    return light;
}

// E at p with the falloff `profile(alpha_degrees)` of the angle from the axis.
template <class Profile>
double spot_irradiance(const Vec3d& p, const Profile& profile) {
    Vec3d d = kSpotPosition - p;
    double r = length(d);
    double alpha = std::acos(std::clamp(dot(-d / r, kSpotAxis), -1.0, 1.0)) * 180.0 / kPiD;
    return 2.0 * profile(alpha) * std::max(0.0, d.y) / (r * r * r);
}

// pbrt-v4's: the smoothstep of cos alpha between cos(cone_angle) and cos(cone_angle - cone_delta).
double smoothstep_profile(double alpha) {
    const double ce = std::cos(kConeAngle * kPiD / 180.0), cs = std::cos((kConeAngle - kConeDelta) * kPiD / 180.0);
    const double t = std::clamp((std::cos(alpha * kPiD / 180.0) - ce) / (cs - ce), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// A plausible wrong one: linear in the angle over the same range.
double linear_profile(double alpha) {
    return std::clamp((kConeAngle - alpha) / kConeDelta, 0.0, 1.0);
}

TEST_P(DeltaLightIrradiance, SpotLightFallsOffAsPbrtsSmoothstep) {
    Scene s = lit_floor();
    add_light(s, test_spot());
    const test::ReceiverPlane plane{0.0f, 1.0f, 0.0, 0.35, 1.3};
    Scene scene = with_estimator(s, GetParam(), 64);
    test::RenderMoments m = expect_closed_form(
        scene, plane, [](const Vec3d& p) { return spot_irradiance(p, smoothstep_profile); },
        "spot_" + GetParam().name);
    // The test sees the profile: a linear falloff is rejected.
    test::ExpectedImage linear =
        test::expected_plane_image(scene, plane, [](const Vec3d& p) { return spot_irradiance(p, linear_profile); });
    test::ZTestFamily wrong = test::test_plane_image(m, linear, kAlbedo, 1.0, kBlock, kRounding);
    EXPECT_GE(wrong.rejected(), 3) << wrong.summary();
    // And the edge is inside the view: some of the floor tested is dark, some fully lit.
    const test::ExpectedImage e = test::expected_plane_image(
        scene, plane, [](const Vec3d& p) { return spot_irradiance(p, smoothstep_profile); });
    int dark = 0, lit = 0;
    for (size_t i = 0; i < e.value.size(); ++i) {
        if (!e.valid[i]) continue;
        dark += e.value[i] == 0.0;
        lit += e.value[i] > 0.0;
    }
    EXPECT_GT(dark, 20);
    EXPECT_GT(lit, 100);
}

// ---- disk light: radius 0.6, radiance 3, 0.8 above the floor, facing down.

const Vec3d kDiskCenter(0.2, 0.8, 0.1);
constexpr double kDiskRadius = 0.6, kDiskRadiance = 3.0;

double disk_irradiance(const Vec3d& p) {
    // Howell's differential element to a parallel disk: H = h / a, R = r / a, Z = 1 + H^2 + R^2,
    // F = (1 - (Z - 2 R^2) / sqrt(Z^2 - 4 R^2)) / 2; on the axis F = r^2 / (h^2 + r^2).
    const double h = kDiskCenter.y - p.y, a = std::hypot(p.x - kDiskCenter.x, p.z - kDiskCenter.z);
    const double r = kDiskRadius;
    double F;
    if (a < 1e-9) {
        F = r * r / (h * h + r * r);
    } else {
        const double H = h / a, R = r / a, Z = 1.0 + H * H + R * R;
        F = 0.5 * (1.0 - (Z - 2.0 * R * R) / std::sqrt(Z * Z - 4.0 * R * R));
    }
    return kPiD * kDiskRadiance * F;
}

void add_disk_light(Scene& s) {
    s.disks.push_back(make_round_disk(kDiskCenter, {0, -1, 0}, kDiskRadius));
    s.shapes.push_back({ShapeKind::kDisk, uint32_t(s.disks.size() - 1), 1, Rgb(float(kDiskRadiance)), false});
}

class DiskLightIrradiance : public ::testing::TestWithParam<std::pair<EstimatorCase, int>> {};

TEST_P(DiskLightIrradiance, FloorUnderADiskMatchesTheParallelDiskFormFactor) {
    Scene s = lit_floor();
    add_disk_light(s);
    const auto& [estimator, spp] = GetParam();
    test::RenderMoments m = test::render_moments(with_estimator(s, estimator, spp));
    EXPECT_EQ(m.dropped, 0u);
    // The disk's own pixels are not tested: the region is the floor around its foot, which the
    // disk hides from the camera in part; expected_plane_image only sees the floor, so the hidden
    // pixels are left out by their footprint not reaching the floor unobstructed.
    test::ExpectedImage e = test::expected_plane_image(s, {0.0f, 1.0f, 0.2, 0.1, 1.0}, disk_irradiance);
    PerspectiveCamera camera(s.camera);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int corner = 0; corner < 4; ++corner) {
                Ray r = camera.generate_ray({float(x + corner % 2), float(y + corner / 2)});
                if (intersect_disk(s.disks[0], Vec3d(r.o), Vec3d(r.d), 0.0, 1e30))
                    e.valid[size_t(y) * kSize + size_t(x)] = false;
            }
    EXPECT_GT(test::valid_blocks(e, kBlock), 10);
    test::ZTestFamily family = test::test_plane_image(m, e, kAlbedo, 1.0, kBlock);
    EXPECT_TRUE(family.passed()) << family.summary();
    test::ZTestFamily wrong = test::test_plane_image(m, e, kAlbedo, 1.05, kBlock);
    EXPECT_GE(wrong.rejected(), wrong.tests() / 4) << wrong.summary();
    if (!family.passed()) test::write_diagnostic(m, "disk_light_" + estimator.name);
}

// ---- several lights at once: selection by power and MIS with delta lights among area lights.

TEST_P(DeltaLightIrradiance, PointSpotAndDiskLightsAddUp) {
    Scene s = lit_floor();
    add_disk_light(s);
    add_light(s, PointLight{Vec3f(kPointPosition), Color(kPointIntensity)});
    add_light(s, test_spot());
    Scene scene = with_estimator(s, GetParam(), 1024);
    test::RenderMoments m = test::render_moments(scene);
    EXPECT_EQ(m.dropped, 0u);
    auto sum = [](const Vec3d& p) {
        return disk_irradiance(p) + point_irradiance(p) + spot_irradiance(p, smoothstep_profile);
    };
    test::ExpectedImage e = test::expected_plane_image(scene, {0.0f, 1.0f, 0.2, 0.1, 1.2}, sum);
    PerspectiveCamera camera(scene.camera);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int corner = 0; corner < 4; ++corner) {
                Ray r = camera.generate_ray({float(x + corner % 2), float(y + corner / 2)});
                if (intersect_disk(scene.disks[0], Vec3d(r.o), Vec3d(r.d), 0.0, 1e30))
                    e.valid[size_t(y) * kSize + size_t(x)] = false;
            }
    test::ZTestFamily family = test::test_plane_image(m, e, kAlbedo, 1.0, kBlock);
    EXPECT_TRUE(family.passed()) << family.summary();
    test::ZTestFamily wrong = test::test_plane_image(m, e, kAlbedo, 1.05, kBlock);
    EXPECT_GE(wrong.rejected(), wrong.tests() / 4) << wrong.summary();
    if (!family.passed()) test::write_diagnostic(m, "three_lights_" + GetParam().name);
}

INSTANTIATE_TEST_SUITE_P(NeeEstimators, DeltaLightIrradiance,
                         ::testing::Values(EstimatorCase{"path", IntegratorType::kPath, true},
                                           EstimatorCase{"nee", IntegratorType::kPath, false},
                                           EstimatorCase{"whitted", IntegratorType::kWhitted, true}),
                         [](const auto& param_info) { return param_info.param.name; });

INSTANTIATE_TEST_SUITE_P(
    AllEstimators, DiskLightIrradiance,
    ::testing::Values(std::pair{EstimatorCase{"path", IntegratorType::kPath, true}, 1024},
                      std::pair{EstimatorCase{"nee", IntegratorType::kPath, false}, 1024},
                      std::pair{EstimatorCase{"bsdf", IntegratorType::kBsdf, true}, 4096},
                      std::pair{EstimatorCase{"whitted", IntegratorType::kWhitted, true}, 1024}),
    [](const auto& param_info) { return param_info.param.first.name; });

// ---- directional light: the cosine law, exactly (one light and no bounce: nothing is random
// but the position in the pixel, and E does not depend on it).

class DirectionalLightCosineLaw : public ::testing::TestWithParam<float> {};

TEST_P(DirectionalLightCosineLaw, FloorIsLitByIrradianceTimesCosine) {
    const float theta = radians(GetParam());  // from the floor's normal
    Scene s = lit_floor();
    const Vec3f direction(std::sin(theta), -std::cos(theta), 0.0f);  // travelling down and to +x
    add_light(s, DirectionalLight{direction, Color(2.0f)});
    // A sphere 60 units up the light's path casts a shadow of its own radius, 2: the shadow ray
    // must run to infinity to find it.
    const Vec3d shadow_centre(-0.3, 0.0, 0.6);
    test::add_sphere(s, shadow_centre - Vec3d(direction) * 60.0, 2.0, 0);
    for (const EstimatorCase& c : {EstimatorCase{"path", IntegratorType::kPath, true},
                                   EstimatorCase{"nee", IntegratorType::kPath, false},
                                   EstimatorCase{"whitted", IntegratorType::kWhitted, true}}) {
        Scene scene = with_estimator(s, c, 4);
        RenderResult r = render(scene, {.threads = 2});
        PerspectiveCamera camera(scene.camera);
        int lit = 0, shadowed = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                // Where the pixel's footprint lies on the floor, clearly in or out of the shadow's
                // cylinder of radius 2 along the light's direction.
                double nearest = 1e30, farthest = 0.0;
                bool floor = true;
                for (int corner = 0; corner < 4; ++corner) {
                    Ray ray = camera.generate_ray({float(x + corner % 2), float(y + corner / 2)});
                    floor = floor && ray.d.y < 0.0f;
                    Vec3d p = Vec3d(ray.o) + Vec3d(ray.d) * (-double(ray.o.y) / double(ray.d.y));
                    Vec3d off = p - shadow_centre;
                    double axis_distance = length(off - Vec3d(direction) * dot(off, Vec3d(direction)));
                    nearest = std::min(nearest, axis_distance);
                    farthest = std::max(farthest, axis_distance);
                }
                if (!floor) continue;
                const Rgb& pixel = r.image.at(x, y);
                if (nearest > 2.05) {
                    ++lit;
                    for (int ch = 0; ch < 3; ++ch)
                        EXPECT_NEAR(pixel[ch], kAlbedo[ch] * kInvPi * 2.0f * std::cos(theta),
                                    1e-5f * kAlbedo[ch] * 2.0f * kInvPi)
                            << c.name << " pixel " << x << ", " << y;
                } else if (farthest < 1.95) {
                    ++shadowed;
                    EXPECT_EQ(pixel, Rgb(0.0f)) << c.name << " pixel " << x << ", " << y;
                }
            }
        }
        EXPECT_GT(lit, 200) << c.name;
        EXPECT_GT(shadowed, 20) << c.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Angles, DirectionalLightCosineLaw, ::testing::Values(0.0f, 30.0f, 60.0f, 80.0f));

// ---- the Cornell box lit by its quad and by a point and a spot light: path tracing with MIS and
// next-event estimation alone agree over all bounces (the area light's MIS weights, computed
// with the delta lights taking part of the selection, are right).

TEST(DeltaLightAgreement, PathAndNeeAgreeInTheCornellBoxWithPointAndSpotLights) {
    Scene base = test::cornell_box_scene(kSize, kSize, 1);
    add_light(base, PointLight{{-0.4f, 0.5f, -0.2f}, Color(1.5f, 1.2f, 1.0f)});
    SpotLight spot;
    spot.position = {0.6f, 0.7f, -0.6f};
    spot.axis = normalize(Vec3f(-0.3f, -1.0f, 0.5f));
    spot.intensity = Color(3.0f);
    spot.cos_falloff_start = std::cos(radians(15.0f));
    spot.cos_falloff_end = std::cos(radians(30.0f));
    add_light(base, spot);
    Scene path = with_estimator(base, {"path", IntegratorType::kPath, true}, 2048);
    Scene nee = with_estimator(base, {"nee", IntegratorType::kPath, false}, 2048);
    nee.sampler.seed = base.sampler.seed + 1;
    test::RenderMoments a = test::render_moments(path), b = test::render_moments(nee);
    EXPECT_EQ(a.dropped + b.dropped, 0u);
    const double z = test::sidak_critical_z(test::kRenderTestAlpha, 3L * (kSize / kBlock) * (kSize / kBlock));
    test::ZTestFamily family(z);
    test::compare_renders(a, b, kBlock, family);
    EXPECT_TRUE(family.passed()) << family.summary();
    test::ZTestFamily control(z);
    test::compare_renders(a, b, kBlock, control, 1.05);
    EXPECT_GE(control.rejected(), test::lit_blocks(b, kBlock) / 4) << control.summary();
    if (!family.passed()) {
        test::write_diagnostic(a, "delta_cornell_path");
        test::write_diagnostic(b, "delta_cornell_nee");
    }
}

}  // namespace
}  // namespace candela
