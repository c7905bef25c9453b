// The render job (render/job/job.h) in process: checkpoints, stops, resumes and shards give the
// bits of one uninterrupted render, and a resumed job takes the settings its checkpoint records.
// Exact comparisons throughout: the images' floats and the written files' bytes.
#include "candela/render/job/job.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/scene_file.h"
#include "candela/render/job/shard_merge.h"
#include "candela/scene/enum_names.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;
using test::fresh_dir;
using test::read_bytes;

const fs::path kCornell = fs::path(CANDELA_SOURCE_DIR) / "scenes/cornell-box/scene.json";
// Moving shapes and a moving instance (motion blur): each sample's time must come out the same.
const fs::path kMotionBlur = fs::path(CANDELA_SOURCE_DIR) / "scenes/motion-blur/scene.json";

// A small render of the Cornell box into `dir`.
RenderJobOptions small_job(const fs::path& dir, const std::string& output, int spp) {
    RenderJobOptions o;
    o.scene = kCornell;
    o.overrides.resolution = Resolution{24, 16};
    o.overrides.spp = spp;
    o.outputs = {dir / output};
    o.threads = 2;
    return o;
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

// Stops the job (as SIGINT would) once its first pass is complete.
void stop_after_first_pass(RenderJobOptions& o, const std::shared_ptr<std::atomic<bool>>& passed) {
    o.on_pass = [passed](const RenderState&) { *passed = true; };
    o.stop = [passed] { return *passed ? SIGINT : 0; };
}

SceneError job_error(const RenderJobOptions& o) {
    try {
        run_render_job(o);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "the job did not throw";
    return SceneError({}, "");
}

TEST(RenderJob, CheckpointedRenderResumesBitIdentically) {
    const fs::path dir = fresh_dir("job_checkpoint");
    const RenderJobResult whole = run_render_job(small_job(dir, "whole.pfm", 8));
    ASSERT_EQ(whole.render.end, RenderEnd::kComplete);
    EXPECT_FALSE(whole.checkpoint) << "no checkpoint was asked for";

    RenderJobOptions first = small_job(dir, "first.pfm", 4);
    first.checkpoint = dir / "ck.ckpt";
    const RenderJobResult r = run_render_job(first);
    ASSERT_EQ(r.checkpoint, dir / "ck.ckpt");
    EXPECT_EQ(r.images, std::vector<fs::path>{dir / "first.pfm"});

    RenderJobOptions resume = small_job(dir, "resumed.pfm", 8);
    resume.resume = dir / "ck.ckpt";
    const RenderJobResult resumed = run_render_job(resume);
    EXPECT_EQ(resumed.render.state.samples_done, 8u);
    EXPECT_TRUE(same_bits(resumed.render.image, whole.render.image));
    EXPECT_EQ(read_bytes(dir / "resumed.pfm"), read_bytes(dir / "whole.pfm"));
    EXPECT_EQ(resumed.checkpoint, dir / "resumed.pfm.ckpt") << "a resumed render can be taken further";
}

TEST(RenderJob, StopWritesACheckpointThatResumesBitIdentically) {
    const fs::path dir = fresh_dir("job_stop");
    const RenderJobResult whole = run_render_job(small_job(dir, "whole.pfm", 8));

    RenderJobOptions stopped = small_job(dir, "stopped.pfm", 8);
    stop_after_first_pass(stopped, std::make_shared<std::atomic<bool>>(false));
    const RenderJobResult r = run_render_job(stopped);
    EXPECT_EQ(r.render.end, RenderEnd::kStopped);
    EXPECT_EQ(r.stop_signal, SIGINT);
    EXPECT_EQ(r.exit_code, 128 + SIGINT);
    EXPECT_GT(r.render.state.samples_done, 0u);
    EXPECT_LT(r.render.state.samples_done, 8u);
    ASSERT_EQ(r.checkpoint, dir / "stopped.pfm.ckpt") << "a stopped render always writes its checkpoint";
    EXPECT_TRUE(fs::exists(dir / "stopped.pfm"));

    RenderJobOptions resume = small_job(dir, "resumed.pfm", 8);
    resume.resume = *r.checkpoint;
    const RenderJobResult resumed = run_render_job(resume);
    EXPECT_EQ(resumed.render.end, RenderEnd::kComplete);
    EXPECT_EQ(resumed.exit_code, 0);
    EXPECT_TRUE(same_bits(resumed.render.image, whole.render.image));
    EXPECT_EQ(read_bytes(dir / "resumed.pfm"), read_bytes(dir / "whole.pfm"));
}

TEST(RenderJob, ShardPartsMergeIntoTheWholeImage) {
    const fs::path dir = fresh_dir("job_shards");
    const RenderJobResult whole = run_render_job(small_job(dir, "whole.pfm", 4));
    std::vector<fs::path> parts;
    for (int i = 1; i <= 2; ++i) {
        RenderJobOptions part = small_job(dir, "part" + std::to_string(i) + ".ckpt", 4);
        part.shard = Shard{i, 2};
        const RenderJobResult r = run_render_job(part);
        EXPECT_EQ(r.checkpoint, part.outputs.front());
        EXPECT_TRUE(r.images.empty()) << "a part writes no image";
        parts.push_back(part.outputs.front());
    }
    const MergedRender merged = merge_shard_parts(parts);
    EXPECT_TRUE(same_bits(merged.state.film.resolve(merged.state.samples_done), whole.render.image));
}

// A stopped part resumes to the samples its file records, without --spp, and still merges.
TEST(RenderJob, StoppedShardPartResumesToItsTargetSpp) {
    const fs::path dir = fresh_dir("job_shard_resume");
    const RenderJobResult whole = run_render_job(small_job(dir, "whole.pfm", 8));
    RenderJobOptions first = small_job(dir, "part1.ckpt", 8);
    first.shard = Shard{1, 2};
    stop_after_first_pass(first, std::make_shared<std::atomic<bool>>(false));
    ASSERT_EQ(run_render_job(first).render.end, RenderEnd::kStopped);
    RenderJobOptions resume = first;
    resume.overrides = {};
    resume.resume = first.outputs.front();
    resume.stop = [] { return 0; };
    const RenderJobResult resumed = run_render_job(resume);
    EXPECT_EQ(resumed.spp, 8);
    EXPECT_EQ(resumed.render.state.samples_done, 8u);
    RenderJobOptions second = small_job(dir, "part2.ckpt", 8);
    second.shard = Shard{2, 2};
    run_render_job(second);
    const MergedRender merged = merge_shard_parts({dir / "part1.ckpt", dir / "part2.ckpt"});
    EXPECT_TRUE(same_bits(merged.state.film.resolve(merged.state.samples_done), whole.render.image));
}

// `--resume ck.ckpt` alone continues the render the checkpoint holds: its resolution, seed,
// sampler, integrator, AOV layers and adaptive settings, not the scene file's.
TEST(RenderJob, ResumeTakesTheCheckpointsSettings) {
    const fs::path dir = fresh_dir("job_takes_settings");
    RenderJobOptions settings = small_job(dir, "whole.exr", 12);
    settings.overrides.seed = 7;
    settings.overrides.sampler = SamplerType::kIndependent;
    settings.overrides.integrator = IntegratorType::kWhitted;
    settings.overrides.aovs = AovLayers{};
    settings.overrides.aovs->add(AovLayer::kAlbedo);
    settings.overrides.noise_threshold = 0.2;
    settings.overrides.min_spp = 4;
    const RenderJobResult whole = run_render_job(settings);

    RenderJobOptions first = settings;
    first.outputs = {dir / "first.exr"};
    first.overrides.spp = 4;
    first.checkpoint = dir / "ck.ckpt";
    ASSERT_EQ(run_render_job(first).checkpoint, dir / "ck.ckpt");

    RenderJobOptions resume;
    resume.scene = kCornell;
    resume.overrides.spp = 12;  // continue up to 12
    resume.outputs = {dir / "resumed.exr"};
    resume.resume = dir / "ck.ckpt";
    const RenderJobResult resumed = run_render_job(resume);
    EXPECT_EQ(resumed.width, 24);
    EXPECT_EQ(resumed.height, 16);
    EXPECT_EQ(resumed.integrator, "whitted");
    EXPECT_TRUE(same_bits(resumed.render.image, whole.render.image));
    EXPECT_EQ(read_bytes(dir / "resumed.exr"), read_bytes(dir / "whole.exr"));
}

TEST(RenderJob, ResumeRefusesAFlagThatContradictsTheCheckpointByName) {
    const fs::path dir = fresh_dir("job_contradicts");
    RenderJobOptions first = small_job(dir, "first.pfm", 2);
    first.checkpoint = dir / "ck.ckpt";
    run_render_job(first);

    RenderJobOptions resume = small_job(dir, "resumed.pfm", 4);
    resume.resume = dir / "ck.ckpt";
    resume.overrides.resolution = Resolution{30, 30};
    SceneError e = job_error(resume);
    EXPECT_EQ(e.where().file, (dir / "ck.ckpt").string());
    EXPECT_EQ(e.message(), "cannot resume: the checkpoint is 24x16, this render 30x30 (--resolution 30x30; without it "
                           "the render takes the checkpoint's)");

    resume.overrides.resolution.reset();
    resume.overrides.seed = 3;
    e = job_error(resume);
    EXPECT_EQ(e.where().file, (dir / "ck.ckpt").string());
    EXPECT_NE(e.message().find("(--seed 3; "), std::string::npos) << e.message();
    resume.overrides.seed.reset();
    resume.overrides.noise_threshold = 0.1;
    e = job_error(resume);
    EXPECT_NE(e.message().find("this render adaptive sampling with threshold 0.1 and min_spp 16 (--noise-threshold "
                               "0.1; "),
              std::string::npos)
        << e.message();
}

TEST(RenderJob, StoppedBeforeTheFirstPassWritesNothing) {
    const fs::path dir = fresh_dir("job_stopped_at_once");
    RenderJobOptions o = small_job(dir, "x.pfm", 4);
    o.stop = [] { return SIGTERM; };
    const RenderJobResult r = run_render_job(o);
    EXPECT_EQ(r.render.end, RenderEnd::kStopped);
    EXPECT_EQ(r.exit_code, 128 + SIGTERM);
    EXPECT_TRUE(r.images.empty());
    EXPECT_FALSE(r.checkpoint);
    EXPECT_FALSE(fs::exists(dir / "x.pfm"));
}

// The Python module's way in: a caller's loader in place of the file, and no files written, with
// the bits of the job that reads the file and writes the image, a time-limited stop included.
TEST(RenderJob, ACallersLoaderAndNoFilesGiveTheFilesBits) {
    const fs::path dir = fresh_dir("job_in_memory");
    const RenderJobResult from_file = run_render_job(small_job(dir, "file.pfm", 3));
    RenderJobOptions o = small_job(dir, "never.pfm", 3);
    o.scene = dir / "not-read.json";
    o.write_files = false;
    o.checkpoint_every = 1e-9;  // a periodic checkpoint is not written either
    int loads = 0;
    o.load = [&loads](const LoadOptions& options) {
        ++loads;
        EXPECT_FALSE(options.charge_film);  // the resolution is an override: charged once it is set
        return load_scene_file(kCornell, options);
    };
    const RenderJobResult in_memory = run_render_job(o);
    EXPECT_EQ(loads, 1);
    EXPECT_TRUE(same_bits(in_memory.render.image, from_file.render.image));
    EXPECT_TRUE(in_memory.images.empty());
    EXPECT_FALSE(in_memory.checkpoint);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);  // file.pfm only
    // A stopped render writes no checkpoint either (the file-writing job would).
    stop_after_first_pass(o, std::make_shared<std::atomic<bool>>(false));
    const RenderJobResult stopped = run_render_job(o);
    EXPECT_EQ(stopped.render.end, RenderEnd::kStopped);
    EXPECT_FALSE(stopped.checkpoint);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// The overrides apply before the memory check, which happens once, at the resolution rendered: a
// scene file too large for the limit renders at a --resolution that fits.
TEST(RenderJob, MemoryIsCheckedAtTheResolutionRendered) {
    const fs::path dir = fresh_dir("job_memory");
    const fs::path scene = dir / "scene.json";
    std::ofstream(scene) << R"({"camera": {"resolution": [32768, 32768]},
        "materials": {"m": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "center": [0, 0, 4], "radius": 1, "material": "m"}],
        "lights": [{"type": "environment", "color": [1, 1, 1]}]})";
    RenderJobOptions o;
    o.scene = scene;
    o.memory_limit = MemoryLimit{uint64_t(1) << 30, "the test's limit is"};
    o.outputs = {dir / "x.pfm"};
    const SceneError refused = job_error(o);
    EXPECT_EQ(refused.where().json_pointer, "/camera/resolution");
    EXPECT_EQ(refused.message().rfind("a 32768x32768 film needs about", 0), 0u) << refused.message();
    o.overrides.resolution = Resolution{8, 8};
    o.overrides.spp = 1;
    EXPECT_EQ(run_render_job(o).images, std::vector<fs::path>{dir / "x.pfm"});
}

}  // namespace
}  // namespace candela

