// Stopping and resuming the real program: SIGINT and SIGTERM save the image of the samples done
// and a checkpoint and exit 130 / 143, --time-limit does the same with exit 0, a second signal
// quits at once, and --resume then ends with exactly the bytes of an uninterrupted render (also of
// a shard's part file, stopped at the time limit or by SIGINT after periodic part files).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_run.h"
#include "candela/render/job/checkpoint.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;
using test::ChildProcess;
using test::wait_until;

constexpr double kTimeout = 120.0;  // seconds; only reached when something is broken
const std::string kCornell = std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/scene.json";
// More samples than any test waits for: these renders always end by a stop.
const std::string kEndless = "1000000";

fs::path temp_dir(const std::string& name) { return test::fresh_dir("interrupt_" + name); }

using test::read_bytes;

using test::CliRun;

// Runs candela to the end.
CliRun run(const std::vector<std::string>& args, const fs::path& log) {
    return test::run_to_exit(CANDELA_CLI, args, log, kTimeout);
}

using Args = std::vector<std::string>;

// The Cornell box, small, to NAME.pfm and NAME.exr in `dir`, with `more` flags.
Args cornell(const fs::path& dir, const std::string& name, const std::string& spp, int threads, const Args& more = {}) {
    Args args = {"render", kCornell, "--resolution", "24x24", "--spp", spp, "--threads", std::to_string(threads),
                 "-o", (dir / (name + ".pfm")).string(), "-o", (dir / (name + ".exr")).string()};
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

// The samples per pixel a stopped render reports ("N of 1000000 spp"); 0 when it does not.
uint32_t samples_done(const std::string& output) {
    std::smatch m;
    if (!std::regex_search(output, m, std::regex("(\\d+) of " + kEndless + " spp"))) return 0;
    return uint32_t(std::stoul(m[1]));
}

// Both images of `name` and `reference` in `dir` are byte for byte the same.
void expect_same_images(const fs::path& dir, const std::string& name, const std::string& reference) {
    for (const char* ext : {".pfm", ".exr"}) {
        const std::string a = read_bytes(dir / (name + ext)), b = read_bytes(dir / (reference + ext));
        EXPECT_FALSE(a.empty()) << name << ext;
        EXPECT_TRUE(a == b) << name << ext << " differs from " << reference << ext;
    }
}

// Resumes `checkpoint` to `spp` with one thread and compares with an uninterrupted render on three.
void expect_resume_is_bit_identical(const fs::path& dir, const fs::path& checkpoint, uint32_t spp) {
    const std::string s = std::to_string(spp);
    CliRun resumed = run(cornell(dir, "resumed", s, 1, {"--resume", checkpoint.string()}), dir / "resumed.log");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("resuming from " + checkpoint.string()), std::string::npos) << resumed.output;
    CliRun reference = run(cornell(dir, "reference", s, 3), dir / "reference.log");
    ASSERT_EQ(reference.exit_code, 0) << reference.output;
    expect_same_images(dir, "resumed", "reference");
}

// Starts an endless render with periodic checkpoints and waits until the first is written (so
// the render is under way); the test then stops it.
class RunningRender {
  public:
    RunningRender(const fs::path& dir, const std::string& every)
        : checkpoint_(dir / "stopped.pfm.ckpt"),
          process_(CANDELA_CLI, cornell(dir, "stopped", kEndless, 2, {"--checkpoint-every", every}),
                   dir / "stopped.log") {
        started_ = wait_until([&] { return fs::exists(checkpoint_); }, kTimeout);
        EXPECT_TRUE(started_) << "no checkpoint appeared: " << process_.output();
    }
    bool started() const { return started_; }
    ChildProcess& process() { return process_; }
    const fs::path& checkpoint() const { return checkpoint_; }

  private:
    fs::path checkpoint_;
    ChildProcess process_;
    bool started_ = false;
};

