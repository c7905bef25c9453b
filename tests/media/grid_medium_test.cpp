// pbrt-v4's uniformgrid: coefficients scaled by the density grid, emission from a temperature grid
// or Le times the Le_scale grid, through the medium's transform.
#include "candela/media/grid_medium.h"

#include <gtest/gtest.h>

#include "candela/math/transform.h"
#include "candela/spectrum/blackbody.h"
#include "grid_media_fixtures.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::grey_spectrum;

const Transform kCtm = Transform::translate(Vec3d(1, 2, 3)) * Transform::rotate(Vec3d(0, 1, 1), 0.5) *
                       Transform::scale(Vec3d(2, 1, 0.5));

// A uniformgrid over p0..p1 = (0, 0, 0)..(2, 1, 1) under kCtm; nx * ny * nz densities.
GridMedium grid(int nx, int ny, int nz, std::vector<float> density) {
    GridMedium m;
    m.box.medium_from_world = affine_map_3f(kCtm.inverse());
    m.box.bounds = Bounds3f{Vec3f(0.0f), Vec3f(2.0f, 1.0f, 1.0f)};
    LatticeGrid d;
    d.nx = nx;
    d.ny = ny;
    d.nz = nz;
    d.values = std::move(density);
    m.density = cell_centred_field(std::move(d), m.box.bounds);
    m.sigma_a = grey_spectrum(0.5f);
    m.sigma_s = grey_spectrum(2.0f);
    return m;
}

// The world point at u in [0, 1]^3 of the box.
Vec3f world_at(const GridMedium& m, const Vec3f& u) {
    return Vec3f(kCtm.apply_point(Vec3d(m.box.bounds.lo + u * m.box.bounds.diagonal())));
}

TEST(GridMedium, CoefficientsAreScaledByTheDensityAtCellCentres) {
    GridMedium m = grid(3, 2, 1, {0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f});
    finish_grid_medium(m);
    EXPECT_FALSE(m.emissive);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) {
            const MediumPoint mp = m.at(world_at(m, Vec3f((x + 0.5f) / 3, (y + 0.5f) / 2, 0.5f)), MediumChannels{});
            const float d = float(y * 3 + x);
            EXPECT_NEAR(mp.sigma_a[0], 0.5f * d, 1e-4f);
            EXPECT_NEAR(mp.sigma_s[2], 2.0f * d, 1e-4f);
            EXPECT_TRUE(mp.Le.is_black());
        }
    // Between two centres along x: the mean.
    const MediumPoint mid = m.at(world_at(m, Vec3f(1.0f / 3, 0.25f, 0.5f)), MediumChannels{});
    EXPECT_NEAR(mid.sigma_a[0], 0.5f * 0.5f, 1e-4f);
}

// pbrt-v4's BlackbodySpectrum(kelvin) at nm, times kCieYIntegral (blackbody_emission.h).
double blackbody_reference(double nm, double kelvin) {
    return planck(nm, kelvin) / planck(kWienDisplacement / kelvin * 1e9, kelvin) * double(kCieYIntegral);
}