namespace candela {
namespace CANDELA_UNITY_ID {

// --integrator that ignores the scene's media is warned about, as the scene loader warns about a
// scene file's own integrator; volpath is not.
TEST(RenderJob, AnIntegratorFlagThatIgnoresMediaIsWarnedAbout) {
    const fs::path dir = fresh_dir("job_media_warning");
    for (IntegratorType type : {IntegratorType::kPath, IntegratorType::kVolPath}) {
        RenderJobOptions o = small_job(dir, "fog.exr", 1);
        o.scene = fs::path(CANDELA_SOURCE_DIR) / "scenes/fog-room/scene.json";
        o.overrides.integrator = type;
        std::vector<std::string> warnings;
        o.message = [&](JobMessage kind, const std::string& text) {
            if (kind == JobMessage::kWarning) warnings.push_back(text);
        };
        run_render_job(o);
        const bool warned = std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) {
            return w.find("--integrator path: the scene has participating media") != std::string::npos;
        });
        EXPECT_EQ(warned, type == IntegratorType::kPath);
    }
}

// A scene file whose own integrator (path) cannot follow part of it is warned about by the loader
// (`file_warning`); --integrator volpath withdraws that warning (it no longer holds), and
// --integrator path gives its own (`flag_warning`).
void expect_integrator_flag_replaces_warning(const std::string& name, const std::string& scene_text,
                                             const char* file_warning, const char* flag_warning) {
    const fs::path dir = fresh_dir("job_" + name + "_warning_withdrawn");
    const fs::path scene = dir / (name + ".json");
    std::ofstream(scene) << scene_text;
    for (std::optional<IntegratorType> type : {std::optional<IntegratorType>(), std::optional(IntegratorType::kVolPath),
                                               std::optional(IntegratorType::kPath)}) {
        RenderJobOptions o = small_job(dir, name + ".exr", 1);
        o.scene = scene;
        o.overrides.integrator = type;
        std::vector<std::string> warnings;
        o.message = [&](JobMessage kind, const std::string& text) {
            if (kind == JobMessage::kWarning) warnings.push_back(text);
        };
        run_render_job(o);
        const auto count = [&](const char* words) {
            return std::count_if(warnings.begin(), warnings.end(),
                                 [&](const std::string& w) { return w.find(words) != std::string::npos; });
        };
        SCOPED_TRACE(type ? integrator_type_name(*type) : "the file's");
        EXPECT_EQ(count(file_warning), type ? 0 : 1);
        EXPECT_EQ(count(flag_warning), type == IntegratorType::kPath ? 1 : 0);
    }
}

