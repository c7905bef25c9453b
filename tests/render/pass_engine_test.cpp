// The pass engine (render/pass_engine.h) with executors of the tests' own: whatever runs a pass's
// tiles, in whatever order and on whatever thread, the image is render()'s, bit for bit; the
// engine cuts passes at adaptive sampling's decision points and nowhere else; an executor that
// abandons a pass (as the MPI root does for another rank's stop) leaves the last complete pass,
// which resumes to the uninterrupted bits; and finish() is called once, with the end and state.
#include <gtest/gtest.h>

#include <cstring>
#include <utility>
#include <vector>

#include "candela/core/error.h"
#include "candela/render/adaptive_sampling.h"
#include "candela/render/frame_renderer.h"
#include "candela/render/pass_engine.h"
#include "candela/render/renderer.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

// Renders a pass's tiles one by one on the calling thread, last tile first, recording each
// pass's sample range; optionally abandons the render halfway through pass `abandon_in_pass`.
class SerialReverseExecutor final : public PassExecutor {
  public:
    explicit SerialReverseExecutor(const FrameRenderer& frame, uint32_t abandon_in_pass = 0)
        : frame_(frame), abandon_in_pass_(abandon_in_pass) {}

    int threads() const override { return 1; }

    uint64_t run_pass(const PassWork& pass, PassEngine& engine) override {
        passes.emplace_back(pass.begin, pass.end);
        const std::vector<Tile>& tiles = engine.tiles();
        for (size_t i = tiles.size(); i-- > 0;) {
            if (pass.id == abandon_in_pass_ && i == tiles.size() / 2) engine.abandon(RenderEnd::kStopped);
            if (engine.should_stop()) break;
            const uint64_t rays_before = tally_.rays.total();
            frame_.render_tile(tiles[i], pass.begin, pass.end, *pass.from, *pass.to, tally_, pass.target_scale);
            engine.tile_done(i, pass, tally_.rays.total() - rays_before);
        }
        return std::exchange(tally_.dropped, 0);
    }

    RayCounters finish(RenderEnd end, const RenderState& state) override {
        ++finishes;
        finished_with = end;
        finished_samples = state.samples_done;
        return tally_.rays;
    }

    std::vector<std::pair<uint32_t, uint32_t>> passes;  // [begin, end) of each pass begun
    int finishes = 0;
    RenderEnd finished_with = RenderEnd::kComplete;
    uint32_t finished_samples = 0;

  private:
    const FrameRenderer& frame_;
    const uint32_t abandon_in_pass_;
    TileTally tally_;
};

RenderResult run_with(SerialReverseExecutor& executor, const FrameRenderer& frame, const Scene& scene,
                      const RenderOptions& options, RenderState start) {
    PassEngine engine(frame, scene, options, std::move(start));
    return engine.run(executor);
}

TEST(PassEngine, AnyExecutorGivesRenderBits) {
    const Scene scene = test::lit_small_box_scene(37, 23, 9);
    const RenderOptions options{.threads = 2, .tile_size = 8, .pass_spp = 2};
    const RenderResult reference = render(scene, options);
    const FrameRenderer frame(scene);
    SerialReverseExecutor serial(frame);
    const RenderResult result = run_with(serial, frame, scene, options, RenderState{make_film(scene)});
    EXPECT_TRUE(same_bits(result.image, reference.image));
    EXPECT_EQ(result.end, RenderEnd::kComplete);
    EXPECT_EQ(result.stats.passes, 5);  // 2 + 2 + 2 + 2 + 1 samples per pixel
    EXPECT_EQ(result.stats.samples, uint64_t(37 * 23 * 9));
    EXPECT_EQ(result.stats.rays.total(), reference.stats.rays.total());
    EXPECT_EQ(serial.finishes, 1);
    EXPECT_EQ(serial.finished_samples, 9u);
}

TEST(PassEngine, PassesEndAtDecisionPoints) {
    Scene scene = test::lit_small_box_scene(24, 16, 40);
    scene.sampler.adaptive = AdaptiveSettings{0.05f, 8};
    const RenderOptions options{.tile_size = 8, .pass_spp = 5};
    const FrameRenderer frame(scene);
    SerialReverseExecutor serial(frame);
    const RenderResult result = run_with(serial, frame, scene, options, RenderState{make_film(scene, true)});
    ASSERT_FALSE(serial.passes.empty());
    uint32_t expected_begin = 0;
    for (const auto& [begin, end] : serial.passes) {
        EXPECT_EQ(begin, expected_begin);
        // A pass never crosses a decision point: it ends at the next one or before.
        EXPECT_LE(end, next_decision_point(begin, 8)) << "pass [" << begin << ", " << end << ")";
        EXPECT_LE(end - begin, 5u);
        expected_begin = end;
    }
    EXPECT_TRUE(same_bits(result.image, render(scene, {.threads = 2, .tile_size = 8}).image));
}

TEST(PassEngine, AbandonedPassKeepsTheLastCompleteOneAndResumes) {
    const Scene scene = test::lit_small_box_scene(37, 23, 8);
    const RenderOptions options{.tile_size = 8, .pass_spp = 2};
    const FrameRenderer frame(scene);
    SerialReverseExecutor stopping(frame, /*abandon_in_pass=*/3);
    RenderResult stopped = run_with(stopping, frame, scene, options, RenderState{make_film(scene)});
    EXPECT_EQ(stopped.end, RenderEnd::kStopped);
    EXPECT_EQ(stopped.state.samples_done, 4u);  // passes 1 and 2 of 2 samples each
    EXPECT_EQ(stopping.finished_with, RenderEnd::kStopped);
    EXPECT_EQ(stopping.finishes, 1);

    Scene four = scene;
    four.sampler.spp = 4;
    EXPECT_TRUE(same_bits(stopped.image, render(four, {.threads = 2}).image));
    SerialReverseExecutor rest(frame);
    const RenderResult resumed = run_with(rest, frame, scene, options, std::move(stopped.state));
    EXPECT_TRUE(same_bits(resumed.image, render(scene, {.threads = 2}).image));
    EXPECT_EQ(rest.passes.front().first, 4u);
}

TEST(PassEngine, RefusesAStartStateOfAnotherSize) {
    const Scene scene = test::lit_small_box_scene(37, 23, 4);
    const FrameRenderer frame(scene);
    const RenderOptions options;
    EXPECT_THROW(PassEngine(frame, scene, options, RenderState{make_film(test::lit_small_box_scene(36, 23, 4))}),
                 RenderError);
}

}  // namespace
}  // namespace candela
