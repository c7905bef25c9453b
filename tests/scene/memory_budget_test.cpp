// Memory estimates and the budget they are charged to (scene/memory_budget.h).
#include "candela/scene/memory_budget.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "candela/film/film.h"
#include "candela/geometry/accelerator.h"
#include "candela/scene/scene.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr uint64_t kMiB = uint64_t(1) << 20;
constexpr uint64_t kGiB = uint64_t(1) << 30;

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(MemoryEstimate, FilmTakes72BytesPerPixel) {
    EXPECT_EQ(film_memory_bytes(640, 480), uint64_t(640) * 480 * 72);
    // The largest film a scene may ask for: 32768^2 pixels, 72 GiB.
    EXPECT_EQ(film_memory_bytes(32768, 32768), 72 * kGiB);
    EXPECT_EQ(film_memory_bytes(0, 480), 0u);
}

TEST(MemoryEstimate, AovLayersAddTheirSumsAndImages) {
    EXPECT_EQ(aov_memory_bytes(640, 480, AovLayers{}), 0u);
    AovLayers aovs;
    aovs.add(AovLayer::kAlbedo);
    aovs.add(AovLayer::kDepth);
    // (3 + 1) doubles in two films, and two resolved layers with their outputs.
    EXPECT_EQ(aov_memory_bytes(640, 480, aovs), uint64_t(640) * 480 * (4 * 16 + 2 * 24));
}

// The statistics are charged once, whichever of adaptive sampling, the variance or spp layer and
// --target-error (the `statistics` argument) asks for them.
TEST(MemoryEstimate, StatisticsAreChargedWhenAnythingAsksForThem) {
    Scene scene;
    scene.camera.width = 640;
    scene.camera.height = 480;
    const uint64_t plain = scene_memory_bytes(scene), stats = film_statistics_memory_bytes(640, 480);
    EXPECT_EQ(stats, uint64_t(640) * 480 * 2 * 72);  // both films of a pass (film.h)
    EXPECT_EQ(scene_memory_bytes(scene, true), plain + stats);
    scene.sampler.adaptive = AdaptiveSettings{};
    EXPECT_EQ(scene_memory_bytes(scene), plain + stats);
    EXPECT_EQ(scene_memory_bytes(scene, true), plain + stats);
}

TEST(MemoryEstimate, MeshGrowsWithCountsAndAttributes) {
    const uint64_t plain = mesh_memory_bytes(1000, 2000, false, false);
    EXPECT_EQ(plain, 1000u * 24 + 2000u * 152);
    EXPECT_EQ(mesh_memory_bytes(1000, 2000, true, false), plain + 1000u * 12);
    EXPECT_EQ(mesh_memory_bytes(1000, 2000, true, true), plain + 1000u * 20);
    EXPECT_GT(mesh_memory_bytes(1000, 2001, false, false), plain);
    // Meshes beyond the normal table's size do without it (geometry/accelerator.h).
    const uint64_t big = kMaxTrianglesWithNormalTable + 1;
    EXPECT_EQ(mesh_memory_bytes(1000, big, false, false), 1000u * 24 + big * 140);
}

TEST(MemoryEstimate, SaturatesInsteadOfWrapping) {
    // A header may claim any count; 2^62 triangles must not wrap to a small number.
    EXPECT_EQ(mesh_memory_bytes(0, uint64_t(1) << 62, false, false), UINT64_MAX);
    EXPECT_EQ(mesh_memory_bytes(UINT64_MAX, UINT64_MAX, true, true), UINT64_MAX);
    EXPECT_EQ(mesh_loading_memory_bytes(UINT64_MAX / 2, 1), UINT64_MAX);
}

TEST(MemoryEstimate, EnvironmentCountsImageCopyAndTables) {
    EXPECT_EQ(environment_memory_bytes(2048, 1024), uint64_t(2048) * 1024 * 36);
}

