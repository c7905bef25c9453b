// Shards through the program: `candela render --shard I/N -o part-I.ckpt` for I = 1..N and then
// `candela merge` write the bytes of one `candela render` (.exr and .png, N = 1, 2, 5, a box
// filter and a weighted one); bad --shard values, resumes of the wrong file and every kind of
// merge refusal are one line on stderr and exit 2; scripts/slurm-shards.sh, run as Slurm would
// run it (a stand-in sbatch), writes the render's bytes too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_run.h"
#include "support/run_command.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;

const std::string kCornell = std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/scene.json";

fs::path temp_dir(const std::string& name) { return test::fresh_dir("shard_cli_" + name); }

using test::read_bytes;

using test::CliRun;

CliRun run(const Args& args, const fs::path& log) { return test::run_to_exit(CANDELA_CLI, args, log, 60.0); }

// A small scene of its own: a diffuse sphere under a sky, through a Mitchell filter (a film with
// weight sums) and the Reinhard tone map with a gamma transfer (the part files carry them).
fs::path write_weighted_scene(const fs::path& dir, const std::string& albedo = "0.5") {
    const fs::path file = dir / ("weighted-" + albedo + ".json");
    std::ofstream(file) << R"({"sampler": {"spp": 2}, "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0],
  "resolution": [37, 23]}, "film": {"filter": {"type": "mitchell"}, "tonemap": "reinhard", "transfer": "gamma",
  "gamma": 2.0}, "materials": {"m": {"type": "diffuse", "albedo": )"
                        << albedo << R"(}}, "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
  "material": "m"}], "lights": [{"type": "environment", "color": [1, 1, 1]}]})";
    return file;
}

// Renders parts 1..n of `render` (the scene and its flags) to part-I.ckpt in `dir`; their paths.
std::vector<std::string> render_parts(const fs::path& dir, const Args& render, int n) {
    std::vector<std::string> parts;
    for (int i = 1; i <= n; ++i) {
        parts.push_back((dir / ("part-" + std::to_string(i) + ".ckpt")).string());
        Args args = render;
        args.insert(args.end(), {"--shard", std::to_string(i) + "/" + std::to_string(n), "-o", parts.back()});
        const CliRun r = run(args, dir / "part.log");
        EXPECT_EQ(r.exit_code, 0) << r.output;
        EXPECT_NE(r.output.find("wrote " + parts.back() + " (part " + std::to_string(i) + " of " + std::to_string(n) + ")"),
                  std::string::npos)
            << r.output;
    }
    return parts;
}

// Merging parts 1..N of `render` gives the bytes of the render itself, for N = 1, 2, 5.
void expect_merge_is_the_render(const fs::path& dir, const Args& render, const std::string& size) {
    Args whole = render;
    whole.insert(whole.end(), {"--threads", "3", "-o", (dir / "whole.exr").string(), "-o", (dir / "whole.png").string()});
    const CliRun w = run(whole, dir / "whole.log");
    ASSERT_EQ(w.exit_code, 0) << w.output;
    for (int n : {1, 2, 5}) {
        std::vector<std::string> parts = render_parts(dir, render, n);
        std::reverse(parts.begin(), parts.end());  // any order
        Args merge = {"merge"};
        merge.insert(merge.end(), parts.begin(), parts.end());
        merge.insert(merge.end(), {"-o", (dir / "merged.exr").string(), "-o", (dir / "merged.png").string()});
        const CliRun m = run(merge, dir / "merge.log");
        ASSERT_EQ(m.exit_code, 0) << m.output;
        EXPECT_NE(m.output.find("merged " + std::to_string(n) + (n == 1 ? " part" : " parts") + " of a " + size +
                                " render"),
                  std::string::npos)
            << m.output;
        for (const char* ext : {".exr", ".png"}) {
            const std::string a = read_bytes(dir / (std::string("merged") + ext));
            EXPECT_FALSE(a.empty()) << ext;
            EXPECT_TRUE(a == read_bytes(dir / (std::string("whole") + ext))) << n << " parts: " << ext << " differs";
        }
    }
}

