// The film's weighted filters and crop window in whole renders: a constant image stays constant
// under every filter (the film divides by the weight sum), a weighted render resumes bit for bit
// through a checkpoint, and a cropped render's pixels are the full render's, bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "candela/core/error.h"
#include "candela/render/job/checkpoint.h"
#include "candela/render/renderer.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Every filter: the named ones and pbrt-v4's parameterized and tabulated ones.
std::vector<FilterSettings> all_filters() {
    std::vector<FilterSettings> filters = {FilterType::kBox, FilterType::kTent, FilterType::kGaussian,
                                           FilterType::kSmallpt};
    for (FilterType t : {FilterType::kBox, FilterType::kTent, FilterType::kOffsetGaussian, FilterType::kMitchell,
                         FilterType::kLanczos})
        filters.push_back(test::filter_of(t));
    filters.back().radius = {4.0f, 1.5f};  // and an anisotropic one
    return filters;
}

TEST(FilmFilterRender, ConstantImageStaysConstantUnderEveryFilter) {
    // An emitter filling the view (and every filter's reach past the image's edges): every sample
    // is the emission, so every pixel must be too, whatever the weights.
    Scene s;
    s.materials = {make_diffuse(Rgb(0.0f))};
    s.material_names = {"black"};
    const uint32_t wall = test::add_quad(s, {-50, -50, 1}, {100, 0, 0}, {0, 100, 0});
    test::set_emission(s, wall, Rgb(0.75f, 0.3f, 1.7f), true);
    test::set_camera(s, {0, 0, -1}, {0, 0, 0}, 60, 12, 9);
    s.sampler.spp = 8;
    for (const FilterSettings& f : all_filters()) {
        s.film.filter = f;
        const RenderResult r = render(s, {.threads = 2});
        for (size_t i = 0; i < r.image.pixels.size(); ++i) {
            const Rgb& p = r.image.pixels[i];
            // With negative lobes a few samples' weights may cancel exactly (+-I each): such a
            // pixel is 0, as in pbrt-v4, whatever the radiance.
            if (r.state.film.weighted() && r.state.film.weights()[i] == 0.0) {
                EXPECT_EQ(p, Rgb(0.0f));
                continue;
            }
            EXPECT_NEAR(p.r, 0.75f, 1e-5f) << int(f.type);
            EXPECT_NEAR(p.g, 0.3f, 1e-5f) << int(f.type);
            EXPECT_NEAR(p.b, 1.7f, 1e-5f) << int(f.type);
        }
    }
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

TEST(FilmFilterRender, WeightedFiltersChangeTheImage) {
    Scene s = test::lit_small_box_scene(16, 12, 4);
    const Image box = render(s, {.threads = 2}).image;
    for (FilterType t : {FilterType::kOffsetGaussian, FilterType::kMitchell, FilterType::kLanczos}) {
        s.film.filter = test::filter_of(t);
        EXPECT_FALSE(same_bits(render(s, {.threads = 2}).image, box)) << int(t);
    }
}

TEST(FilmFilterRender, WeightedRenderResumesThroughACheckpointBitForBit) {
    Scene s = test::lit_small_box_scene(19, 11, 8);
    s.film.filter = test::filter_of(FilterType::kMitchell);
    const RenderResult reference = render(s, {.threads = 3});
    ASSERT_TRUE(reference.state.film.weighted());
    int passes = 0;
    RenderOptions stop_early{.threads = 2};
    stop_early.pass_spp = 3;
    stop_early.on_pass = [&passes](const RenderState&) { ++passes; };
    stop_early.stop = [&passes] { return passes >= 1; };
    RenderResult part = render(s, stop_early);
    ASSERT_EQ(part.state.samples_done, 3u);
    const std::filesystem::path file = std::filesystem::path(CANDELA_TEST_BINARY_DIR) / "weighted_resume.ckpt";
    write_checkpoint(file, render_identity(s, 1), part.state);
    Checkpoint c = read_checkpoint(file);
    ASSERT_TRUE(c.state.film.weighted());
    EXPECT_EQ(c.state.film.weights(), part.state.film.weights());
    const RenderResult rest = render(s, {.threads = 1}, std::move(c.state));
    EXPECT_EQ(rest.state.film.weights(), reference.state.film.weights());
    EXPECT_TRUE(same_bits(rest.image, reference.image));
    // A film without weight sums cannot continue a weighted render.
    EXPECT_THROW(render(s, {}, RenderState{Film(19, 11)}), RenderError);
}

TEST(FilmFilterRender, CroppedPixelsAreTheFullRendersBitForBit) {
    for (SamplerType sampler : {SamplerType::kIndependent, SamplerType::kSobol}) {
        for (const FilterSettings& f : {FilterSettings(FilterType::kTent), test::filter_of(FilterType::kLanczos)}) {
            Scene s = test::lit_small_box_scene(37, 23, 4);
            s.sampler.type = sampler;
            s.film.filter = f;
            const Image full = render(s, {.threads = 2}).image;
            s.film.crop_window = {0.2f, 0.7f, 0.3f, 0.9f};
            const PixelBounds b = render_pixel_bounds(s);
            // pbrt-v4's rounding: ceil(37 * 0.2) = 8 .. ceil(37 * 0.7) = 26, ceil(23 * 0.3) = 7 ..
            // ceil(23 * 0.9) = 21.
            EXPECT_EQ(b.x0, 8);
            EXPECT_EQ(b.x1, 26);
            EXPECT_EQ(b.y0, 7);
            EXPECT_EQ(b.y1, 21);
            const Image crop = render(s, {.threads = 2}).image;
            ASSERT_EQ(crop.width, b.width());
            ASSERT_EQ(crop.height, b.height());
            for (int y = 0; y < crop.height; ++y)
                for (int x = 0; x < crop.width; ++x) {
                    const Rgb a = crop.pixels[size_t(y * crop.width + x)];
                    const Rgb e = full.pixels[size_t((y + b.y0) * full.width + x + b.x0)];
                    ASSERT_EQ(std::memcmp(&a, &e, sizeof(Rgb)), 0) << x << ", " << y;
                }
        }
    }
}

}  // namespace
}  // namespace candela
