// The cloud medium reproduces pbrt-v4's: its Perlin noise (math/perlin_noise.h) and its density
// are pbrt-v4's functions, compared with values pbrt-v4's own code computes.
#include "candela/media/cloud_medium.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

#include "candela/math/perlin_noise.h"
#include "candela/math/transform.h"
#include "grid_media_fixtures.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Reference values from pbrt-v4's code (mmp/pbrt-v4 src/pbrt/util/noise.cpp: Noise, DNoise, the
// permutation table; src/pbrt/media.h: CloudMedium::Density), compiled outside this repository
// with a few lines standing in for pbrt-v4's Point3f, Lerp, Pow and Clamp:
//   extract noise.cpp's "Perlin Noise Data" .. DNoise and CloudMedium::Density into ref.cpp, then
//   g++ -O2 -std=c++17 -o ref ref.cpp && ./ref    (g++ 12.2, x86-64)
// Each row: x, y, z, Noise(p), DNoise(p).
constexpr float kNoise[][7] = {
    {0.5f, 0.25f, 0.75f, -0.375078678f, -0.818300247f, 0.777059793f, -0.387498736f},
    {1.29999995f, -2.70000005f, 4.0999999f, 0.168821469f, -0.642475486f, -0.146462023f, 0.492145121f},
    {10.1230001f, 20.5f, -30.25f, 0.11518839f, -0.0734254718f, -0.825378299f, 0.074736774f},
    {-0.100000001f, 0.899999976f, 0.330000013f, -0.0418499261f, 0.863347948f, 0.895006955f, 0.90566802f},
    {255.5f, 256.25f, 1000.0f, 0.146484375f, -0.0335723162f, -1.8558085f, -0.102995336f},
    {3.0f, 4.0f, 5.0f, 0.0f, 0.0f, 1.00098836f, 1.00098836f},
};
// Each row: x, y, z, Density(p) with density 1, wispiness 1, frequency 5 (pbrt-v4's defaults),
// and with density 1.5, wispiness 0, frequency 3.
constexpr float kDensity[][5] = {
    {0.5f, 0.5f, 0.5f, 0.0880670473f, 0.0f},
    {0.200000003f, 0.699999988f, 0.400000006f, 0.365069151f, 0.389663488f},
    {0.899999976f, 0.550000012f, 0.100000001f, 0.0523063168f, 0.0f},
    {0.300000012f, 0.300000012f, 0.800000012f, 0.778037071f, 0.399999976f},
    {0.600000024f, 0.949999988f, 0.600000024f, 0.0179677662f, 0.0f},
    {0.449999988f, 0.620000005f, 0.270000011f, 0.0f, 0.0f},
};

TEST(PerlinNoise, MatchesPbrtV4) {
    for (const auto& r : kNoise) {
        const Vec3f p(r[0], r[1], r[2]);
        EXPECT_NEAR(perlin_noise(p), r[3], 1e-6f) << p.x << " " << p.y << " " << p.z;
        const Vec3f g = perlin_noise_gradient(p);
        // A difference quotient over 0.01 magnifies the noise's last-bit rounding by 100.
        EXPECT_NEAR(g.x, r[4], 2e-4f);
        EXPECT_NEAR(g.y, r[5], 2e-4f);
        EXPECT_NEAR(g.z, r[6], 2e-4f);
    }
}

TEST(PerlinNoise, ControlAnotherPermutationDiffers) {
    // The check above can tell tables apart: noise at the first point with the lattice shifted by
    // one (a different hash of the same cell) is not the reference value.
    EXPECT_GT(std::abs(perlin_noise(Vec3f(1.5f, 0.25f, 0.75f)) - kNoise[0][3]), 1e-3f);
}