TEST(ShardCli, MergedPartsWriteTheRendersBytes) {
    const fs::path dir = temp_dir("box");
    expect_merge_is_the_render(dir, {"render", kCornell, "--resolution", "40x24", "--spp", "2"}, "40x24");
}

TEST(ShardCli, MergedPartsOfAWeightedFilmWriteTheRendersBytes) {
    const fs::path dir = temp_dir("weighted");
    expect_merge_is_the_render(dir, {"render", write_weighted_scene(dir).string()}, "37x23");
}

// Adaptive sampling with the variance and spp layers: the parts carry the film's statistics and
// stop where their own blocks stop (parts 2 and 5 of 5 after min_spp), and the merge is still the
// render's bytes.
TEST(ShardCli, MergedAdaptivePartsWriteTheRendersBytes) {
    const fs::path dir = temp_dir("adaptive");
    expect_merge_is_the_render(dir,
                               {"render", kCornell, "--resolution", "40x24", "--spp", "64", "--noise-threshold", "0.1",
                                "--min-spp", "4", "--aov", "variance,spp"},
                               "40x24");
    // The parts of 5 left there: blocks that stopped at min_spp and blocks that took every sample.
    Args merge = {"merge"};
    for (int i = 1; i <= 5; ++i) merge.push_back((dir / ("part-" + std::to_string(i) + ".ckpt")).string());
    merge.insert(merge.end(), {"-o", (dir / "merged.exr").string()});
    const CliRun m = run(merge, dir / "merge.log");
    ASSERT_EQ(m.exit_code, 0) << m.output;
    EXPECT_NE(m.output.find(" min 4 max 64; wrote"), std::string::npos) << m.output;
}

// `args` fails with exit 2 and exactly one line, "candela: error: " + `message`.
void expect_one_line_error(const Args& args, const fs::path& dir, const std::string& message) {
    const CliRun r = run(args, dir / "error.log");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(r.output.rfind("candela: error: " + message, 0), 0u) << r.output;
}

TEST(ShardCli, BadShardFlagsAreOneLineAndExitTwo) {
    const fs::path dir = temp_dir("bad_flags");
    const std::string part = (dir / "p.ckpt").string();
    for (const char* bad : {"0/3", "4/3", "x", "1/0", "", "3", "1/3/3", "-1/2"})
        expect_one_line_error({"render", kCornell, "--shard", bad, "-o", part}, dir,
                              std::string("--shard: expected I/N, part I of N with 1 <= I <= N <= 1048576, got \"") +
                                  bad + "\"");
    const std::string image = (dir / "x.png").string();
    expect_one_line_error({"render", kCornell, "--shard", "1/2", "-o", image}, dir,
                          "--shard 1/2: writes a part file, not images: give one -o PART.ckpt");
    expect_one_line_error({"render", kCornell, "--shard", "1/2", "-o", part, "-o", image}, dir,
                          "--shard 1/2: writes a part file, not images");
    expect_one_line_error({"render", kCornell, "--shard", "1/2"}, dir, "--shard 1/2: writes a part file");
    expect_one_line_error({"render", kCornell, "-o", part}, dir,
                          "-o " + part + ": a part file (.ckpt) is written only with --shard I/N");
    expect_one_line_error({"render", kCornell, "--shard", "1/2", "-o", part, "--checkpoint", part}, dir,
                          "--checkpoint: with --shard the part file (-o " + part + ") is the checkpoint");
    expect_one_line_error({"render", kCornell, "--resolution", "40x24", "--shard", "7/7", "-o", part}, dir,
                          "--shard 7/7: a 40x24 film has 6 tiles of 16 pixels, so at most 6 parts");
    EXPECT_FALSE(fs::exists(part));
    EXPECT_FALSE(fs::exists(image));
}

