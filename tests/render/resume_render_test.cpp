// Interrupt and resume: a render stopped after any pass (or inside one), then continued, with
// other thread counts and pass sizes, gives exactly the bits of an uninterrupted render; and the
// image of a stopped render is exactly the image of a render of the samples it completed.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <string>
#include <tuple>

#include "candela/core/error.h"
#include "candela/render/job/checkpoint.h"
#include "candela/render/renderer.h"
#include "candela/scene/enum_names.h"
#include "support/test_scenes.h"

namespace candela {

// Readable parameters and ends in test names and failure messages.
inline void PrintTo(IntegratorType t, std::ostream* os) { *os << integrator_type_name(t); }
inline void PrintTo(SamplerType t, std::ostream* os) { *os << sampler_type_name(t); }
inline void PrintTo(RenderEnd e, std::ostream* os) {
    *os << (e == RenderEnd::kComplete ? "complete" : e == RenderEnd::kStopped ? "stopped" : "deadline");
}

namespace CANDELA_UNITY_ID {

bool same_bits(const Film& a, const Film& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.sums().data(), b.sums().data(), a.sums().size() * sizeof(PixelSum)) == 0;
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

// Options that stop the render once `k` passes of `pass_spp` are complete.
RenderOptions stop_after_passes(int k, uint32_t pass_spp, int threads, int& passes) {
    RenderOptions o;
    o.threads = threads;
    o.pass_spp = pass_spp;
    o.on_pass = [&passes](const RenderState&) { ++passes; };
    o.stop = [&passes, k] { return passes >= k; };
    return o;
}

Scene lit_scene(IntegratorType integrator, SamplerType sampler, int spp, bool spectral = false) {
    // Not a multiple of the tile size; a light, a mirror and indirect light, so every branch of
    // the transport integrators runs.
    Scene s = integrator == IntegratorType::kVolPath ? test::media_small_box_scene(37, 23, spp)
                                                      : test::lit_small_box_scene(37, 23, spp);
    s.integrator.type = integrator;
    s.integrator.spectral = spectral;
    s.sampler.type = sampler;
    return s;
}

using Param = std::tuple<IntegratorType, SamplerType, bool>;  // bool: spectral mode

class Resume : public ::testing::TestWithParam<Param> {};

std::string param_name(const ::testing::TestParamInfo<Param>& info) {
    return std::string(integrator_type_name(std::get<0>(info.param))) + "_" +
           std::string(sampler_type_name(std::get<1>(info.param))) + (std::get<2>(info.param) ? "_spectral" : "");
}

TEST_P(Resume, StoppedAfterAnyPassAndResumedIsBitIdentical) {
    const Scene scene = lit_scene(std::get<0>(GetParam()), std::get<1>(GetParam()), 12, std::get<2>(GetParam()));
    const RenderResult reference = render(scene, {.threads = 2});
    ASSERT_EQ(reference.state.samples_done, 12u);
    float brightest = 0.0f;  // a black image would be trivially identical
    for (const Rgb& p : reference.image.pixels) brightest = std::max(brightest, p.max_component());
    ASSERT_GT(brightest, 0.0f);

    // Stops after 1, 4 and 9 samples (k passes of k), each with other thread counts before and
    // after, and passes of 5 (not dividing what is left) or timed ones after.
    const std::pair<int, int> thread_pairs[] = {{1, 2}, {2, 3}, {3, 1}};
    for (int k = 1; k <= 3; ++k) {
        for (auto [before, after] : thread_pairs) {
            SCOPED_TRACE("stopped after " + std::to_string(k) + " passes of " + std::to_string(k) + ", threads " +
                         std::to_string(before) + " then " + std::to_string(after));
            int passes = 0;
            RenderResult part = render(scene, stop_after_passes(k, uint32_t(k), before, passes));
            EXPECT_EQ(part.end, RenderEnd::kStopped);
            ASSERT_EQ(part.state.samples_done, uint32_t(k * k));
            // The stopped render's image is the image of its samples.
            Scene fewer = scene;
            fewer.sampler.spp = k * k;
            EXPECT_TRUE(same_bits(part.image, render(fewer, {.threads = 2}).image));

            RenderOptions rest_options{.threads = after};
            rest_options.pass_spp = after == 1 ? 0 : 5;
            RenderResult rest = render(scene, rest_options, std::move(part.state));
            EXPECT_EQ(rest.end, RenderEnd::kComplete);
            EXPECT_EQ(rest.state.samples_done, 12u);
            EXPECT_EQ(rest.state.dropped_samples, reference.state.dropped_samples);
            EXPECT_TRUE(same_bits(rest.state.film, reference.state.film));
            EXPECT_TRUE(same_bits(rest.image, reference.image));
        }
    }
}

TEST_P(Resume, ThroughACheckpointFileIsBitIdentical) {
    const Scene scene = lit_scene(std::get<0>(GetParam()), std::get<1>(GetParam()), 10, std::get<2>(GetParam()));
    const RenderResult reference = render(scene, {.threads = 3});
    int passes = 0;
    RenderResult part = render(scene, stop_after_passes(2, 3, 2, passes));
    ASSERT_EQ(part.state.samples_done, 6u);
    const std::filesystem::path file =
        std::filesystem::path(CANDELA_TEST_BINARY_DIR) / ("resume_" + param_name({GetParam(), 0}) + ".ckpt");
    write_checkpoint(file, render_identity(scene, 1), part.state);
    Checkpoint c = read_checkpoint(file);
    RenderResult rest = render(scene, {.threads = 1}, std::move(c.state));
    EXPECT_TRUE(same_bits(rest.state.film, reference.state.film));
    EXPECT_TRUE(same_bits(rest.image, reference.image));
}

INSTANTIATE_TEST_SUITE_P(TransportIntegrators, Resume,
                         ::testing::Combine(::testing::Values(IntegratorType::kPath, IntegratorType::kBsdf, IntegratorType::kVolPath),
                                            ::testing::Values(SamplerType::kIndependent, SamplerType::kSobol),
                                            ::testing::Bool()),
                         param_name);

TEST(ResumeRender, AbandonedPassLeavesNoTrace) {
    // Passes of 4: the stop comes after the first pass and three tiles of the second (of 6), so
    // half of the second pass is in `next` when it is abandoned.
    const Scene scene = lit_scene(IntegratorType::kPath, SamplerType::kIndependent, 8);
    std::atomic<int> tiles_started{0};
    int passes = 0;
    RenderOptions o{.threads = 2};
    o.pass_spp = 4;
    o.on_pass = [&](const RenderState&) { ++passes; };
    // Asked once between the passes, then before each tile: true from the fourth tile on.
    o.stop = [&] { return passes >= 1 && tiles_started.fetch_add(1) >= 4; };
    RenderResult stopped = render(scene, o);
    EXPECT_EQ(stopped.end, RenderEnd::kStopped);
    EXPECT_EQ(stopped.stats.passes, 1);
    ASSERT_EQ(stopped.state.samples_done, 4u);

    Scene four = scene;
    four.sampler.spp = 4;
    const RenderResult reference4 = render(four, {.threads = 1});
    EXPECT_TRUE(same_bits(stopped.state.film, reference4.state.film));
    EXPECT_TRUE(same_bits(stopped.image, reference4.image));
    EXPECT_EQ(stopped.state.dropped_samples, reference4.state.dropped_samples);
    // The abandoned tiles did trace rays: the stop did land inside the pass.
    EXPECT_GT(stopped.stats.rays.camera, reference4.stats.rays.camera);

    const RenderResult reference8 = render(scene, {.threads = 2});
    RenderResult resumed = render(scene, {.threads = 3}, std::move(stopped.state));
    EXPECT_TRUE(same_bits(resumed.state.film, reference8.state.film));
}

TEST(ResumeRender, DeadlineStopsAtAPassBoundary) {
    const Scene scene = lit_scene(IntegratorType::kPath, SamplerType::kIndependent, 1 << 20);
    RenderOptions o{.threads = 2};
    o.pass_seconds = 0.02;
    o.deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
    RenderResult stopped = render(scene, o);
    EXPECT_EQ(stopped.end, RenderEnd::kDeadline);
    ASSERT_GT(stopped.state.samples_done, 0u);
    ASSERT_LT(stopped.state.samples_done, uint32_t(1 << 20));
    Scene done = scene;
    done.sampler.spp = int(stopped.state.samples_done);
    EXPECT_TRUE(same_bits(stopped.state.film, render(done, {.threads = 1}).state.film));
}

TEST(ResumeRender, DeadlineAlreadyPassedRendersNothing) {
    const Scene scene = lit_scene(IntegratorType::kPath, SamplerType::kIndependent, 4);
    RenderOptions o;
    o.deadline = std::chrono::steady_clock::now();
    RenderResult r = render(scene, o);
    EXPECT_EQ(r.end, RenderEnd::kDeadline);
    EXPECT_EQ(r.state.samples_done, 0u);
    EXPECT_EQ(r.stats.rays.total(), 0u);
}

TEST(ResumeRender, StartPastTheRequestedSamplesIsReturnedAsItIs) {
    Scene scene = lit_scene(IntegratorType::kPath, SamplerType::kIndependent, 6);
    const RenderResult six = render(scene, {.threads = 2});
    scene.sampler.spp = 4;
    RenderState start{six.state.film, six.state.samples_done, six.state.dropped_samples};
    RenderResult r = render(scene, {.threads = 2}, std::move(start));
    EXPECT_EQ(r.end, RenderEnd::kComplete);
    EXPECT_EQ(r.state.samples_done, 6u);
    EXPECT_EQ(r.stats.passes, 0);
    EXPECT_EQ(r.stats.rays.total(), 0u);
    EXPECT_TRUE(same_bits(r.image, six.image));
}

TEST(ResumeRender, StartOfAnotherSizeIsAnInternalError) {
    const Scene scene = lit_scene(IntegratorType::kPath, SamplerType::kIndependent, 2);
    EXPECT_THROW(render(scene, {}, RenderState{Film(36, 23)}), RenderError);
}

}  // namespace
}  // namespace candela