void expect_stop_by_signal(const std::string& name, int signal, int expected_exit, const char* signal_name) {
    const fs::path dir = temp_dir(name);
    RunningRender r(dir, "0.1");
    ASSERT_TRUE(r.started());
    r.process().signal(signal);
    const int code = r.process().wait_exit(kTimeout);
    const std::string out = r.process().output();
    ASSERT_EQ(code, expected_exit) << out;
    EXPECT_NE(out.find(std::string("stopped by ") + signal_name), std::string::npos) << out;
    EXPECT_NE(out.find("continue with --resume " + r.checkpoint().string()), std::string::npos) << out;
    const uint32_t done = samples_done(out);
    ASSERT_GT(done, 0u) << out;
    EXPECT_EQ(read_checkpoint(r.checkpoint()).state.samples_done, done);
    // The saved image is that of the samples done...
    CliRun partial = run(cornell(dir, "partial", std::to_string(done), 3), dir / "partial.log");
    ASSERT_EQ(partial.exit_code, 0) << partial.output;
    expect_same_images(dir, "stopped", "partial");
    // ...and the render goes on to exactly the uninterrupted result.
    expect_resume_is_bit_identical(dir, r.checkpoint(), done + 5);
}

TEST(Interrupt, SigintSavesExitsWith130AndResumesBitIdentically) {
    expect_stop_by_signal("sigint", SIGINT, 130, "SIGINT");
}

TEST(Interrupt, SigtermSavesExitsWith143AndResumesBitIdentically) {
    expect_stop_by_signal("sigterm", SIGTERM, 143, "SIGTERM");
}

TEST(Interrupt, TimeLimitSavesExitsWithZeroAndResumesBitIdentically) {
    const fs::path dir = temp_dir("time_limit");
    CliRun r = test::run_stopped_after_a_pass(
        [&](const std::string& limit) {
            return run(cornell(dir, "stopped", kEndless, 2, {"--time-limit", limit}), dir / "stopped.log");
        },
        0.5);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("stopped at the time limit"), std::string::npos) << r.output;
    const uint32_t done = samples_done(r.output);
    ASSERT_GT(done, 0u) << r.output;
    EXPECT_TRUE(fs::exists(dir / "stopped.pfm"));
    expect_resume_is_bit_identical(dir, dir / "stopped.pfm.ckpt", done + 3);
}