TEST(ShardCli, ResumingTheWrongFileIsRefused) {
    const fs::path dir = temp_dir("resume");
    const Args render = {"render", kCornell, "--resolution", "40x24", "--spp", "1"};
    const std::vector<std::string> parts = render_parts(dir, render, 2);
    const std::string whole = (dir / "whole.ckpt").string();
    Args full = render;
    full.insert(full.end(), {"-o", (dir / "whole.exr").string(), "--checkpoint", whole});
    ASSERT_EQ(run(full, dir / "whole.log").exit_code, 0);
    auto with = [&](const Args& more) {
        Args args = render;
        args.insert(args.end(), more.begin(), more.end());
        return args;
    };
    expect_one_line_error(with({"--resume", parts[0], "-o", (dir / "x.exr").string()}), dir,
                          parts[0] + ": part 1 of 2 of a shard render, not a checkpoint of the whole image: resume it "
                                     "with --shard 1/2");
    expect_one_line_error(with({"--shard", "1/2", "--resume", whole, "-o", parts[0]}), dir,
                          whole + ": a checkpoint of the whole image, not a shard's part file");
    expect_one_line_error(with({"--shard", "2/2", "--resume", parts[0], "-o", parts[1]}), dir,
                          parts[0] + ": cannot resume: this is part 1 of 2, the render asks for --shard 2/2");
    expect_one_line_error(with({"--shard", "1/2", "--seed", "5", "--resume", parts[0], "-o", parts[0]}), dir,
                          parts[0] + ": cannot resume: the checkpoint has seed 0, this render seed 5");
}

TEST(ShardCli, MergeRefusalsAreOneLineAndExitTwo) {
    const fs::path dir = temp_dir("merge_refusals");
    const Args render = {"render", kCornell, "--resolution", "40x24", "--spp", "1"};
    const std::vector<std::string> p = render_parts(dir, render, 3);
    const std::string out = (dir / "m.exr").string();
    // A part 3 of 3 of another render, one per difference.
    const std::string odd = (dir / "odd.ckpt").string();
    auto other = [&](const Args& render_args, const Args& more, const std::string& message) {
        Args args = render_args;
        args.insert(args.end(), more.begin(), more.end());
        args.insert(args.end(), {"--shard", "3/3", "-o", odd});
        const CliRun r = run(args, dir / "odd.log");
        ASSERT_EQ(r.exit_code, 0) << r.output;
        expect_one_line_error({"merge", p[0], p[1], odd, "-o", out}, dir, odd + ": " + message);
    };
    other(render, {"--seed", "5"}, "seed 5, but " + p[0] + " has seed 0: parts of different renders cannot be merged");
    other({"render", kCornell, "--resolution", "40x24", "--spp", "2"}, {}, "spp 2, but " + p[0] + " has spp 1");
    other(render, {"--sampler", "independent"}, "sampler independent, but " + p[0] + " has sampler sobol");
    other(render, {"--integrator", "bsdf"}, "integrator bsdf, but " + p[0] + " has integrator path");
    other({"render", write_weighted_scene(dir).string(), "--resolution", "40x24", "--spp", "1", "--sampler", "sobol"},
          {}, "a part of another scene than " + p[0]);
    Args four = render;
    four.insert(four.end(), {"--shard", "3/4", "-o", odd});
    ASSERT_EQ(run(four, dir / "odd.log").exit_code, 0);
    expect_one_line_error({"merge", p[0], p[1], odd, "-o", out}, dir,
                          odd + ": part 3 of 4, but " + p[0] + " is part 1 of 3: parts of different shard counts");

    expect_one_line_error({"merge", p[0], p[2], "-o", out}, dir, "part 2 of 3 is missing");
    expect_one_line_error({"merge", p[0], p[1], p[1], p[2], "-o", out}, dir, p[1] + ": given twice");
    const std::string copy = (dir / "copy.ckpt").string();
    fs::copy_file(p[1], copy);
    expect_one_line_error({"merge", p[0], p[1], copy, p[2], "-o", out}, dir,
                          copy + ": part 2 of 3 again: " + p[1] + " is part 2 too");
    const std::string bytes = read_bytes(p[2]);
    std::ofstream(odd, std::ios::binary) << bytes.substr(0, bytes.size() - 9);
    expect_one_line_error({"merge", p[0], p[1], odd, "-o", out}, dir, odd + ": truncated part file");
    std::string flipped = bytes;
    flipped[bytes.size() - 20] = char(flipped[bytes.size() - 20] ^ 4);
    std::ofstream(odd, std::ios::binary) << flipped;
    expect_one_line_error({"merge", p[0], p[1], odd, "-o", out}, dir, odd + ": corrupt checkpoint: the checksum");
    std::ofstream(odd, std::ios::binary) << "an image, say";
    expect_one_line_error({"merge", p[0], p[1], odd, "-o", out}, dir, odd + ": not a candela checkpoint");
    Args full = render;
    full.insert(full.end(), {"-o", (dir / "whole.exr").string(), "--checkpoint", odd});
    ASSERT_EQ(run(full, dir / "whole.log").exit_code, 0);
    expect_one_line_error({"merge", p[0], p[1], odd, "-o", out}, dir,
                          odd + ": a checkpoint of the whole image, not a shard's part file");
    expect_one_line_error({"merge", p[0], p[1], p[2], "-o", (dir / "m.tiff").string()}, dir,
                          "-o " + (dir / "m.tiff").string() + ": unknown image format");
    EXPECT_FALSE(fs::exists(out));
}

