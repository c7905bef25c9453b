// Adaptive sampling and the noise target (render/adaptive_sampling.h, RenderOptions.target_error):
// the image is a function of scene and settings only (threads, tiles, passes, stop and resume
// change no bit), an adaptive render converges to the uniform render's image, and --target-error
// stops where its estimate says, with the true relMSE within 2x of that estimate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "bench/image_compare.h"
#include "candela/core/error.h"
#include "candela/film/pixel_statistics.h"
#include "candela/render/adaptive_sampling.h"
#include "candela/render/pass_engine.h"
#include "candela/render/renderer.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Every value of both films (sums, squares, counts) has the same bits.
bool same_bits(const Film& a, const Film& b) {
    if (a.width() != b.width() || a.height() != b.height() || a.values_per_pixel() != b.values_per_pixel())
        return false;
    const PixelBounds all{0, 0, a.width(), a.height()};
    std::vector<double> va(size_t(a.width()) * size_t(a.height()) * size_t(a.values_per_pixel())), vb(va.size());
    a.read_region(all, va.data());
    b.read_region(all, vb.data());
    return std::memcmp(va.data(), vb.data(), va.size() * sizeof(double)) == 0;
}

// A lit box whose width and height are not multiples of the block size; adaptive with a threshold
// that stops some blocks early and not others.
Scene adaptive_scene(SamplerType sampler) {
    Scene s = test::lit_small_box_scene(37, 23, 96);
    s.sampler.type = sampler;
    s.sampler.adaptive = AdaptiveSettings{0.08f, 8};
    return s;
}

class AdaptiveDeterminism : public ::testing::TestWithParam<SamplerType> {};

TEST_P(AdaptiveDeterminism, SameBitsForThreadsTilesPassesAndResume) {
    const Scene scene = adaptive_scene(GetParam());
    const RenderResult reference = render(scene, {.threads = 2});
    const SppSummary spp = spp_summary(reference.state.film);
    // The threshold stops some blocks, not all: the test covers both kinds.
    ASSERT_GE(spp.min, 8.0);
    ASSERT_LT(spp.min, 96.0);
    ASSERT_EQ(spp.max, 96.0);

    for (int threads : {1, 3})
        for (int tile_size : {5, 16, 24})
            for (uint32_t pass_spp : {0u, 1u, 7u}) {
                SCOPED_TRACE(::testing::Message() << threads << " threads, tiles " << tile_size << ", passes " << pass_spp);
                const RenderResult r =
                    render(scene, {.threads = threads, .tile_size = tile_size, .pass_spp = pass_spp});
                EXPECT_TRUE(same_bits(r.state.film, reference.state.film));
            }

    // Stopped after 2, 5 and 11 passes of 3 samples, resumed with other threads and passes.
    for (int k : {2, 5, 11}) {
        SCOPED_TRACE(::testing::Message() << "stopped after " << k << " passes");
        int passes = 0;
        RenderOptions first{.threads = 1, .pass_spp = 3};
        first.on_pass = [&passes](const RenderState&) { ++passes; };
        first.stop = [&passes, k] { return passes >= k; };
        RenderResult stopped = render(scene, first);
        ASSERT_EQ(stopped.end, RenderEnd::kStopped);
        const RenderResult resumed = render(scene, {.threads = 3, .pass_spp = 5}, std::move(stopped.state));
        EXPECT_TRUE(same_bits(resumed.state.film, reference.state.film));
    }
}

// Shards (and MPI ranks) render only their tiles: a block's decisions read only its own pixels,
// so the parts, each rendered from an empty film and put together, are the whole render.
TEST_P(AdaptiveDeterminism, ShardsPutTogetherAreTheWholeRender) {
    const Scene scene = adaptive_scene(GetParam());
    const RenderResult whole = render(scene, {.threads = 2});
    Film merged(whole.state.film.width(), whole.state.film.height(), false, {}, true);
    for (int part = 1; part <= 3; ++part) {
        const RenderOptions options{.threads = 2, .shard = Shard{part, 3}};
        const RenderResult r = render(scene, options);
        for (const Tile& tile : render_tiles(merged.width(), merged.height(), options, true)) {
            std::vector<double> values(size_t(tile.pixels()) * size_t(merged.values_per_pixel()));
            r.state.film.read_region(tile.bounds(), values.data());
            merged.write_region(tile.bounds(), values.data());
        }
    }
    EXPECT_TRUE(same_bits(merged, whole.state.film));
}