TEST(Interrupt, SecondSignalQuitsAtOnceLeavingTheLastCheckpoint) {
    const fs::path dir = temp_dir("second_signal");
    RunningRender r(dir, "0.3");
    ASSERT_TRUE(r.started());
    // Both signals arrive while the process is stopped, so they are handled one right after the
    // other when it continues, before it could save anything: the second must quit.
    r.process().signal(SIGSTOP);
    ASSERT_TRUE(wait_until([&] { return r.process().is_stopped(); }, kTimeout));
    r.process().signal(SIGINT);
    r.process().signal(SIGTERM);
    r.process().signal(SIGCONT);
    const int code = r.process().wait_exit(kTimeout);
    const std::string out = r.process().output();
    EXPECT_TRUE(code == 130 || code == 143) << code << ": " << out;
    EXPECT_NE(out.find("second signal: quitting without saving"), std::string::npos) << out;
    EXPECT_EQ(out.find("wrote"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(dir / "stopped.pfm"));
    // The last periodic checkpoint is whole and continues the render.
    const uint32_t done = read_checkpoint(r.checkpoint()).state.samples_done;
    ASSERT_GT(done, 0u);
    expect_resume_is_bit_identical(dir, r.checkpoint(), done + 2);
}

// A shard of the Cornell box (part `which`, 2 of 3 unless said, of a 40x24 film) to `part`, with
// `more` flags.
Args shard(const fs::path& part, const std::string& spp, int threads, const Args& more = {},
           const std::string& which = "2/3") {
    Args args = {"render", kCornell, "--resolution", "40x24", "--spp", spp, "--threads", std::to_string(threads),
                 "--shard", which, "-o", part.string()};
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

// Resumes the stopped part to `spp` with one thread and compares its file with that of the part
// rendered at once on three: byte for byte.
void expect_part_resume_is_bit_identical(const fs::path& dir, const fs::path& part, uint32_t spp,
                                         const Args& more = {}, const std::string& which = "2/3") {
    const std::string s = std::to_string(spp);
    Args resume = more;
    resume.insert(resume.end(), {"--resume", part.string()});
    CliRun resumed = run(shard(part, s, 1, resume, which), dir / "resumed.log");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("resuming from " + part.string()), std::string::npos) << resumed.output;
    CliRun reference = run(shard(dir / "reference.ckpt", s, 3, more, which), dir / "reference.log");
    ASSERT_EQ(reference.exit_code, 0) << reference.output;
    const std::string a = read_bytes(part);
    EXPECT_FALSE(a.empty());
    EXPECT_TRUE(a == read_bytes(dir / "reference.ckpt")) << "the resumed part differs from the uninterrupted one";
}

TEST(Interrupt, ShardStoppedAtTheTimeLimitResumesToTheUninterruptedPart) {
    const fs::path dir = temp_dir("shard_time_limit");
    const fs::path part = dir / "part-2.ckpt";
    CliRun r = test::run_stopped_after_a_pass(
        [&](const std::string& limit) {
            return run(shard(part, kEndless, 2, {"--time-limit", limit}), dir / "stopped.log");
        },
        0.5);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("stopped at the time limit"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("continue with --shard 2/3 --resume " + part.string() + " -o " + part.string()),
              std::string::npos)
        << r.output;
    const uint32_t done = samples_done(r.output);
    ASSERT_GT(done, 0u) << r.output;
    // An incomplete part is no part to merge...
    CliRun merge = run({"merge", part.string(), "-o", (dir / "m.exr").string()}, dir / "merge.log");
    EXPECT_EQ(merge.exit_code, 2) << merge.output;
    EXPECT_NE(merge.output.find(part.string() + ": part 2 of 3 is incomplete: " + std::to_string(done) + " of " +
                                kEndless + " spp done; finish it with candela render SCENE --shard 2/3 --resume"),
              std::string::npos)
        << merge.output;
    // ...but goes on to exactly the uninterrupted part.
    expect_part_resume_is_bit_identical(dir, part, done + 3);
}

TEST(Interrupt, ShardStoppedBySigintAfterPeriodicPartFilesResumesToTheUninterruptedPart) {
    const fs::path dir = temp_dir("shard_sigint");
    const fs::path part = dir / "part-2.ckpt";
    ChildProcess p(CANDELA_CLI, shard(part, kEndless, 2, {"--checkpoint-every", "0.1"}), dir / "stopped.log");
    ASSERT_TRUE(wait_until([&] { return fs::exists(part); }, kTimeout)) << "no periodic part file: " << p.output();
    p.signal(SIGINT);
    ASSERT_EQ(p.wait_exit(kTimeout), 130) << p.output();
    const std::string out = p.output();
    EXPECT_NE(out.find("stopped by SIGINT"), std::string::npos) << out;
    const uint32_t done = samples_done(out);
    ASSERT_GT(done, 0u) << out;
    expect_part_resume_is_bit_identical(dir, part, done + 2);
}

// An adaptive part (its statistics and settings in the part file) stopped at the time limit goes
// on, past at least one more decision point, to exactly the uninterrupted part. Part 1 of 3: it
// has blocks that stop at min_spp (black) and blocks that go on (part 2 is all black).
TEST(Interrupt, AdaptiveShardStoppedAtTheTimeLimitResumesToTheUninterruptedPart) {
    const fs::path dir = temp_dir("adaptive_shard_time_limit");
    const fs::path part = dir / "part-1.ckpt";
    const Args adaptive = {"--noise-threshold", "0.003", "--min-spp", "4", "--aov", "spp"};
    CliRun r = test::run_stopped_after_a_pass(
        [&](const std::string& limit) {
            Args stopped = adaptive;
            stopped.insert(stopped.end(), {"--time-limit", limit});
            return run(shard(part, kEndless, 2, stopped, "1/3"), dir / "stopped.log");
        },
        0.5);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("stopped at the time limit"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" min 4 max "), std::string::npos) << r.output;
    const uint32_t done = samples_done(r.output);
    ASSERT_GT(done, 0u) << r.output;
    // Blocks still sampling: no part to merge yet.
    CliRun merge = run({"merge", part.string(), "-o", (dir / "m.exr").string()}, dir / "merge.log");
    EXPECT_EQ(merge.exit_code, 2) << merge.output;
    EXPECT_NE(merge.output.find(part.string() + ": part 1 of 3 is incomplete: " + std::to_string(done) + " of " +
                                kEndless + " spp done and pixels still sampling"),
              std::string::npos)
        << merge.output;
    expect_part_resume_is_bit_identical(dir, part, done + done / 8 + 8, adaptive, "1/3");
}