TEST(ShardCli, AdaptiveSettingsMustMatchToMergeOrResume) {
    const fs::path dir = temp_dir("adaptive_refusals");
    const Args render = {"render", kCornell, "--resolution", "40x24", "--spp", "8", "--noise-threshold", "0.1",
                         "--min-spp", "4"};
    const std::vector<std::string> p = render_parts(dir, render, 2);
    const std::string out = (dir / "m.exr").string();
    const std::string odd = (dir / "odd.ckpt").string();
    auto other = [&](const Args& more, const std::string& message) {
        Args args = {"render", kCornell, "--resolution", "40x24", "--spp", "8"};
        args.insert(args.end(), more.begin(), more.end());
        args.insert(args.end(), {"--shard", "2/2", "-o", odd});
        const CliRun r = run(args, dir / "odd.log");
        ASSERT_EQ(r.exit_code, 0) << r.output;
        expect_one_line_error({"merge", p[0], odd, "-o", out}, dir, odd + ": " + message);
    };
    other({"--noise-threshold", "0.2", "--min-spp", "4"},
          "adaptive sampling threshold 0.2, min_spp 4, but " + p[0] +
              " has adaptive sampling threshold 0.1, min_spp 4: parts of different renders cannot be merged");
    other({"--noise-threshold", "0.1", "--min-spp", "6"}, "adaptive sampling threshold 0.1, min_spp 6, but " + p[0]);
    other({}, "adaptive sampling off, but " + p[0] + " has adaptive sampling threshold 0.1, min_spp 4");
    // Statistics without adaptive sampling (the spp layer) against parts without them.
    other({"--aov", "spp"}, "adaptive sampling off, but " + p[0]);

    Args resume = {"render", kCornell, "--resolution", "40x24", "--spp", "16", "--noise-threshold", "0.2",
                   "--min-spp", "4", "--shard", "1/2", "--resume", p[0], "-o", p[0]};
    expect_one_line_error(resume, dir,
                          p[0] + ": cannot resume: the checkpoint used adaptive sampling with threshold 0.1 and "
                                 "min_spp 4, this render adaptive sampling with threshold 0.2 and min_spp 4");
    resume = {"render", kCornell, "--resolution", "40x24", "--spp", "16", "--min-spp", "6", "--shard", "1/2",
              "--resume", p[0], "-o", p[0]};
    expect_one_line_error(resume, dir,
                          p[0] + ": cannot resume: the checkpoint used adaptive sampling with threshold 0.1 and "
                                 "min_spp 4, this render adaptive sampling with threshold 0.1 and min_spp 6 "
                                 "(--min-spp 6; without it the render takes the checkpoint's)");
    // Without the flags the part's own adaptive settings (and resolution) are taken.
    resume = {"render", kCornell, "--spp", "16", "--shard", "1/2", "--resume", p[0], "-o", p[0]};
    const CliRun resumed = run(resume, dir / "resumed.log");
    EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
    // A whole-image target is no part's: refused with --shard.
    expect_one_line_error({"render", kCornell, "--resolution", "40x24", "--target-error", "0.01", "--shard", "1/2",
                           "-o", odd},
                          dir, "--target-error does not run with --shard");
}