TEST(MemoryBudget, ChargesUntilTheLimitAndSaysWhatIsNeeded) {
    MemoryBudget budget(MemoryLimit{1000, "the test's limit is"});
    EXPECT_FALSE(budget.charge(600, "a film"));
    EXPECT_EQ(budget.used(), 600u);
    const std::optional<std::string> refused = budget.charge(500, "a mesh");
    ASSERT_TRUE(refused);
    EXPECT_EQ(*refused, "a mesh needs about 500 B of memory (1.1 KiB with what the scene holds already), but "
                        "the test's limit is 1000 B");
    EXPECT_EQ(budget.used(), 600u);  // a refused charge adds nothing
    EXPECT_FALSE(budget.charge(400, "a light"));
    EXPECT_EQ(budget.used(), 1000u);
}

TEST(MemoryBudget, TransientBytesAreCheckedButNotKept) {
    MemoryBudget budget(MemoryLimit{1000, "the test's limit is"});
    EXPECT_TRUE(budget.charge(100, "a mesh", 950));
    EXPECT_FALSE(budget.charge(100, "a mesh", 900));
    EXPECT_EQ(budget.used(), 100u);
}

TEST(MemoryBudget, FormatsBytesInBinaryUnits) {
    EXPECT_EQ(format_bytes(512), "512 B");
    EXPECT_EQ(format_bytes(1536), "1.5 KiB");
    EXPECT_EQ(format_bytes(48 * kGiB), "48.0 GiB");
    EXPECT_EQ(format_bytes(UINT64_MAX), "16.0 EiB");
}

TEST(MemoryBudget, ParsesByteCounts) {
    EXPECT_EQ(parse_byte_count("4096"), 4096u);
    EXPECT_EQ(parse_byte_count("4096B"), 4096u);
    EXPECT_EQ(parse_byte_count("512M"), 512u << 20);
    EXPECT_EQ(parse_byte_count("8G"), 8 * kGiB);
    EXPECT_EQ(parse_byte_count("8g"), 8 * kGiB);
    EXPECT_EQ(parse_byte_count("8GB"), 8 * kGiB);
    EXPECT_EQ(parse_byte_count("8GiB"), 8 * kGiB);
    EXPECT_EQ(parse_byte_count("1T"), uint64_t(1) << 40);
    for (const char* bad : {"", "G", "0", "-1", "1.5G", "8X", "8 G", "8GG", "99999999999T"})
        EXPECT_FALSE(parse_byte_count(bad)) << bad;
}

TEST(MemoryLimit, IsAtMostThePhysicalMemory) {
    const MemoryLimit limit = MemoryLimit::of_this_process();
    const uint64_t physical = uint64_t(sysconf(_SC_PHYS_PAGES)) * uint64_t(sysconf(_SC_PAGESIZE));
    EXPECT_GT(limit.bytes, 0u);
    EXPECT_LE(limit.bytes, physical);
    EXPECT_FALSE(limit.source.empty());
}

TEST(MemoryLimit, AnAddressSpaceLimitLowersIt) {
    // In a child, so the limit does not reach the other tests. The limit counts the address
    // space already used (large under a sanitizer), so it is set 256 MiB above that.
    const pid_t pid = fork();
    if (pid == 0) {
        std::ifstream statm("/proc/self/statm");
        uint64_t pages = 0;
        statm >> pages;
        const uint64_t used = pages * uint64_t(sysconf(_SC_PAGESIZE));
        const rlimit r{used + 256 * kMiB, RLIM_INFINITY};
        if (setrlimit(RLIMIT_AS, &r) != 0) _exit(2);
        const MemoryLimit limit = MemoryLimit::of_this_process();
        const bool ok = limit.bytes <= 256 * kMiB && contains(limit.source, "ulimit -v");
        _exit(ok ? 0 : 1);
    }
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: the limit was not lowered; 2: setrlimit failed";
}

}  // namespace
}  // namespace candela