// --target-error's allocation (render/error_allocation.h) is decided from the whole film at
// decision points, and handed to every tile: the same bits for threads, tiles, passes and resume.
TEST_P(AdaptiveDeterminism, TargetAllocationSameBitsForThreadsTilesPassesAndResume) {
    Scene scene = adaptive_scene(GetParam());
    scene.sampler.adaptive.reset();
    scene.sampler.spp = 512;
    constexpr double kTarget = 1e-3;
    const RenderResult reference = render(scene, {.threads = 2, .target_error = kTarget});
    const SppSummary spp = spp_summary(reference.state.film);
    std::printf("target %g: spp mean %.1f min %g max %g, estimate %g\n", kTarget, spp.mean, spp.min, spp.max,
                *reference.stats.relmse_estimate);
    // The allocation stopped some blocks before others, and the target was met.
    ASSERT_TRUE(reference.stats.converged);
    ASSERT_LT(spp.min, spp.max);

    for (int threads : {1, 3})
        for (int tile_size : {5, 24})
            for (uint32_t pass_spp : {0u, 7u}) {
                SCOPED_TRACE(::testing::Message() << threads << " threads, tiles " << tile_size << ", passes " << pass_spp);
                const RenderResult r = render(
                    scene, {.threads = threads, .tile_size = tile_size, .pass_spp = pass_spp, .target_error = kTarget});
                EXPECT_TRUE(same_bits(r.state.film, reference.state.film));
            }
    for (int k : {2, 9, 20}) {
        SCOPED_TRACE(::testing::Message() << "stopped after " << k << " passes");
        int passes = 0;
        RenderOptions first{.threads = 1, .pass_spp = 3, .target_error = kTarget};
        first.on_pass = [&passes](const RenderState&) { ++passes; };
        first.stop = [&passes, k] { return passes >= k; };
        RenderResult stopped = render(scene, first);
        ASSERT_EQ(stopped.end, RenderEnd::kStopped);
        const RenderResult resumed =
            render(scene, {.threads = 3, .pass_spp = 5, .target_error = kTarget}, std::move(stopped.state));
        EXPECT_TRUE(same_bits(resumed.state.film, reference.state.film));
    }
}

INSTANTIATE_TEST_SUITE_P(Samplers, AdaptiveDeterminism,
                         ::testing::Values(SamplerType::kIndependent, SamplerType::kSobol));

// Calls f(mean in a, mean in b, sum of their variances of the mean) for every pixel and channel
// of two films with statistics.
template <class F>
void for_each_channel(const Film& a, const Film& b, F&& f) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const PixelSum va = variance_of_mean(a, x, y), vb = variance_of_mean(b, x, y);
            for (size_t c = 0; c < 3; ++c)
                f(a.sum(x, y)[c] / a.count(x, y), b.sum(x, y)[c] / b.count(x, y), va[c] + vb[c]);
        }
}

// Per pixel and channel, z = (adaptive - uniform) / sqrt(var_adaptive + var_uniform) from the
// films' own estimates (independent samples: unbiased). Returns the fraction with |z| > 4: for a
// t distribution with 15 degrees of freedom (the fewest samples a pixel has) that is 0.12%.
double fraction_rejected(const Film& a, const Film& b) {
    int rejected = 0, total = 0;
    for_each_channel(a, b, [&](double ma, double mb, double var) {
        const bool differ = var > 0.0 ? std::abs(ma - mb) > 4.0 * std::sqrt(var) : ma != mb;
        rejected += differ ? 1 : 0;
        ++total;
    });
    return double(rejected) / double(total);
}