TEST(PerlinNoise, ZeroOnTheLatticeAndBounded) {
    Rng rng(51, 52);
    for (int i = 0; i < 1000; ++i) {
        const Vec3f lattice(std::floor(200 * rng.next_float() - 100), std::floor(200 * rng.next_float() - 100),
                            std::floor(200 * rng.next_float() - 100));
        EXPECT_EQ(perlin_noise(lattice), 0.0f);
        const float n = perlin_noise(test::random_in(rng, -50.0f, 50.0f));
        EXPECT_LE(std::abs(n), 1.1f);
    }
}

// pbrt-v4's Noise written plainly, as noise.cpp has it: fmod on every coordinate, each corner's hash
// from the full three lookups, the gradient picked by branches. perlin_noise (shared hashes,
// branch-free gradients, fmod only where it changes something) must give its bits exactly.
float plain_noise(const Vec3f& p) {
    auto perm = [](int i) { return kPerlinPermutation[i & 255]; };
    auto grad = [&](int x, int y, int z, float dx, float dy, float dz) {
        const int h = perm(perm(perm(x) + y) + z) & 15;
        const float u = h < 8 || h == 12 || h == 13 ? dx : dy;
        const float v = h < 4 || h == 12 || h == 13 ? dy : dz;
        return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
    };
    // pbrt-v4's Pow<5>, Pow<4> and Pow<3>: (t t)(t t) t, (t t)(t t), (t t) t.
    auto fade = [](float t) { return 6 * ((t * t) * (t * t) * t) - 15 * ((t * t) * (t * t)) + 10 * ((t * t) * t); };
    constexpr float kWrap = float(1 << 30);
    const float x = std::fmod(p.x, kWrap), y = std::fmod(p.y, kWrap), z = std::fmod(p.z, kWrap);
    const int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
    const float dx = x - float(ix), dy = y - float(iy), dz = z - float(iz);
    const int X = ix & 255, Y = iy & 255, Z = iz & 255;
    const float wx = fade(dx), wy = fade(dy), wz = fade(dz);
    const float x00 = lerp(wx, grad(X, Y, Z, dx, dy, dz), grad(X + 1, Y, Z, dx - 1, dy, dz));
    const float x10 = lerp(wx, grad(X, Y + 1, Z, dx, dy - 1, dz), grad(X + 1, Y + 1, Z, dx - 1, dy - 1, dz));
    const float x01 = lerp(wx, grad(X, Y, Z + 1, dx, dy, dz - 1), grad(X + 1, Y, Z + 1, dx - 1, dy, dz - 1));
    const float x11 =
        lerp(wx, grad(X, Y + 1, Z + 1, dx, dy - 1, dz - 1), grad(X + 1, Y + 1, Z + 1, dx - 1, dy - 1, dz - 1));
    return lerp(wz, lerp(wy, x00, x10), lerp(wy, x01, x11));
}

uint32_t bits(float f) { return std::bit_cast<uint32_t>(f); }

TEST(PerlinNoise, FastFormGivesThePlainFormsBits) {
    Rng rng(61, 62);
    int differ = 0;
    for (int i = 0; i < 200000; ++i) {
        // Cells near the origin, across the period of 256, beyond 2^30 (where fmod acts), and
        // points on and just below lattice planes (where the gradient's lookups change cell).
        const float scale = i % 4 == 0 ? 2.0f : i % 4 == 1 ? 300.0f : i % 4 == 2 ? 3e9f : 20.0f;
        Vec3f p = test::random_in(rng, -scale, scale);
        if (i % 7 == 0) p.x = std::floor(p.x) - (i % 3 == 0 ? 0.005f : 0.0f);
        if (i % 11 == 0) p.y = -0.0f;
        const float delta = 0.01f;
        const Vec3f plain_gradient = (Vec3f(plain_noise(p + Vec3f(delta, 0, 0)), plain_noise(p + Vec3f(0, delta, 0)),
                                            plain_noise(p + Vec3f(0, 0, delta))) -
                                      Vec3f(plain_noise(p))) /
                                     delta;
        const Vec3f g = perlin_noise_gradient(p);
        differ += bits(perlin_noise(p)) != bits(plain_noise(p)) || bits(g.x) != bits(plain_gradient.x) ||
                  bits(g.y) != bits(plain_gradient.y) || bits(g.z) != bits(plain_gradient.z);
    }
    EXPECT_EQ(differ, 0);
    // Control: the plain form at another point differs (the comparison can see a difference).
    EXPECT_NE(bits(plain_noise(Vec3f(0.5f, 0.25f, 0.75f))), bits(perlin_noise(Vec3f(0.5f, 0.25f, 0.7501f))));
}

