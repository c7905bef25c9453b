// Telling from the environment whether an MPI launcher started this process (how a candela built
// without MPI knows to refuse to run as N copies that would each render the whole image).
#include "candela/distributed/mpi_launch.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace candela {
namespace CANDELA_UNITY_ID {

// Clears the launchers' variables for a test and restores nothing: each test sets what it needs.
void clear_launcher_variables() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) unsetenv(name);
}

TEST(MpiLaunch, NoLauncherMeansNoSize) {
    clear_launcher_variables();
    EXPECT_FALSE(mpi_launch_size());
}

TEST(MpiLaunch, ReadsOpenMpisAndPmisWorldSize) {
    clear_launcher_variables();
    setenv("OMPI_COMM_WORLD_SIZE", "4", 1);
    EXPECT_EQ(mpi_launch_size(), 4);
    clear_launcher_variables();
    setenv("PMI_SIZE", "16", 1);
    EXPECT_EQ(mpi_launch_size(), 16);
    clear_launcher_variables();
}

TEST(MpiLaunch, APmixRankOrAGarbledSizeCountsAsLaunchedWithSizeUnknown) {
    clear_launcher_variables();
    setenv("PMIX_RANK", "0", 1);
    EXPECT_EQ(mpi_launch_size(), 0);
    clear_launcher_variables();
    setenv("OMPI_COMM_WORLD_SIZE", "many", 1);
    EXPECT_EQ(mpi_launch_size(), 0);
    clear_launcher_variables();
}

}  // namespace
}  // namespace candela
