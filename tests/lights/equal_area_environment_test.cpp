// The equal-area (octahedral) environment map: the square <-> sphere map of equal_area_mapping.h
// (round trips, the centre is +z and the corners -z, equal areas), lookups at known directions,
// continuity of bilinear lookups across the folded edges, the point filter, agreement of
// sample() with pdf() and radiance(), and environment_up_illuminance.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/lights/environment_light.h"
#include "candela/lights/equal_area_mapping.h"
#include "candela/sampling/rng.h"

namespace candela {
namespace CANDELA_UNITY_ID {

void expect_rgb_near(Rgb a, Rgb b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.r, b.r, tolerance);
    EXPECT_NEAR(a.g, b.g, tolerance);
    EXPECT_NEAR(a.b, b.b, tolerance);
}

// A square map whose every texel differs from every other, in all three channels.
Image distinct_map(int n) {
    Image img(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            img.at(x, y) = Rgb(1.0f + static_cast<float>(x), 1.0f + static_cast<float>(y * y),
                               1.0f + static_cast<float>((3 * x + 5 * y) % 7));
    return img;
}

EnvironmentLight equal_area(const Image& img, EnvironmentFilter filter = EnvironmentFilter::kBilinear,
                            const Transform& to_world = Transform()) {
    return EnvironmentLight(img, 1.0f, to_world, EnvironmentSampling::kImportance, EnvironmentMapping::kEqualArea,
                            filter);
}

TEST(EqualAreaMapping, RoundTripsSquareToSphereToSquare) {
    Rng rng(1, 0);
    for (int i = 0; i < 20000; ++i) {
        Vec2f p = rng.next_vec2f();
        Vec3f d = equal_area_square_to_sphere(p);
        EXPECT_NEAR(length(d), 1.0f, 2e-6f);
        Vec2f q = equal_area_sphere_to_square(d);
        // Off the folded edges the map is one to one.
        ASSERT_NEAR(q.x, p.x, 2e-6f) << p.x << " " << p.y;
        ASSERT_NEAR(q.y, p.y, 2e-6f) << p.x << " " << p.y;
    }
}

TEST(EqualAreaMapping, RoundTripsSphereToSquareToSphere) {
    Rng rng(2, 0);
    for (int i = 0; i < 20000; ++i) {
        Vec2f u = rng.next_vec2f();
        // Uniform on the sphere, written out here.
        float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
        Vec3f d(r * std::cos(phi), r * std::sin(phi), z);
        Vec3f e = equal_area_square_to_sphere(equal_area_sphere_to_square(d));
        ASSERT_NEAR(e.x, d.x, 3e-6f);
        ASSERT_NEAR(e.y, d.y, 3e-6f);
        ASSERT_NEAR(e.z, d.z, 3e-6f);
    }
}

TEST(EqualAreaMapping, CentreIsPlusZCornersAreMinusZAxesOnTheDiamond) {
    auto expect_dir = [](Vec2f p, Vec3f d) {
        Vec3f e = equal_area_square_to_sphere(p);
        EXPECT_NEAR(e.x, d.x, 1e-6f);
        EXPECT_NEAR(e.y, d.y, 1e-6f);
        EXPECT_NEAR(e.z, d.z, 1e-6f);
    };
    expect_dir({0.5f, 0.5f}, {0, 0, 1});
    for (Vec2f corner : {Vec2f(0, 0), Vec2f(1, 0), Vec2f(0, 1), Vec2f(1, 1)}) expect_dir(corner, {0, 0, -1});
    // The diamond's corners (the edge midpoints) are the horizon's axes, signs of (u', v').
    expect_dir({1.0f, 0.5f}, {1, 0, 0});
    expect_dir({0.0f, 0.5f}, {-1, 0, 0});
    expect_dir({0.5f, 1.0f}, {0, 1, 0});
    expect_dir({0.5f, 0.0f}, {0, -1, 0});
    Vec2f c = equal_area_sphere_to_square({0, 0, 1});
    EXPECT_EQ(c.x, 0.5f);
    EXPECT_EQ(c.y, 0.5f);
}

TEST(EqualAreaMapping, EqualAreasAreEqualSolidAngles) {
    // The fraction of a uniform grid over the square with z > 0.5 is the solid angle of that cap
    // over 4pi: 2pi (1 - 0.5) / 4pi = 1/4.
    constexpr int kN = 1000;
    int inside = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i)
            inside += equal_area_square_to_sphere({(i + 0.5f) / kN, (j + 0.5f) / kN}).z > 0.5f;
    EXPECT_NEAR(static_cast<double>(inside) / (kN * kN), 0.25, 2e-3);  // cells cut by the circle
}

TEST(EqualAreaEnvironment, CentreIsPlusZAndEveryCornerIsMinusZ) {
    Image img = distinct_map(4);
    EnvironmentLight env = equal_area(img);
    // +z sits between the four middle texels, -z between the four corner texels (the fold).
    expect_rgb_near(env.radiance({0, 0, 1}), (img.at(1, 1) + img.at(2, 1) + img.at(1, 2) + img.at(2, 2)) * 0.25f);
    expect_rgb_near(env.radiance({0, 0, -1}), (img.at(0, 0) + img.at(3, 0) + img.at(0, 3) + img.at(3, 3)) * 0.25f);
    // A point lookup sees the texel the point falls in.
    EnvironmentLight point = equal_area(img, EnvironmentFilter::kPoint);
    expect_rgb_near(point.radiance({0, 0, 1}), img.at(2, 2));
    expect_rgb_near(point.radiance(normalize(Vec3f(0.1f, 0.1f, 1.0f))), img.at(2, 2));
    expect_rgb_near(point.radiance(normalize(Vec3f(-0.1f, -0.1f, 1.0f))), img.at(1, 1));
    // +x is the middle of the right edge (u = 1, v = 0.5), -y the middle of the top edge.
    expect_rgb_near(point.radiance(normalize(Vec3f(1.0f, 0.01f, 0.01f))), img.at(3, 2));
    expect_rgb_near(point.radiance(normalize(Vec3f(0.01f, -1.0f, 0.01f))), img.at(2, 0));
}

TEST(EqualAreaEnvironment, TexelCentresReturnTheirTexels) {
    constexpr int kN = 8;
    Image img = distinct_map(kN);
    EnvironmentLight env = equal_area(img);
    for (int y = 0; y < kN; ++y)
        for (int x = 0; x < kN; ++x) {
            Vec3f d = equal_area_square_to_sphere({(x + 0.5f) / kN, (y + 0.5f) / kN});
            expect_rgb_near(env.radiance(d), img.at(x, y), 2e-3f);
        }
}

TEST(EqualAreaEnvironment, ToWorldTakesPbrtsLightFrameToTheWorld) {
    Image img = distinct_map(4);
    // A light frame whose +z is the world's +y (a rotation of -90 degrees about x).
    Transform to_world = Transform::rotate(Vec3d(1, 0, 0), -kPiD / 2.0);
    EnvironmentLight rotated = equal_area(img, EnvironmentFilter::kBilinear, to_world);
    EnvironmentLight plain = equal_area(img);
    expect_rgb_near(rotated.radiance({0, 1, 0}), plain.radiance({0, 0, 1}));
    Vec3f d = normalize(Vec3f(0.3f, -0.2f, 0.8f));
    expect_rgb_near(rotated.radiance(Vec3f(to_world.apply_vector(Vec3d(d)))), plain.radiance(d));
}

// The square's edges fold: (0, v) and (0, 1 - v) are one direction, and so on. Bilinear lookups
// just inside an edge at two points the fold joins agree, although the texels next to them are
// different, so the map is continuous on the sphere there.
TEST(EqualAreaEnvironment, BilinearLookupsAreContinuousAcrossTheFoldedEdges) {
    constexpr int kN = 8;
    Image img = distinct_map(kN);
    EnvironmentLight env = equal_area(img);
    constexpr float kIn = 1e-4f;  // from the edge, in units of the square
    // A texel step is 1/8; within kIn of the edge the field moves by at most
    // kIn * 8 * (largest texel difference, 50).
    constexpr float kTolerance = kIn * kN * 50.0f * 2.0f;
    for (float t : {0.05f, 0.2f, 0.33f, 0.45f}) {
        struct Pair { Vec2f a, b; };
        for (Pair p : {Pair{{kIn, t}, {kIn, 1 - t}}, Pair{{1 - kIn, t}, {1 - kIn, 1 - t}},
                       Pair{{t, kIn}, {1 - t, kIn}}, Pair{{t, 1 - kIn}, {1 - t, 1 - kIn}}}) {
            Vec3f da = equal_area_square_to_sphere(p.a), db = equal_area_square_to_sphere(p.b);
            EXPECT_LT(length(da - db), 1e-3f);  // the same place on the sphere
            Rgb a = env.radiance(da), b = env.radiance(db);
            expect_rgb_near(a, b, kTolerance);
        }
        // The texels on either side differ by far more than the tolerance: the test has teeth.
        EXPECT_GT(std::abs(img.at(0, static_cast<int>(t * kN)).g - img.at(0, static_cast<int>((1 - t) * kN)).g), 1.0f);
    }
    // Near a corner all four corners meet at -z.
    Rgb near_corner = env.radiance(equal_area_square_to_sphere({kIn, kIn}));
    for (Vec2f c : {Vec2f(1 - kIn, kIn), Vec2f(kIn, 1 - kIn), Vec2f(1 - kIn, 1 - kIn)})
        expect_rgb_near(env.radiance(equal_area_square_to_sphere(c)), near_corner, kTolerance);
}

TEST(EqualAreaEnvironment, SamplesAgreeExactlyWithPdfAndRadiance) {
    Image img = distinct_map(8);
    img.at(3, 5) = Rgb(0.0f);
    Transform to_world = Transform::rotate(Vec3d(1.0, 0.5, -0.3), 0.9);
    EnvironmentLight env = equal_area(img, EnvironmentFilter::kBilinear, to_world);
    Rng rng(5, 0);
    for (int i = 0; i < 2000; ++i) {
        auto s = env.sample(rng.next_vec2f());
        ASSERT_TRUE(s);
        EXPECT_EQ(s->pdf, env.pdf(s->wi));
        EXPECT_EQ(s->Le, env.radiance(s->wi));
        EXPECT_NEAR(length(s->wi), 1.0f, 1e-5f);
    }
    // pdf = texel luminance / mean luminance / 4pi: the map is equal-area.
    double mean = 0.0;
    for (const Rgb& p : img.pixels) mean += static_cast<double>(p.luminance());
    mean /= static_cast<double>(img.pixels.size());
    Vec3f centre_of_texel = equal_area_square_to_sphere({6.5f / 8.0f, 1.5f / 8.0f});
    Vec3f world(to_world.apply_vector(Vec3d(centre_of_texel)));
    EXPECT_NEAR(env.pdf(world), static_cast<double>(img.at(6, 1).luminance()) / mean / (4.0 * kPiD), 1e-5);
    Vec3f black = equal_area_square_to_sphere({3.5f / 8.0f, 5.5f / 8.0f});
    EXPECT_EQ(env.pdf(Vec3f(to_world.apply_vector(Vec3d(black)))), 0.0f);
}

TEST(EqualAreaEnvironment, ConstantMapHasPowerPiR2LAndUniformPdfWhereLuminanceIsEven) {
    Image img(4, 4);
    for (Rgb& p : img.pixels) p = Rgb(2.0f);
    EnvironmentLight env = equal_area(img);
    EXPECT_NEAR(env.power(3.0f), kPi * 9.0f * 2.0f, 1e-3f);
    EXPECT_NEAR(env.pdf(normalize(Vec3f(0.2f, -0.7f, 0.1f))), kInv4Pi, 1e-7f);
    expect_rgb_near(env.radiance(normalize(Vec3f(-0.4f, 0.1f, -0.9f))), Rgb(2.0f));
}

TEST(EnvironmentUpIlluminance, ConstantIsPiTimesLuminanceInBothMappings) {
    Image one(1, 1);
    one.at(0, 0) = Rgb(0.5f, 1.0f, 2.0f);
    const double expected = kPiD * static_cast<double>(Rgb(0.5f, 1.0f, 2.0f).luminance());
    for (auto mapping : {EnvironmentMapping::kEqualArea, EnvironmentMapping::kEquirectangular}) {
        EXPECT_DOUBLE_EQ(environment_up_illuminance(one, mapping, EnvironmentFilter::kBilinear), expected);
        // A larger constant map is integrated numerically: the midpoint rule's error only.
        Image big(mapping == EnvironmentMapping::kEqualArea ? 6 : 12, 6);
        for (Rgb& p : big.pixels) p = Rgb(0.5f, 1.0f, 2.0f);
        EXPECT_NEAR(environment_up_illuminance(big, mapping, EnvironmentFilter::kBilinear), expected, 1e-4 * expected);
    }
}

TEST(EnvironmentUpIlluminance, OnlyTheUpperHemisphereCounts) {
    // Equal-area: the inner diamond is z > 0. Light only in the corners gives nothing.
    Image corners(4, 4);
    for (int y : {0, 3})
        for (int x : {0, 3}) corners.at(x, y) = Rgb(10.0f);
    EXPECT_EQ(environment_up_illuminance(corners, EnvironmentMapping::kEqualArea, EnvironmentFilter::kPoint), 0.0);
    // Equirectangular: rows below the horizon (v > 0.5) are +y's lower hemisphere.
    Image below(8, 4);
    for (int x = 0; x < 8; ++x)
        for (int y : {2, 3}) below.at(x, y) = Rgb(10.0f);
    EXPECT_EQ(environment_up_illuminance(below, EnvironmentMapping::kEquirectangular, EnvironmentFilter::kPoint), 0.0);
    // The upper half alone of a constant map: pi L.
    Image above(8, 4);
    for (int x = 0; x < 8; ++x)
        for (int y : {0, 1}) above.at(x, y) = Rgb(1.0f);
    EXPECT_NEAR(environment_up_illuminance(above, EnvironmentMapping::kEquirectangular, EnvironmentFilter::kPoint),
                kPiD, 1e-4);
}

}  // namespace
}  // namespace candela