CloudMedium cloud(float density, float wispiness, float frequency) {
    CloudMedium c;
    c.density = density;
    c.wispiness = wispiness;
    c.frequency = frequency;
    c.sigma_a = test::grey_spectrum(2.0f);
    c.sigma_s = test::grey_spectrum(3.0f);
    return c;
}

TEST(CloudMedium, DensityMatchesPbrtV4) {
    const CloudMedium a = cloud(1.0f, 1.0f, 5.0f), b = cloud(1.5f, 0.0f, 3.0f);
    for (const auto& r : kDensity) {
        const Vec3f p(r[0], r[1], r[2]);
        EXPECT_NEAR(a.density_at(p), r[3], 2e-6f) << p.x << " " << p.y << " " << p.z;
        EXPECT_NEAR(b.density_at(p), r[4], 2e-6f) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(CloudMedium, CoefficientsScaleWithDensityThroughTheTransform) {
    CloudMedium c = cloud(1.0f, 1.0f, 5.0f);
    const Transform ctm = Transform::translate(Vec3d(4, 0, -1)) * Transform::scale(Vec3d(2.0));
    c.box.medium_from_world = affine_map_3f(ctm.inverse());
    const Vec3f p_medium(0.2f, 0.7f, 0.4f);
    const MediumPoint mp = c.at(Vec3f(ctm.apply_point(Vec3d(p_medium))), MediumChannels{});
    const float d = c.density_at(p_medium);
    EXPECT_NEAR(mp.sigma_a[0], 2.0f * d, 1e-5f);
    EXPECT_NEAR(mp.sigma_s[1], 3.0f * d, 1e-5f);
    EXPECT_TRUE(mp.Le.is_black());
    EXPECT_FALSE(c.emissive);
}

TEST(CloudMedium, MajorantIsSigmaTOverTheBox) {
    // pbrt-v4's: one segment, the ray inside the box (here [0, 2]^3 + (4, 0, -1) in the world),
    // sigma_a + sigma_s, which bounds the density (at most 1) times the coefficients.
    CloudMedium c = cloud(1.0f, 1.0f, 5.0f);
    const Transform ctm = Transform::translate(Vec3d(4, 0, -1)) * Transform::scale(Vec3d(2.0));
    c.box.medium_from_world = affine_map_3f(ctm.inverse());
    Ray ray;
    ray.o = Vec3f(0.0f, 1.0f, 0.0f);
    ray.d = Vec3f(1.0f, 0.0f, 0.0f);
    auto it = c.majorants(ray, kInfinity, MediumChannels{});
    const std::optional<MajorantSegment> s = it.next();
    ASSERT_TRUE(s.has_value());
    EXPECT_NEAR(s->t0, 4.0f, 1e-5f);
    EXPECT_NEAR(s->t1, 6.0f, 1e-5f);
    EXPECT_EQ(s->sigma_maj[0], 5.0f);
    EXPECT_FALSE(it.next().has_value());
    Rng rng(53, 54);
    for (int i = 0; i < 2000; ++i) {
        const float d = c.density_at(test::random_in(rng, 0.0f, 1.0f));
        EXPECT_GE(d, 0.0f);
        EXPECT_LE(d, 1.0f);
    }
    ray.o.y = 5.0f;  // above the box
    EXPECT_FALSE(c.majorants(ray, kInfinity, MediumChannels{}).next().has_value());
}

}  // namespace
}  // namespace candela
