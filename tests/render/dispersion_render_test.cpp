// Dispersion's weighting. At the first dispersive refraction a spectral path drops its three
// secondary wavelengths and the hero's value is counted four times (pbrt-v4's
// TerminateSecondary: the pdf of the one wavelength left is a quarter of the four's). Whether
// that is unbiased is seen where dispersion changes nothing else: a glass slab whose index is a
// spectrum of the same value at every wavelength refracts and reflects every wavelength alike,
// so flagged dispersive it must render the image of the same slab with a plain index (z-tests
// on the difference of independent renders). The control: the dispersive render counted once
// instead of four times (the image scaled by 1/4) must reject.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/materials/material.h"
#include "candela/spectrum/dense_spectrum.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 32;
constexpr int kBlock = 8;
constexpr int kSpp = 128;
constexpr float kIor = 1.5f;

// The Cornell walls (white light) with a closed glass slab standing turned before the back wall:
// the camera sees the walls through it, the light in it, and its caustic on the floor.
Scene slab_scene(bool dispersive) {
    Scene s = test::cornell_walls_scene(kSize, kSize, kSpp);
    DielectricParams glass{kIor, ColorParam{Rgb(1.0f)}, false};
    if (dispersive) glass.ior_spectrum = s.textures.add_spectrum(dense_constant(kIor));
    s.materials.push_back(make_material(glass));
    s.material_names.push_back("slab");
    const uint32_t slab = uint32_t(s.materials.size() - 1);
    const Vec3f center{0.0f, -0.45f, 0.1f}, half{0.55f, 0.55f, 0.2f};
    const float degrees = 30.0f;
    test::add_box(s, center, half, degrees, slab);
    // add_box leaves the bottom face out; the slab must be closed (faces outwards: -y).
    const float c = std::cos(radians(degrees)), sn = std::sin(radians(degrees));
    auto rotate = [&](Vec3f v) { return Vec3f(v.x * c + v.z * sn, v.y, -v.x * sn + v.z * c); };
    test::add_quad(s, center + rotate(Vec3f{-half.x, -half.y, -half.z}), rotate(Vec3f{2 * half.x, 0, 0}),
                   rotate(Vec3f{0, 0, 2 * half.z}), slab);
    for (Shape& shape : s.shapes)
        if (!shape.emission.is_black()) shape.emission = Rgb(4.0f);
    s.integrator.spectral = true;
    return s;
}

// z-tests of every block and the whole image: the plain slab's render minus the dispersive
// slab's scaled by `scale`, variances added (other seeds: independent renders).
test::ZTestFamily compare_slabs(double scale) {
    const test::RenderMoments plain = test::render_moments(slab_scene(false));
    Scene dispersive_scene = slab_scene(true);
    dispersive_scene.sampler.seed += 1000;
    const test::RenderMoments dispersive = test::render_moments(dispersive_scene);
    EXPECT_EQ(plain.dropped, 0u);
    EXPECT_EQ(dispersive.dropped, 0u);
    return test::compare_blocks_and_whole(plain, dispersive, kBlock, scale);
}

TEST(Dispersion, ConstantDispersiveIndexRendersAsPlainIndex) {
    test::ZTestFamily family = compare_slabs(1.0);
    EXPECT_TRUE(family.passed()) << family.summary();
}

// The control: the hero counted once instead of four times is seen at this sample count.
TEST(Dispersion, HeroWeightedOnceIsRejected) {
    test::ZTestFamily family = compare_slabs(0.25);
    EXPECT_FALSE(family.passed()) << family.summary();
}

}  // namespace
}  // namespace candela
