// --target-error where light is hard (issue 28): on a glass Cornell box's caustics, a prism's
// dispersed caustic (spectral) and veach-bidir's lamp behind its glass fixture, each at three
// targets over three decades, the true relMSE of the render that stopped on its estimate is at
// most 1.5x the target. The truth is against a converged reference made by
// bench's candela_make_reference (tests/data/target-error/README.md: the commands), less the
// reference's own relMSE, which that tool prints and which lies well under each scene's tightest
// target / 10. Renders at 64x64 for seconds each: the `reference` label.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <ostream>
#include <string>
#include <utility>

#include "bench/image_compare.h"
#include "candela/film/film.h"
#include "candela/formats/scene_file.h"
#include "candela/image/image_io.h"
#include "candela/render/adaptive_sampling.h"
#include "candela/render/renderer.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 64;
constexpr double kAllowed = 1.5;  // the promise: true relMSE at most 1.5x the target

struct HardScene {
    const char* name;         // tests/data/target-error/NAME.exr
    const char* file;         // under the source tree
    double reference_relmse;  // printed by candela_make_reference
    std::array<double, 3> targets;
};

// The loose targets are where the estimate used to fail: at 16 spp cornell-glass's true relMSE
// was 18x its estimate, the prism's 37x (bench/RESULTS.md, issue 28).
const HardScene kScenes[] = {
    {"cornell-glass", "scenes/cornell-glass/scene.json", 3.68983e-05, {0.1, 0.01, 0.001}},
    {"prism", "scenes/prism/scene.json", 0.000333086, {1.0, 0.1, 0.01}},
    {"veach-bidir", "scenes/pbrt-v4/veach-bidir/scene-v4.pbrt", 0.00697292, {100.0, 10.0, 1.0}},
};

struct Case {
    const HardScene* scene;
    double target;
    SamplerType sampler;
};

// How gtest and ctest name a case (else the bytes of its pointer).
void PrintTo(const Case& c, std::ostream* os) {
    *os << c.scene->name << ", target " << c.target
        << (c.sampler == SamplerType::kIndependent ? ", independent" : ", sobol");
}

class TargetErrorOnHardLight : public ::testing::TestWithParam<Case> {};

TEST_P(TargetErrorOnHardLight, TrueRelmseIsAtMostOneAndAHalfTimesTheTarget) {
    const Case c = GetParam();
    Scene scene = load_scene_file(std::string(CANDELA_SOURCE_DIR) + "/" + c.scene->file);
    scene.camera.width = kSize;
    scene.camera.height = kSize;
    scene.sampler.type = c.sampler;
    scene.sampler.seed = 5;
    scene.sampler.spp = 1 << 16;  // far above what any target here needs: the target stops it
    scene.sampler.adaptive.reset();
    const RenderResult r = render(scene, {.threads = 2, .target_error = c.target});
    ASSERT_TRUE(r.stats.converged);
    const Image reference = read_image(std::string(CANDELA_TEST_DATA_DIR) + "/target-error/" + c.scene->name + ".exr");
    const double truth = bench::relmse(r.image, reference) - c.scene->reference_relmse;
    std::printf("%s, target %g: stopped at %u spp (mean %.1f), estimate %g, true relMSE %g (%.2fx the target)\n",
                c.scene->name, c.target, r.state.samples_done, double(r.stats.samples) / (kSize * kSize),
                *r.stats.relmse_estimate, truth, truth / c.target);
    EXPECT_LE(truth, kAllowed * c.target);
}