// Participating media, which the path integrator ignores.
TEST(RenderJob, AnIntegratorFlagReplacesTheLoadersMediaWarning) {
    expect_integrator_flag_replaces_warning("fog-path", R"({"integrator": {"type": "path"}, "sampler": {"spp": 1},
      "media": {"fog": {"type": "homogeneous", "sigma_s": 0.1}},
      "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40, "resolution": [8, 8],
                 "medium": "fog"},
      "lights": [{"type": "environment", "color": 1}]})",
                                            "the path integrator ignores them",
                                            "--integrator path: the scene has participating media");
}

// A tabulated subsurface material, which only volpath (and bsdf) follows below its surface.
TEST(RenderJob, AnIntegratorFlagReplacesTheLoadersSubsurfaceWarning) {
    expect_integrator_flag_replaces_warning("skin-path", R"({"integrator": {"type": "path"}, "sampler": {"spp": 1},
      "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40, "resolution": [8, 8]},
      "materials": {"skin": {"type": "subsurface", "name": "Skin1"}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "skin"}],
      "lights": [{"type": "environment", "color": 1}]})",
                                            "the path integrator renders only their dielectric boundary",
                                            "--integrator path: the scene has subsurface materials");
}

// Motion blur: the times that samples draw are theirs however the render is split. The whole
// render on two threads against one thread, a stop and resume, and two shards merged.
TEST(RenderJob, MovingShapesGiveTheSameBitsAcrossThreadsResumesAndShards) {
    const fs::path dir = fresh_dir("job_motion");
    auto job = [&](const std::string& output, int threads) {
        RenderJobOptions o = small_job(dir, output, 8);
        o.scene = kMotionBlur;
        o.threads = threads;
        return o;
    };
    const RenderJobResult whole = run_render_job(job("whole.pfm", 2));
    EXPECT_TRUE(same_bits(run_render_job(job("one.pfm", 1)).render.image, whole.render.image));

    RenderJobOptions stopped = job("stopped.pfm", 2);
    stop_after_first_pass(stopped, std::make_shared<std::atomic<bool>>(false));
    const RenderJobResult r = run_render_job(stopped);
    ASSERT_EQ(r.render.end, RenderEnd::kStopped);
    ASSERT_TRUE(r.checkpoint);
    RenderJobOptions resume = job("resumed.pfm", 1);
    resume.resume = *r.checkpoint;
    EXPECT_TRUE(same_bits(run_render_job(resume).render.image, whole.render.image));

    std::vector<fs::path> parts;
    for (int i = 1; i <= 2; ++i) {
        RenderJobOptions part = job("part" + std::to_string(i) + ".ckpt", 2);
        part.shard = Shard{i, 2};
        run_render_job(part);
        parts.push_back(part.outputs.front());
    }
    const MergedRender merged = merge_shard_parts(parts);
    EXPECT_TRUE(same_bits(merged.state.film.resolve(merged.state.samples_done), whole.render.image));
}

}  // namespace
}  // namespace candela
