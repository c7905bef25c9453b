#include "candela/distributed/mpi_launch.h"

#include <cstdlib>
#include <string>

namespace candela {

std::optional<int> mpi_launch_size() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
        if (const char* value = std::getenv(name)) {
            try {
                return std::stoi(value);
            } catch (const std::exception&) {
                return 0;
            }
        }
    }
    if (std::getenv("PMIX_RANK")) return 0;
    return std::nullopt;
}

}  // namespace candela