std::vector<Case> cases() {
    std::vector<Case> all;
    for (const HardScene& s : kScenes)
        for (const double target : s.targets) all.push_back({&s, target, SamplerType::kSobol});
    // The other sampler at the loosest target of the first scene, where the old estimate failed most.
    all.push_back({&kScenes[0], kScenes[0].targets[0], SamplerType::kIndependent});
    all.push_back({&kScenes[1], kScenes[1].targets[1], SamplerType::kIndependent});
    // veach-bidir's own sampler, one decade below its tightest Sobol target: where the samples after
    // the last power of two went unseen (3.3x the target) until the halves' estimate counted them.
    all.push_back({&kScenes[2], 0.1, SamplerType::kIndependent});
    return all;
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
    std::string name = info.param.scene->name;
    for (char& ch : name)
        if (ch == '-') ch = '_';
    char target[32];
    std::snprintf(target, sizeof target, "%g", info.param.target);
    std::string t = target;
    for (char& ch : t)
        if (ch == '.') ch = 'p';
    return name + "_" + t + (info.param.sampler == SamplerType::kIndependent ? "_independent" : "_sobol");
}

INSTANTIATE_TEST_SUITE_P(Scenes, TargetErrorOnHardLight, ::testing::ValuesIn(cases()), case_name);

// The true relMSE of the pixels of `block` of `image` against `reference` (the benchmark's measure).
double block_relmse(const Image& image, const Image& reference, const PixelBounds& block) {
    double sum = 0.0;
    for (int y = block.y0; y < block.y1; ++y)
        for (int x = block.x0; x < block.x1; ++x) {
            const size_t i = size_t(y) * size_t(image.width) + size_t(x);
            const Rgb a = image.pixels[i], b = reference.pixels[i];
            for (const auto& [t, r] : {std::pair{a.r, b.r}, std::pair{a.g, b.g}, std::pair{a.b, b.b}})
                sum += double(t - r) * double(t - r) / (double(r) * double(r) + 0.01);
        }
    return sum / (3.0 * double(block.width()) * double(block.height()));
}

// --noise-threshold T stops a block when each of its pixels' estimated relative error is below T,
// so a block that stopped has a true relMSE (the mean of its pixels' squared relative errors) of at
// most T^2: the threshold's own promise, with no allowance, since the squares' estimate it reads is
// conservative for Sobol samples. No block under the glass sphere or in the prism's caustic may stop
// because its samples have not found the light yet. (Over each pixel's own mean, as before issue 28,
// cornell-glass's worst stopped block at T = 0.5 had 1.09 T^2.)
TEST(NoiseThresholdOnHardLight, StoppedBlocksHoldTheThreshold) {
    for (const HardScene& glass : {kScenes[0], kScenes[1]})
        for (const float threshold : {0.5f, 0.3f}) {
            Scene scene = load_scene_file(std::string(CANDELA_SOURCE_DIR) + "/" + glass.file);
            scene.camera.width = kSize;
            scene.camera.height = kSize;
            scene.sampler.seed = 5;
            scene.sampler.spp = 4096;
            scene.sampler.adaptive = AdaptiveSettings{threshold, 16};
            const RenderResult r = render(scene, {.threads = 2});
            const Image reference =
                read_image(std::string(CANDELA_TEST_DATA_DIR) + "/target-error/" + glass.name + ".exr");
            const double allowed = double(threshold) * double(threshold);
            double worst = 0.0;
            int stopped = 0;
            for (int y = 0; y < kSize; y += kAdaptiveBlockSize)
                for (int x = 0; x < kSize; x += kAdaptiveBlockSize) {
                    const PixelBounds block{x, y, x + kAdaptiveBlockSize, y + kAdaptiveBlockSize};
                    if (r.state.film.count(x, y) >= double(scene.sampler.spp)) continue;  // never stopped
                    ++stopped;
                    const double truth = block_relmse(r.image, reference, block) - glass.reference_relmse;
                    worst = std::max(worst, truth);
                    EXPECT_LE(truth, allowed)
                        << "block at " << x << ", " << y << " stopped at " << r.state.film.count(x, y) << " spp";
                }
            std::printf("%s, threshold %g: %d of 64 blocks stopped, worst true block relMSE %g (%.2fx T^2)\n",
                        glass.name, double(threshold), stopped, worst, worst / (double(threshold) * double(threshold)));
            EXPECT_GT(stopped, 0);
        }
}

}  // namespace CANDELA_UNITY_ID
}  // namespace candela