// The sum over pixels and channels of (adaptive - uniform) over the square root of the sum of
// their variances: a standard normal when both images have the same expectation. Far more
// sensitive to a bias common to many pixels (as early stopping could cause) than the per-pixel test.
double aggregate_z(const Film& a, const Film& b) {
    double difference = 0.0, variance = 0.0;
    for_each_channel(a, b, [&](double ma, double mb, double var) {
        difference += ma - mb;
        variance += var;
    });
    return difference / std::sqrt(variance);
}

// `a` (an adaptive render of `uniform` with another seed) has the uniform render's expectation,
// pixel by pixel and in aggregate; and the controls, 3% and 30% more light, are seen as different.
void expect_same_expectation(const RenderResult& a, const Scene& uniform) {
    const RenderResult u = render(uniform, {.statistics = true});
    const SppSummary spp = spp_summary(a.state.film);
    ASSERT_LT(spp.min, spp.max);  // it adapted
    std::printf("adaptive: spp mean %.1f min %g max %g; aggregate z %.2f\n", spp.mean, spp.min, spp.max,
                aggregate_z(a.state.film, u.state.film));
    EXPECT_LT(fraction_rejected(a.state.film, u.state.film), 0.01);
    EXPECT_LT(std::abs(aggregate_z(a.state.film, u.state.film)), 4.0);

    // Controls: 3% more light is a different image, and the aggregate test must see it; 30% more,
    // and the per-pixel test must too.
    for (const float scale : {1.03f, 1.3f}) {
        Scene brighter = uniform;
        for (Shape& shape : brighter.shapes) shape.emission = shape.emission * scale;
        const RenderResult b = render(brighter, {.statistics = true});
        EXPECT_GT(std::abs(aggregate_z(a.state.film, b.state.film)), 4.0) << "emission x" << scale;
        if (scale > 1.1f) {
            EXPECT_GT(fraction_rejected(a.state.film, b.state.film), 0.05);
        }
    }
}

Scene glass_box_for_convergence() {
    Scene s = test::cornell_glass_scene(32, 32, 512);
    s.sampler.type = SamplerType::kIndependent;
    s.sampler.seed = 11;
    return s;
}

Scene uniform_reference_of(const Scene& adaptive) {
    Scene uniform = adaptive;
    uniform.sampler.adaptive.reset();
    uniform.sampler.seed = 12;
    uniform.sampler.spp = 256;
    return uniform;
}

TEST(AdaptiveSampling, ConvergesToTheUniformImage) {
    Scene adaptive = glass_box_for_convergence();
    adaptive.sampler.adaptive = AdaptiveSettings{0.1f, 16};
    expect_same_expectation(render(adaptive, {}), uniform_reference_of(adaptive));
}

// Blocks that --target-error's allocation stops early keep an unbiased mean too.
TEST(TargetError, AllocationConvergesToTheUniformImage) {
    const Scene scene = glass_box_for_convergence();
    const RenderResult a = render(scene, {.target_error = 5e-3});
    ASSERT_TRUE(a.stats.converged);
    expect_same_expectation(a, uniform_reference_of(scene));
}

// The relMSE of `test` against `reference`, less the reference's own estimated relMSE (its noise
// adds to the difference's).
double true_relmse(const RenderResult& test, const RenderResult& reference) {
    return bench::relmse(test.image, reference.image) - estimated_relmse(reference.state.film);
}

// With both samplers: for Sobol samples the image's estimate comes from the halves of each pixel's
// last power of two (film/pixel_statistics.h), which keeps it within 2x of the truth.
class TargetErrorSampler : public ::testing::TestWithParam<SamplerType> {};

