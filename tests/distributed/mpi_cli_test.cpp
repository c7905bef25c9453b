// `mpirun -np N candela render`: the bits of one process for N = 1, 2, 3 and any threads per rank
// (also with a weighted filter and a crop window); a stop under MPI resumes in one process and the
// other way round, bit-identically; SIGINT to mpirun saves the image and a checkpoint; a killed
// rank ends the job within seconds, naming it, and its last checkpoint resumes; a scene that does
// not load ends the job with exit 2 and the located error.
//
// CliRun as root (CI), Open MPI wants OMPI_ALLOW_RUN_AS_ROOT and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM set;
// .ci/run sets them and so does this test. --oversubscribe: more ranks than this machine's cores.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_run.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;
using test::ChildProcess;
using test::wait_until;
using Args = std::vector<std::string>;

constexpr double kTimeout = 120.0;  // seconds; only reached when something is broken
const std::string kCornellDir = std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box";
const std::string kCornell = kCornellDir + "/scene.json";
const std::string kEndless = "1000000";  // more samples than any test waits for

// Run as root, mpirun wants to be told that is meant. And in the sanitizer build (scripts/sanitize.sh),
// LeakSanitizer is off for the ranks: Open MPI keeps allocations to the end by design, many of
// them in its plug-ins, which it unloads before the leak check runs, so that they can be neither
// attributed nor suppressed. candela's own code is leak-checked by every other test.
class MpiEnvironment : public ::testing::Environment {
  public:
    void SetUp() override {
        setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
        setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
        const char* asan = std::getenv("ASAN_OPTIONS");
        setenv("ASAN_OPTIONS", ((asan ? std::string(asan) + ":" : std::string()) + "detect_leaks=0").c_str(), 1);
    }
};
const auto* const kEnvironment = ::testing::AddGlobalTestEnvironment(new MpiEnvironment);

fs::path temp_dir(const std::string& name) { return test::fresh_dir("mpi_" + name); }

using test::read_bytes;

using test::CliRun;

Args mpirun_args(int ranks, const Args& candela_args) {
    Args args = {"--oversubscribe", "-np", std::to_string(ranks), CANDELA_CLI};
    args.insert(args.end(), candela_args.begin(), candela_args.end());
    return args;
}

CliRun run_alone(const Args& args, const fs::path& log) { return test::run_to_exit(CANDELA_CLI, args, log, kTimeout); }

CliRun run_mpi(int ranks, const Args& args, const fs::path& log) {
    return test::run_to_exit(CANDELA_MPIEXEC, mpirun_args(ranks, args), log, kTimeout);
}