TEST(GridMedium, TemperatureGridEmitsTheBlackbodyOfTheOffsetAndScaledTemperature) {
    GridMedium m = grid(2, 1, 1, {1.0f, 1.0f});
    LatticeGrid t;
    t.nx = 2;
    t.ny = t.nz = 1;
    t.values = {1500.0f, 250.0f};
    m.temperature = cell_centred_field(std::move(t), m.box.bounds);
    m.temperature_offset = 200.0f;
    m.temperature_scale = 1.5f;
    m.Le_scale = make_le_scale_field(1.0f, m.box.bounds);
    finish_grid_medium(m);
    ASSERT_TRUE(m.emissive);
    // At the first voxel's centre, u = (1/4, 1/2, 1/2): T = (1500 - 200) 1.5 = 1950 K, and the
    // default Le_scale (one sample at the box's centre) is 3/4 there.
    const Vec3f p = world_at(m, Vec3f(0.25f, 0.5f, 0.5f));
    const Color lambda = Color::from_channels(450.0f, 550.0f, 650.0f, 750.0f);
    const MediumPoint mp = m.at(p, MediumChannels{&lambda});
    for (int c = 0; c < 4; ++c) {
        const double expected = 0.75 * blackbody_reference(double(lambda[c]), 1950.0);
        EXPECT_NEAR(mp.Le[c], expected, 2e-4 * expected) << lambda[c];
        // Control: 2% off in temperature is told apart.
        const double wrong = 0.75 * blackbody_reference(double(lambda[c]), 1950.0 * 1.02);
        EXPECT_GT(std::abs(double(mp.Le[c]) - wrong), 1e-2 * wrong);
    }
    const Rgb rgb = to_rgb(m.at(p, MediumChannels{}).Le);
    const Rgb exact = blackbody_rgb_exact(1950.0);
    EXPECT_NEAR(rgb.r, 0.75f * exact.r, 2e-3f * std::abs(exact.r));
    EXPECT_NEAR(rgb.g, 0.75f * exact.g, 2e-3f * std::abs(exact.r));
    // At the second voxel's centre T = (250 - 200) 1.5 = 75 K: below 100 K nothing is emitted.
    EXPECT_TRUE(m.at(world_at(m, Vec3f(0.75f, 0.5f, 0.5f)), MediumChannels{&lambda}).Le.is_black());
}

TEST(GridMedium, DefaultLeScaleFallsFromTheCentreToTheFacesAndCorners) {
    GridMedium m = grid(1, 1, 1, {1.0f});
    m.Le = grey_spectrum(2.0f);
    m.Le_scale = make_le_scale_field(1.0f, m.box.bounds);
    finish_grid_medium(m);
    ASSERT_TRUE(m.emissive);
    EXPECT_NEAR(m.at(world_at(m, Vec3f(0.5f)), MediumChannels{}).Le[0], 2.0f, 1e-5f);
    EXPECT_NEAR(m.at(world_at(m, Vec3f(0.0f, 0.5f, 0.5f)), MediumChannels{}).Le[0], 1.0f, 1e-5f);
    EXPECT_NEAR(m.at(world_at(m, Vec3f(1.0f, 1.0f, 0.0f)), MediumChannels{}).Le[1], 0.25f, 1e-5f);
}

TEST(GridMedium, LeScaleGridScalesLe) {
    GridMedium m = grid(2, 1, 1, {1.0f, 1.0f});
    m.Le = grey_spectrum(3.0f);
    LatticeGrid s;
    s.nx = 2;
    s.ny = s.nz = 1;
    s.values = {0.0f, 2.0f};
    m.Le_scale = cell_centred_field(std::move(s), m.box.bounds);
    finish_grid_medium(m);
    EXPECT_TRUE(m.at(world_at(m, Vec3f(0.25f, 0.5f, 0.5f)), MediumChannels{}).Le.is_black());
    EXPECT_NEAR(m.at(world_at(m, Vec3f(0.75f, 0.5f, 0.5f)), MediumChannels{}).Le[0], 6.0f, 1e-4f);
    EXPECT_NEAR(m.at(world_at(m, Vec3f(0.5f, 0.5f, 0.5f)), MediumChannels{}).Le[0], 3.0f, 1e-4f);
}

TEST(GridMedium, MajorantGridHoldsTheDensityBounds) {
    // One dense voxel in a 32^3 grid: only the majorant cells whose lookups can read it are
    // non-zero (pbrt-v4's MaxValue reads one sample beyond each cell's samples).
    std::vector<float> d(32 * 32 * 32, 0.0f);
    d[size_t((5 * 32 + 6) * 32 + 7)] = 4.0f;  // x = 7, y = 6, z = 5
    GridMedium m = grid(32, 32, 32, d);
    finish_grid_medium(m);
    int non_zero = 0;
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                if (m.majorant.at(x, y, z) != 0.0f) {
                    ++non_zero;
                    EXPECT_EQ(m.majorant.at(x, y, z), 4.0f);
                }
    EXPECT_EQ(m.majorant.at(3, 3, 2), 4.0f);  // the cell that holds the voxel's centre
    EXPECT_GE(non_zero, 1);
    EXPECT_LE(non_zero, 27);
}

}  // namespace
}  // namespace candela