TEST_P(TargetErrorSampler, StopsWhenTheEstimateSaysAndTheTrueErrorAgrees) {
    Scene scene = test::cornell_box_scene(24, 24, 4096);
    scene.sampler.type = GetParam();
    constexpr double kTarget = 2e-3;
    std::vector<std::pair<uint32_t, double>> estimates;  // at each decision point
    RenderOptions options{.target_error = kTarget};
    options.on_pass = [&](const RenderState& state) {
        if (is_decision_point(state.samples_done, kFirstTargetCheck))
            estimates.emplace_back(state.samples_done, estimated_relmse(state.film));
    };
    const RenderResult r = render(scene, options);
    ASSERT_TRUE(r.stats.converged);
    ASSERT_GE(estimates.size(), 2u);
    // It stopped at the first decision point where the estimate met the target.
    EXPECT_LE(estimates.back().second, kTarget);
    EXPECT_GT(estimates[estimates.size() - 2].second, kTarget);
    EXPECT_EQ(estimates.back().first, r.state.samples_done);
    // The same sum in another order (tiles, then rows).
    EXPECT_NEAR(*r.stats.relmse_estimate, estimates.back().second, 1e-12 * kTarget);

    // A converged render (32x the samples, another seed).
    Scene converged = scene;
    converged.sampler.seed = 99;
    converged.sampler.spp = int(32 * r.state.samples_done);
    const RenderResult reference = render(converged, {.statistics = true});
    const double truth = true_relmse(r, reference);
    std::printf("target %g: stopped at %u spp, estimate %g, true relMSE %g\n", kTarget, r.state.samples_done,
                *r.stats.relmse_estimate, truth);
    EXPECT_GT(truth, 0.5 * *r.stats.relmse_estimate);
    EXPECT_LT(truth, 2.0 * *r.stats.relmse_estimate);
}

INSTANTIATE_TEST_SUITE_P(Samplers, TargetErrorSampler, ::testing::Values(SamplerType::kIndependent, SamplerType::kSobol));

// The variance and spp AOV layers (film/aov_layers.h) come from the film's statistics: with or
// without adaptive sampling, named as the issue says, equal to the film's own estimates.
TEST(AdaptiveSampling, VarianceAndSppLayersAreTheFilmsStatistics) {
    for (const bool adaptive : {false, true}) {
        Scene scene = adaptive_scene(SamplerType::kIndependent);
        if (!adaptive) scene.sampler.adaptive.reset();
        scene.film.aovs.add(AovLayer::kVariance);
        scene.film.aovs.add(AovLayer::kSpp);
        const RenderResult r = render(scene, {.threads = 2});
        const Film& film = r.state.film;
        ASSERT_TRUE(film.has_statistics());
        const std::vector<ImageLayer> layers = film.resolve_aovs(r.state.samples_done);
        ASSERT_EQ(layers.size(), 2u);
        EXPECT_EQ(layers[0].name, "variance");
        EXPECT_EQ(layers[0].channel_names[0], "variance.R");
        EXPECT_EQ(layers[1].name, "spp");
        EXPECT_EQ(layers[1].channels, 1);
        EXPECT_EQ(layers[0].image.pixels, variance_image(film).pixels);
        EXPECT_EQ(layers[1].image.pixels, spp_image(film).pixels);
        const SppSummary spp = spp_summary(film);
        EXPECT_EQ(spp.max, 96.0);
        EXPECT_EQ(spp.min < spp.max, adaptive);
        // The beauty image is the one a render without the layers gives.
        Scene plain = scene;
        plain.film.aovs = {};
        EXPECT_EQ(render(plain, {.threads = 1, .statistics = true}).image.pixels, r.image.pixels);
    }
}

// A film without statistics cannot continue a render that needs them.
TEST(TargetError, RefusesAStartStateWithoutStatistics) {
    Scene scene = test::cornell_box_scene(8, 8, 4);
    EXPECT_THROW(render(scene, {.target_error = 0.1}, RenderState{make_film(scene)}), RenderError);
    scene.sampler.adaptive = AdaptiveSettings{};
    EXPECT_THROW(render(scene, {}, RenderState{Film(8, 8)}), RenderError);
}

}  // namespace
}  // namespace candela
