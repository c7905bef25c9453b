// The progress bar's arithmetic (render/progress.h): what it shows done, and the re-estimate that
// adaptive sampling makes at its decision points.
#include "candela/render/progress.h"

#include <gtest/gtest.h>

namespace candela {
namespace CANDELA_UNITY_ID {

TEST(ProgressBar, FractionIsTheWorkDone) {
    ProgressBar bar(200, false);
    EXPECT_EQ(bar.fraction(), 0.0);
    bar.advance(50, 0);
    EXPECT_EQ(bar.fraction(), 0.25);
    bar.advance(150, 0);
    EXPECT_EQ(bar.fraction(), 1.0);
    EXPECT_EQ(ProgressBar(0, false).fraction(), 1.0);  // nothing to do is done
}

// An adaptive render of 100 pixels x 8 spp: after 4 spp of all pixels, only 10 pixels still sample;
// the bar then fills with their 4 x 10 samples, and is full when they are taken.
TEST(ProgressBar, RemainingWorkReEstimatedFromTheActivePixels) {
    ProgressBar bar(100 * 8, false);
    bar.advance(100 * 4, 0);
    EXPECT_EQ(bar.fraction(), 0.5);
    bar.set_remaining(10 * 4);
    EXPECT_EQ(bar.fraction(), 400.0 / 440.0);
    bar.advance(10 * 4, 0);
    EXPECT_EQ(bar.fraction(), 1.0);
    bar.set_remaining(0);  // every block stopped
    EXPECT_EQ(bar.fraction(), 1.0);
}

}  // namespace
}  // namespace candela