// The Cornell box (or `scene`), small, to NAME.exr and NAME.pfm in `dir`.
Args render_args(const fs::path& dir, const std::string& name, const std::string& spp, int threads,
                 const Args& more = {}, const std::string& scene = kCornell) {
    Args args = {"render", scene, "--resolution", "40x30", "--spp", spp, "--threads", std::to_string(threads),
                 "-o", (dir / (name + ".exr")).string(), "-o", (dir / (name + ".pfm")).string()};
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

void expect_same_images(const fs::path& dir, const std::string& name, const std::string& reference) {
    for (const char* ext : {".exr", ".pfm"}) {
        const std::string a = read_bytes(dir / (name + ext)), b = read_bytes(dir / (reference + ext));
        EXPECT_FALSE(a.empty()) << name << ext;
        EXPECT_TRUE(a == b) << name << ext << " differs from " << reference << ext;
    }
}

// The samples per pixel of a stopped render ("N of 1000000 spp"); 0 when it says none.
uint32_t samples_done(const std::string& output) {
    std::smatch m;
    if (!std::regex_search(output, m, std::regex("(\\d+) of " + kEndless + " spp"))) return 0;
    return uint32_t(std::stoul(m[1]));
}

TEST(MpiRender, GivesTheBitsOfOneProcessForEveryRankAndThreadCount) {
    const fs::path dir = temp_dir("bits");
    ASSERT_EQ(run_alone(render_args(dir, "one", "6", 2), dir / "one.log").exit_code, 0);
    struct Case {
        int ranks, threads;
    };
    for (Case c : {Case{1, 1}, Case{2, 1}, Case{3, 1}, Case{2, 2}, Case{3, 3}}) {
        const std::string name = "n" + std::to_string(c.ranks) + "t" + std::to_string(c.threads);
        const CliRun r = run_mpi(c.ranks, render_args(dir, name, "6", c.threads), dir / (name + ".log"));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        expect_same_images(dir, name, "one");
        if (c.ranks > 1) {
            EXPECT_NE(r.output.find(std::to_string(c.ranks) + " ranks"), std::string::npos) << r.output;
        }
        // One summary line: the other ranks print nothing (Open MPI may add notices of its own).
        size_t lines = 0;
        for (size_t at = r.output.find("candela:"); at != std::string::npos; at = r.output.find("candela:", at + 1))
            ++lines;
        EXPECT_EQ(lines, 1u) << r.output;
    }
    // Smaller tiles (more of them to share) change nothing either.
    const CliRun small = run_mpi(3, render_args(dir, "tiles5", "6", 1, {"--tile-size", "5"}), dir / "tiles5.log");
    ASSERT_EQ(small.exit_code, 0) << small.output;
    expect_same_images(dir, "tiles5", "one");
}

// Motion blur (scenes/motion-blur: moving shapes and a moving instance): each sample's time comes
// from the sampler, so ranks give one process's bits.
TEST(MpiRender, GivesTheBitsOfOneProcessWithMovingShapes) {
    const fs::path dir = temp_dir("motion");
    const std::string motion = std::string(CANDELA_SOURCE_DIR) + "/scenes/motion-blur/scene.json";
    ASSERT_EQ(run_alone(render_args(dir, "one", "2", 2, {}, motion), dir / "one.log").exit_code, 0);
    const CliRun r = run_mpi(2, render_args(dir, "two", "2", 1, {}, motion), dir / "two.log");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    expect_same_images(dir, "two", "one");
}

// Volpath in a scene with media (the fog room: fog around the camera, amber glass, a spot light):
// its medium walks draw from generators seeded by the sampler, so ranks give one process's bits.
TEST(MpiRender, GivesTheBitsOfOneProcessWithMedia) {
    const fs::path dir = temp_dir("media");
    const std::string fog = std::string(CANDELA_SOURCE_DIR) + "/scenes/fog-room/scene.json";
    for (const char* mode : {"--rgb", "--spectral"}) {
        const std::string one = std::string("one") + (mode[2] == 'r' ? "_rgb" : "_spectral");
        const std::string two = std::string("two") + (mode[2] == 'r' ? "_rgb" : "_spectral");
        ASSERT_EQ(run_alone(render_args(dir, one, "2", 2, {mode}, fog), dir / (one + ".log")).exit_code, 0);
        const CliRun r = run_mpi(2, render_args(dir, two, "2", 1, {mode}, fog), dir / (two + ".log"));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        expect_same_images(dir, two, one);
    }
}

TEST(MpiRender, GivesTheBitsOfOneProcessWithAWeightedFilterAndACropWindow) {
    const fs::path dir = temp_dir("weighted");
    // The Cornell box with pbrt-v4's Mitchell filter (weighted samples: the film keeps weight
    // sums, 32 bytes per pixel) and a crop window.
    std::string json = read_bytes(kCornell);
    json = std::regex_replace(json, std::regex("\"meshes/"), "\"" + kCornellDir + "/meshes/");
    json = std::regex_replace(json, std::regex("\"filter\": \"tent\""),
                              "\"filter\": {\"type\": \"mitchell\"}, \"crop_window\": [0.1, 0.8, 0.2, 1]");
    ASSERT_NE(json.find("mitchell"), std::string::npos);
    const fs::path scene = dir / "scene.json";
    std::ofstream(scene) << json;
    ASSERT_EQ(run_alone(render_args(dir, "one", "5", 2, {}, scene.string()), dir / "one.log").exit_code, 0);
    const CliRun r = run_mpi(3, render_args(dir, "three", "5", 1, {}, scene.string()), dir / "three.log");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    expect_same_images(dir, "three", "one");
}

TEST(MpiRender, APartRenderedOnRanksMergesWithAPartRenderedAlone) {
    const fs::path dir = temp_dir("shard");
    ASSERT_EQ(run_alone(render_args(dir, "whole", "5", 2), dir / "whole.log").exit_code, 0);
    const Args part = {"render", kCornell, "--resolution", "40x30", "--spp", "5", "--threads", "1"};
    Args first = part, second = part;
    first.insert(first.end(), {"--shard", "1/2", "-o", (dir / "part-1.ckpt").string()});
    second.insert(second.end(), {"--shard", "2/2", "-o", (dir / "part-2.ckpt").string()});
    const CliRun ranks = run_mpi(3, first, dir / "part-1.log");
    ASSERT_EQ(ranks.exit_code, 0) << ranks.output;
    ASSERT_EQ(run_alone(second, dir / "part-2.log").exit_code, 0);
    const CliRun merged = run_alone({"merge", (dir / "part-1.ckpt").string(), (dir / "part-2.ckpt").string(), "-o",
                                     (dir / "merged.exr").string(), "-o", (dir / "merged.pfm").string()},
                                    dir / "merge.log");
    ASSERT_EQ(merged.exit_code, 0) << merged.output;
    expect_same_images(dir, "merged", "whole");
}

// AOV layers travel with the film's values (Film::values_per_pixel): the EXR's layers and the
// files beside the .pfm are the bits of one process.
TEST(MpiRender, GivesTheAovLayersOfOneProcess) {
    const fs::path dir = temp_dir("aovs");
    const Args aovs = {"--aov", "albedo,normal,depth,position"};
    ASSERT_EQ(run_alone(render_args(dir, "one", "3", 2, aovs), dir / "one.log").exit_code, 0);
    const CliRun r = run_mpi(3, render_args(dir, "three", "3", 1, aovs), dir / "three.log");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    expect_same_images(dir, "three", "one");
    for (const char* layer : {".albedo.pfm", ".normal.pfm", ".depth.pfm", ".position.pfm"}) {
        const std::string a = read_bytes(dir / (std::string("three") + layer));
        EXPECT_FALSE(a.empty()) << layer;
        EXPECT_TRUE(a == read_bytes(dir / (std::string("one") + layer))) << layer;
    }
}

TEST(MpiRender, ProgressShowsTheWholeJobWhenAskedFor) {
    const fs::path dir = temp_dir("progress");
    // Under mpirun stderr is never a terminal: no bar unless --progress, then one for the job.
    const CliRun quiet = run_mpi(2, render_args(dir, "quiet", "4", 1), dir / "quiet.log");
    ASSERT_EQ(quiet.exit_code, 0) << quiet.output;
    EXPECT_EQ(quiet.output.find('%'), std::string::npos) << quiet.output;
    const CliRun shown = run_mpi(2, render_args(dir, "shown", "4", 1, {"--progress"}), dir / "shown.log");
    ASSERT_EQ(shown.exit_code, 0) << shown.output;
    EXPECT_NE(shown.output.find("100.0%"), std::string::npos) << shown.output;
    // The bar's last line ends before the summary line.
    EXPECT_NE(shown.output.find("rays/s\ncandela: 40x30"), std::string::npos) << shown.output;
}

TEST(MpiRender, AdaptiveSamplingAndATargetErrorGiveTheBitsOfOneProcess) {
    const fs::path dir = temp_dir("adaptive");
    // Blocks stop at the decision points: the MPI renderer cuts its passes there and decides from
    // the same sums. The variance and spp layers show where the samples went.
    const Args adaptive = {"--noise-threshold", "0.2", "--min-spp", "8", "--aov", "variance,spp"};
    ASSERT_EQ(run_alone(render_args(dir, "one", "48", 2, adaptive), dir / "one.log").exit_code, 0);
    const CliRun r = run_mpi(3, render_args(dir, "three", "48", 1, adaptive), dir / "three.log");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    expect_same_images(dir, "three", "one");
    // Blocks did stop early (else this would test nothing adaptive), and the estimates agree.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex("relMSE ~([0-9.e-]+), spp mean ([0-9.]+) min (\\d+) max (\\d+)")))
        << r.output;
    EXPECT_LT(std::stoi(m[3]), 48) << r.output;
    std::smatch one;
    const std::string one_log = read_bytes(dir / "one.log");
    ASSERT_TRUE(std::regex_search(one_log, one, std::regex("relMSE ~[0-9.e-]+, spp mean [0-9.]+ min \\d+ max \\d+")));
    EXPECT_NE(r.output.find(one.str()), std::string::npos) << one_log << r.output;

    const Args target = {"--target-error", "0.02"};
    const CliRun alone = run_alone(render_args(dir, "t_one", "4096", 2, target), dir / "t_one.log");
    ASSERT_EQ(alone.exit_code, 0) << alone.output;
    const CliRun ranks = run_mpi(2, render_args(dir, "t_two", "4096", 1, target), dir / "t_two.log");
    ASSERT_EQ(ranks.exit_code, 0) << ranks.output;
    expect_same_images(dir, "t_two", "t_one");
    EXPECT_NE(ranks.output.find("(converged)"), std::string::npos) << ranks.output;
}

TEST(MpiRender, AStopUnderMpiResumesInOneProcessAndTheOtherWayRound) {
    const fs::path dir = temp_dir("resume");
    // Stopped by the time limit on 3 ranks, resumed alone.
    const CliRun stopped = test::run_stopped_after_a_pass(
        [&](const std::string& limit) {
            return run_mpi(3, render_args(dir, "a", kEndless, 1, {"--time-limit", limit}), dir / "a.log");
        },
        1.0);
    ASSERT_EQ(stopped.exit_code, 0) << stopped.output;
    const uint32_t done = samples_done(stopped.output);
    ASSERT_GT(done, 0u) << stopped.output;
    const std::string spp = std::to_string(done + 3);
    ASSERT_EQ(run_alone(render_args(dir, "a_resumed", spp, 2, {"--resume", (dir / "a.exr.ckpt").string()}),
                        dir / "a_resumed.log").exit_code, 0);
    ASSERT_EQ(run_alone(render_args(dir, "a_whole", spp, 2), dir / "a_whole.log").exit_code, 0);
    expect_same_images(dir, "a_resumed", "a_whole");

    // Stopped alone, resumed on 2 ranks of 2 threads.
    const CliRun alone = test::run_stopped_after_a_pass(
        [&](const std::string& limit) {
            return run_alone(render_args(dir, "b", kEndless, 1, {"--time-limit", limit}), dir / "b.log");
        },
        1.0);
    ASSERT_EQ(alone.exit_code, 0) << alone.output;
    const uint32_t done_alone = samples_done(alone.output);
    ASSERT_GT(done_alone, 0u) << alone.output;
    const std::string spp_b = std::to_string(done_alone + 3);
    const CliRun resumed = run_mpi(2, render_args(dir, "b_resumed", spp_b, 2, {"--resume", (dir / "b.exr.ckpt").string()}),
                                dir / "b_resumed.log");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    ASSERT_EQ(run_alone(render_args(dir, "b_whole", spp_b, 2), dir / "b_whole.log").exit_code, 0);
    expect_same_images(dir, "b_resumed", "b_whole");
}

TEST(MpiRender, SigintToMpirunSavesTheImageAndACheckpoint) {
    const fs::path dir = temp_dir("sigint");
    const fs::path checkpoint = dir / "s.exr.ckpt";
    ChildProcess p(CANDELA_MPIEXEC, mpirun_args(2, render_args(dir, "s", kEndless, 1, {"--checkpoint-every", "0.2"})),
                   dir / "s.log");
    ASSERT_TRUE(wait_until([&] { return fs::exists(checkpoint); }, kTimeout)) << p.output();
    fs::remove(checkpoint);
    p.signal(SIGINT);
    // mpirun (Open MPI 4.1) sends the ranks SIGTERM a second later and exits 1 itself.
    EXPECT_NE(p.wait_exit(30), 0);
    const std::string output = p.output();
    EXPECT_NE(output.find("stopped by SIGTERM"), std::string::npos) << output;
    ASSERT_TRUE(fs::exists(checkpoint)) << output;
    ASSERT_TRUE(fs::exists(dir / "s.exr")) << output;
    const uint32_t done = samples_done(output);
    ASSERT_GT(done, 0u) << output;
    const std::string spp = std::to_string(done + 2);
    ASSERT_EQ(run_alone(render_args(dir, "resumed", spp, 2, {"--resume", checkpoint.string()}), dir / "r.log").exit_code,
              0);
    ASSERT_EQ(run_alone(render_args(dir, "whole", spp, 2), dir / "w.log").exit_code, 0);
    expect_same_images(dir, "resumed", "whole");
}

// The process of rank `rank` among mpirun's children (Open MPI sets OMPI_COMM_WORLD_RANK in
// each rank's environment); 0 when there is none (yet).
pid_t rank_pid(pid_t mpirun, int rank) {
    const std::string wanted = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
    for (const fs::directory_entry& e : fs::directory_iterator("/proc")) {
        const std::string name = e.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::istringstream stat(read_bytes(e.path() / "stat"));
        std::string field;
        const std::string text = stat.str();
        const size_t paren = text.rfind(')');
        if (paren == std::string::npos) continue;
        std::istringstream rest(text.substr(paren + 2));
        std::string state;
        pid_t parent = 0;
        rest >> state >> parent;
        if (parent != mpirun) continue;
        std::string environ = read_bytes(e.path() / "environ");
        std::replace(environ.begin(), environ.end(), '\0', '\n');
        if (std::regex_search(environ, std::regex("(^|\n)" + wanted + "\n"))) return pid_t(std::stoi(name));
    }
    return 0;
}

TEST(MpiRender, AKilledRankEndsTheJobAndItsLastCheckpointResumes) {
    const fs::path dir = temp_dir("kill");
    const fs::path checkpoint = dir / "k.exr.ckpt";
    ChildProcess p(CANDELA_MPIEXEC, mpirun_args(3, render_args(dir, "k", kEndless, 1, {"--checkpoint-every", "0.2"})),
                   dir / "k.log");
    ASSERT_TRUE(wait_until([&] { return fs::exists(checkpoint); }, kTimeout)) << p.output();
    const pid_t victim = rank_pid(p.pid(), 1);
    ASSERT_GT(victim, 0) << "rank 1 not found among mpirun's children";
    kill(victim, SIGKILL);
    const auto killed = std::chrono::steady_clock::now();
    EXPECT_NE(p.wait_exit(30), 0);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - killed).count(), 10.0);
    const std::string output = p.output();
    EXPECT_TRUE(std::regex_search(output, std::regex("rank 1 .*(exited|killed|Killed)"))) << output;
    // The last checkpoint (periodic, or rank 0's when mpirun stopped it) resumes the job.
    ASSERT_TRUE(fs::exists(checkpoint));
    const CliRun probe = run_alone({"render", kCornell, "--resolution", "40x30", "--spp", "1", "--threads", "1", "--resume",
                                 checkpoint.string(), "-o", (dir / "probe.exr").string()},
                                dir / "probe.log");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(probe.output, m, std::regex("(\\d+) of 1 spp done"))) << probe.output;
    const std::string spp = std::to_string(std::stoul(m[1]) + 2);
    ASSERT_EQ(run_alone(render_args(dir, "finished", spp, 2, {"--resume", checkpoint.string()}), dir / "f.log").exit_code,
              0);
    ASSERT_EQ(run_alone(render_args(dir, "whole", spp, 2), dir / "w.log").exit_code, 0);
    expect_same_images(dir, "finished", "whole");
}

TEST(MpiRender, ASceneThatDoesNotLoadEndsTheJobWithItsError) {
    const fs::path dir = temp_dir("bad");
    const fs::path scene = dir / "broken.json";
    std::ofstream(scene) << "{\n  \"sampler\": {\"spp\": -4}\n}\n";
    const auto start = std::chrono::steady_clock::now();
    const CliRun r = run_mpi(3, {"render", scene.string(), "-o", (dir / "x.exr").string()}, dir / "bad.log");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
    EXPECT_TRUE(std::regex_search(r.output, std::regex("rank \\d of 3 .*broken\\.json:2"))) << r.output;
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

}  // namespace
}  // namespace candela