// Runs `command` with bash; its exit status and output.
CliRun run_bash(const std::string& command) {
    const candela::test::CommandResult r = candela::test::run_command("bash -c '" + command + "' 2>&1");
    return {r.exit_code, r.output};
}

TEST(ShardCli, SlurmScriptRendersAndMergesTheRendersBytes) {
    const fs::path dir = temp_dir("slurm");
    const std::string script = std::string(CANDELA_SOURCE_DIR) + "/scripts/slurm-shards.sh";
    ASSERT_EQ(run_bash("bash -n " + script).exit_code, 0);
    // sbatch records what it is asked to submit and answers a job id, as `sbatch --parsable` does.
    fs::create_directories(dir / "bin");
    std::ofstream(dir / "bin" / "sbatch") << "#!/usr/bin/env bash\nprintf \"%s\\n\" \"$*\" >> sbatch.log\necho 4242\n";
    fs::permissions(dir / "bin" / "sbatch", fs::perms::owner_all);
    const std::string env = "cd " + dir.string() + " && PATH=" + (dir / "bin").string() + ":$PATH CANDELA=" +
                            CANDELA_CLI + " SHARDS=3 ";
    const std::string args = " " + kCornell + " frame.exr frame.png -- --spp 1 --resolution 40x24";
    const CliRun submit = run_bash(env + "bash " + script + args);
    ASSERT_EQ(submit.exit_code, 0) << submit.output;
    EXPECT_NE(submit.output.find("submitted job array 4242 (3 shards) and merge job 4242"), std::string::npos)
        << submit.output;
    const std::string log = read_bytes(dir / "sbatch.log");
    EXPECT_NE(log.find("--array=1-3 "), std::string::npos) << log;
    EXPECT_NE(log.find("--dependency=afterok:4242"), std::string::npos) << log;
    // The array's tasks, then the merge job's wrapped command line.
    for (int i = 1; i <= 3; ++i) {
        const CliRun task = run_bash(env + "SLURM_ARRAY_TASK_ID=" + std::to_string(i) + " bash " + script + args);
        ASSERT_EQ(task.exit_code, 0) << task.output;
    }
    const CliRun merge = run_bash(env + "eval \"$(sed -n \"s/.*--wrap=//p\" sbatch.log)\"");
    ASSERT_EQ(merge.exit_code, 0) << merge.output;
    EXPECT_NE(merge.output.find("merged 3 parts of a 40x24 render"), std::string::npos) << merge.output;
    const CliRun whole = run({"render", kCornell, "--spp", "1", "--resolution", "40x24", "-o",
                              (dir / "whole.exr").string(), "-o", (dir / "whole.png").string()},
                             dir / "whole.log");
    ASSERT_EQ(whole.exit_code, 0) << whole.output;
    for (const char* ext : {".exr", ".png"}) {
        const std::string a = read_bytes(dir / (std::string("frame") + ext));
        EXPECT_FALSE(a.empty()) << ext;
        EXPECT_TRUE(a == read_bytes(dir / (std::string("whole") + ext))) << ext;
    }
}

}  // namespace
}  // namespace candela
