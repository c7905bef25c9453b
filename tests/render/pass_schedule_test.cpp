// Pass sizes: growing from one sample per pixel, at most doubling, to about the target length,
// never past the samples left or the deadline.
#include "candela/render/pass_schedule.h"

#include <gtest/gtest.h>

#include <optional>

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr double kTarget = 2.0;
constexpr std::optional<double> kNoDeadline = std::nullopt;

TEST(PassSchedule, FirstPassIsOneSample) {
    EXPECT_EQ(next_pass_spp({}, 1000, kTarget, kNoDeadline), 1u);
    EXPECT_EQ(next_pass_spp({}, 1000, kTarget, 100.0), 1u);
}

TEST(PassSchedule, GrowsAtMostTwofold) {
    // Fast passes (1 ms per sample per pixel) would allow 2000 at once: doubling limits them.
    EXPECT_EQ(next_pass_spp({1, 0.001}, 1000, kTarget, kNoDeadline), 2u);
    EXPECT_EQ(next_pass_spp({64, 0.064}, 1000, kTarget, kNoDeadline), 128u);
    // A pass that took no measurable time still only doubles.
    EXPECT_EQ(next_pass_spp({8, 0.0}, 1000, kTarget, kNoDeadline), 16u);
}

TEST(PassSchedule, SizedToTheTargetLength) {
    // 0.1 s per sample per pixel: 20 fit into 2 s.
    EXPECT_EQ(next_pass_spp({16, 1.6}, 1000, kTarget, kNoDeadline), 20u);
    // Slower than the target already: one sample per pixel per pass, never zero.
    EXPECT_EQ(next_pass_spp({1, 30.0}, 1000, kTarget, kNoDeadline), 1u);
}

TEST(PassSchedule, NeverMoreThanWhatIsLeft) {
    EXPECT_EQ(next_pass_spp({64, 0.064}, 5, kTarget, kNoDeadline), 5u);
    EXPECT_EQ(next_pass_spp({}, 1, kTarget, kNoDeadline), 1u);
    EXPECT_EQ(next_pass_spp({4, 0.0}, 3, kTarget, kNoDeadline, 10), 3u);
}

TEST(PassSchedule, FitsBeforeTheDeadline) {
    // 0.1 s per sample per pixel and 0.55 s left: 5 fit.
    EXPECT_EQ(next_pass_spp({16, 1.6}, 1000, kTarget, 0.55), 5u);
    // Not one fits (or the deadline has passed): stop now.
    EXPECT_EQ(next_pass_spp({16, 1.6}, 1000, kTarget, 0.05), 0u);
    EXPECT_EQ(next_pass_spp({16, 1.6}, 1000, kTarget, -1.0), 0u);
}

TEST(PassSchedule, FixedSizeForTests) {
    EXPECT_EQ(next_pass_spp({}, 1000, kTarget, kNoDeadline, 3), 3u);
    EXPECT_EQ(next_pass_spp({3, 100.0}, 1000, kTarget, kNoDeadline, 3), 3u);
}

}  // namespace
}  // namespace candela
