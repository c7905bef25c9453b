// pbrt-v4's rgbgrid: per-voxel RGB coefficients (RGBUnboundedSpectrum in spectral mode) and
// emission (RGBIlluminantSpectrum), the same medium in both colour modes.
#include "candela/media/rgb_grid_medium.h"

#include <gtest/gtest.h>

#include <vector>

#include "candela/math/transform.h"
#include "candela/spectrum/dense_spectrum.h"
#include "grid_media_fixtures.h"

namespace candela {
namespace CANDELA_UNITY_ID {

const Transform kCtm = Transform::translate(Vec3d(-1, 0, 2)) * Transform::scale(Vec3d(1.5, 2, 1));

std::vector<Rgb> random_rgbs(int n, Rng& rng, bool grey) {
    std::vector<Rgb> v;
    for (int i = 0; i < n; ++i) {
        const float a = 3 * rng.next_float();
        v.push_back(grey ? Rgb(a) : Rgb(a, 3 * rng.next_float(), 3 * rng.next_float()));
    }
    return v;
}

RgbGridMedium rgb_grid(bool grey, bool with_le, uint64_t seed) {
    Rng rng(seed, 1);
    RgbGridMedium m;
    m.box.medium_from_world = affine_map_3f(kCtm.inverse());
    m.box.bounds = Bounds3f{Vec3f(0.0f), Vec3f(1.0f, 2.0f, 1.0f)};
    const int nx = 4, ny = 3, nz = 5;
    m.sigma_a = make_rgb_lattice(nx, ny, nz, random_rgbs(nx * ny * nz, rng, grey), false);
    m.sigma_s = make_rgb_lattice(nx, ny, nz, random_rgbs(nx * ny * nz, rng, grey), false);
    if (with_le) m.Le = make_rgb_lattice(nx, ny, nz, random_rgbs(nx * ny * nz, rng, grey), true);
    m.scale = 1.7f;
    m.Le_scale = 0.3f;
    finish_rgb_grid_medium(m);
    return m;
}

Vec3f world_at(const RgbGridMedium& m, const Vec3f& u) {
    return Vec3f(kCtm.apply_point(Vec3d(m.box.bounds.lo + u * m.box.bounds.diagonal())));
}

TEST(RgbGridMedium, GreyVoxelsAreTheSameInBothModes) {
    const RgbGridMedium m = rgb_grid(true, true, 71);
    ASSERT_TRUE(m.emissive);
    Rng rng(72, 73);
    for (int i = 0; i < 500; ++i) {
        const Vec3f p = world_at(m, test::random_in(rng, -0.1f, 1.1f));
        const Color lambda = Color::from_channels(380 + 440 * rng.next_float(), 380 + 440 * rng.next_float(),
                                                  380 + 440 * rng.next_float(), 380 + 440 * rng.next_float());
        const MediumPoint s = m.at(p, MediumChannels{&lambda}), r = m.at(p, MediumChannels{});
        for (int c = 0; c < 4; ++c) {
            // A grey's uplift is a constant spectrum; an illuminant's is that times D65 (Y = 1).
            EXPECT_NEAR(s.sigma_a[c], r.sigma_a[0], 1e-4f * (1 + r.sigma_a[0]));
            EXPECT_NEAR(s.sigma_s[c], r.sigma_s[0], 1e-4f * (1 + r.sigma_s[0]));
            const float d65 = d65_illuminant()(lambda[c]);
            EXPECT_NEAR(s.Le[c], r.Le[0] * d65, 1e-4f * (1 + r.Le[0] * d65));
        }
    }
}

TEST(RgbGridMedium, CoefficientsAreTheScaledVoxelsAndLeIsPbrtV4sRadiance) {
    const RgbGridMedium m = rgb_grid(false, true, 74);
    // The centre of voxel (1, 2, 3) of 4 x 3 x 5.
    const Vec3f u(1.5f / 4, 2.5f / 3, 3.5f / 5);
    const size_t i = size_t((3 * 3 + 2) * 4 + 1);
    const MediumPoint mp = m.at(world_at(m, u), MediumChannels{});
    const Rgb a = m.sigma_a.rgb.values[i], le = m.Le.rgb.values[i];
    EXPECT_NEAR(mp.sigma_a[0], 1.7f * a.r, 1e-4f);
    EXPECT_NEAR(mp.sigma_a[1], 1.7f * a.g, 1e-4f);
    EXPECT_NEAR(mp.sigma_a[2], 1.7f * a.b, 1e-4f);
    // Not normalized, as pbrt-v4's; in candela's units (blackbody_emission.h) times kCieYIntegral.
    EXPECT_NEAR(mp.Le[1], 0.3f * kCieYIntegral * le.g, 1e-3f * kCieYIntegral);
}

TEST(RgbGridMedium, MissingCoefficientGridsAreOne) {
    RgbGridMedium m = rgb_grid(false, false, 75);
    m.sigma_s = RgbLattice{};
    finish_rgb_grid_medium(m);
    EXPECT_FALSE(m.emissive);
    const MediumPoint mp = m.at(world_at(m, Vec3f(0.3f, 0.6f, 0.2f)), MediumChannels{});
    EXPECT_EQ(mp.sigma_s[0], 1.7f);
    EXPECT_TRUE(mp.Le.is_black());
}

// Points of random rays' segments where sigma_t exceeds the segment's majorant times `factor`.
int count_unbounded(const RgbGridMedium& m, float factor, bool spectral) {
    Rng rng(76, 77);
    const Color lambda = Color::from_channels(400.0f, 480.0f, 560.0f, 690.0f);
    const MediumChannels ch = spectral ? MediumChannels{&lambda} : MediumChannels{};
    int bad = 0;
    for (int k = 0; k < 2000; ++k) {
        const Ray ray = test::random_ray_at(m.box, kCtm, rng);
        auto it = m.majorants(ray, kInfinity, ch);
        while (auto s = it.next())
            for (int j = 0; j < 16; ++j) {
                const float t = lerp(rng.next_float(), s->t0, s->t1);
                const MediumPoint mp = m.at(ray.at(t), ch);
                const Color sigma_t = mp.sigma_a + mp.sigma_s;
                for (int c = 0; c < (spectral ? 4 : 3); ++c) bad += sigma_t[c] > factor * s->sigma_maj[c] * (1 + 1e-5f) + 1e-6f;
            }
    }
    return bad;
}

TEST(RgbGridMedium, MajorantsBoundSigmaTInBothModes) {
    const RgbGridMedium m = rgb_grid(false, false, 78);
    EXPECT_EQ(count_unbounded(m, 1.0f, false), 0);
    EXPECT_EQ(count_unbounded(m, 1.0f, true), 0);
    // Control: a majorant 10% low is exceeded (in spectral mode with grey voxels, whose spectra's
    // maxima are their values: a coloured voxel's maximum over 360-830 nm leaves a margin at the
    // path's four wavelengths).
    EXPECT_GT(count_unbounded(m, 0.9f, false), 10);
    EXPECT_GT(count_unbounded(rgb_grid(true, false, 79), 0.9f, true), 10);
}

}  // namespace
}  // namespace candela
