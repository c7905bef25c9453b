// The renderer's guard against bad samples: a camera sample whose value is NaN or infinite in any
// channel is dropped whole (counted in RenderStats::dropped_samples, added to no pixel), so one
// overflow cannot poison a pixel, and the pixel's mean counts it as zero.
//
// The scene overflows on purpose, deterministically: the left half of the view is a black diffuse
// emitter of radiance (2e38, 1, 1), the right half a mirror emitting the same, facing a wall behind
// the camera that emits it too. A sample on the left carries exactly the emitter's radiance, a
// finite float; a sample on the right adds the mirror's emission to the wall's reflected in it, and
// 2e38 + 2e38 overflows the float range in red (green stays a finite 2). The renderer cannot take
// a custom integrator (make_integrator builds it from the scene), so overflow is how a test makes
// an integrator return a non-finite value.
#include <gtest/gtest.h>

#include <string>

#include "candela/render/renderer.h"
#include "candela/scene/enum_names.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kWidth = 16, kHeight = 8, kSpp = 16;
const Rgb kEmission(2e38f, 1.0f, 1.0f);

Scene overflow_scene(IntegratorType type) {
    Scene s;
    s.materials = {make_diffuse(Rgb(0.0f)), make_mirror(Rgb(1.0f))};
    s.material_names = {"black", "mirror"};
    // Both on the plane z = 0 facing the camera (-z), meeting at x = 0, the image's middle column.
    // The camera looks along +z with y up, so image right is world -x.
    uint32_t left = test::add_quad(s, {0, -10, 0}, {0, 20, 0}, {10, 0, 0}, 0);
    uint32_t right = test::add_quad(s, {-10, -10, 0}, {0, 20, 0}, {10, 0, 0}, 1);
    uint32_t wall = test::add_quad(s, {-10, -10, -2}, {20, 0, 0}, {0, 20, 0}, 0);  // z = -2, faces +z
    for (uint32_t shape : {left, right, wall}) test::set_emission(s, shape, kEmission);
    // The emitters' power overflows too; uniform selection does not need it.
    s.integrator.light_selection = LightSelection::kUniform;
    s.integrator.type = type;
    test::set_camera(s, Vec3f{0, 0, -1}, Vec3f{0, 0, 0}, 40, kWidth, kHeight);
    s.sampler.spp = kSpp;
    return s;
}

class NonFiniteSamples : public ::testing::TestWithParam<IntegratorType> {};

TEST_P(NonFiniteSamples, AreDroppedAndCountedNeverWritten) {
    RenderResult r = render(overflow_scene(GetParam()), {.threads = 2});
    // Every sample of the right half overflows (a sample lands in its own pixel with the box filter).
    EXPECT_EQ(r.stats.dropped_samples, uint64_t(kWidth / 2) * kHeight * kSpp);
    EXPECT_EQ(r.stats.samples, uint64_t(kWidth) * kHeight * kSpp);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const Rgb& p = r.image.at(x, y);
            ASSERT_TRUE(p.is_finite()) << "pixel " << x << ", " << y;
            if (x < kWidth / 2) {
                // Huge but finite samples are kept as they are.
                EXPECT_EQ(p, kEmission) << "pixel " << x << ", " << y;
            } else {
                // Dropped whole: the finite green and blue of the overflowing samples are gone too.
                EXPECT_EQ(p, Rgb(0.0f)) << "pixel " << x << ", " << y;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AllTransportIntegrators, NonFiniteSamples,
                         ::testing::Values(IntegratorType::kPath, IntegratorType::kBsdf, IntegratorType::kWhitted),
                         [](const auto& param_info) { return std::string(integrator_type_name(param_info.param)); });

}  // namespace
}  // namespace candela