// A small scene of its own, so that the test can change it.
void write_scene(const fs::path& file, const std::string& albedo) {
    std::ofstream(file) << R"({"sampler": {"spp": 4}, "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0],
  "resolution": [8, 8]}, "materials": {"m": {"type": "diffuse", "albedo": )"
                        << albedo << R"(}}, "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
  "material": "m"}], "lights": [{"type": "environment", "color": [1, 1, 1]}]})";
}

TEST(Interrupt, ResumeRefusesACheckpointOfAnotherRender) {
    const fs::path dir = temp_dir("refuse");
    const fs::path scene = dir / "scene.json", ckpt = dir / "c.ckpt";
    write_scene(scene, "0.5");
    const Args base = {"render", scene.string(), "-o", (dir / "a.pfm").string()};
    auto with = [&](const Args& more) {
        Args args = base;
        args.insert(args.end(), more.begin(), more.end());
        return args;
    };
    CliRun first = run(with({"--checkpoint", ckpt.string()}), dir / "first.log");
    ASSERT_EQ(first.exit_code, 0) << first.output;
    ASSERT_TRUE(fs::exists(ckpt)) << "a render given --checkpoint writes one at the end";

    const std::string refused = "candela: error: " + ckpt.string() + ": cannot resume: ";
    struct Case {
        Args flags;
        const char* reason;
    };
    const Case cases[] = {
        {{"--seed", "9"}, "seed 0, this render seed 9"},
        {{"--resolution", "9x8"}, "the checkpoint is 8x8, this render 9x8"},
        {{"--integrator", "bsdf"}, "integrator path, this render bsdf"},
    };
    for (const Case& c : cases) {
        Args flags = c.flags;
        flags.insert(flags.end(), {"--resume", ckpt.string()});
        CliRun r = run(with(flags), dir / "r.log");
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_EQ(r.output.rfind(refused, 0), 0u) << r.output;
        EXPECT_NE(r.output.find(c.reason), std::string::npos) << r.output;
    }
    write_scene(scene, "0.6");
    CliRun changed = run(with({"--resume", ckpt.string()}), dir / "r.log");
    EXPECT_EQ(changed.exit_code, 2) << changed.output;
    EXPECT_NE(changed.output.find(refused + "the checkpoint is of a different scene"), std::string::npos)
        << changed.output;

    std::ofstream(dir / "junk.ckpt") << "not a checkpoint at all";
    CliRun junk = run(with({"--resume", (dir / "junk.ckpt").string()}), dir / "r.log");
    EXPECT_EQ(junk.exit_code, 2) << junk.output;
    EXPECT_NE(junk.output.find((dir / "junk.ckpt").string() + ": not a candela checkpoint"), std::string::npos)
        << junk.output;
    CliRun missing = run(with({"--resume", (dir / "none.ckpt").string()}), dir / "r.log");
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    EXPECT_NE(missing.output.find("none.ckpt: checkpoint not found"), std::string::npos) << missing.output;
}

TEST(Interrupt, ResumePastTheRequestedSamplesWritesItsImage) {
    const fs::path dir = temp_dir("past");
    const fs::path scene = dir / "scene.json", ckpt = dir / "c.ckpt";
    write_scene(scene, "0.5");
    CliRun four = run({"render", scene.string(), "-o", (dir / "four.pfm").string(), "--checkpoint", ckpt.string()},
                      dir / "four.log");
    ASSERT_EQ(four.exit_code, 0) << four.output;
    CliRun again = run({"render", scene.string(), "--spp", "2", "-o", (dir / "again.pfm").string(), "--resume",
                        ckpt.string()},
                       dir / "again.log");
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find("4 of 2 spp done, nothing left to render"), std::string::npos) << again.output;
    EXPECT_TRUE(read_bytes(dir / "again.pfm") == read_bytes(dir / "four.pfm"));
}

TEST(Interrupt, BadSecondsAreBadFlags) {
    const fs::path dir = temp_dir("bad_flags");
    for (const char* flag : {"--time-limit", "--checkpoint-every"}) {
        for (const char* value : {"0", "-1", "nan", "inf"}) {
            CliRun r = run({"render", kCornell, flag, value, "-o", (dir / "x.png").string()}, dir / "r.log");
            EXPECT_EQ(r.exit_code, 2) << flag << " " << value << ": " << r.output;
        }
    }
}

}  // namespace
}  // namespace candela
