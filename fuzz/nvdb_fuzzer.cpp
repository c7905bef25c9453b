// libFuzzer target: bytes as a NanoVDB file (.nvdb) through our own reader: the table of contents
// (nanovdb_grid_names), then each grid it names (the first four) and "density" if it names none
// so, through read_nanovdb_grid under a 64 MiB budget. Seeds: the NanoVDB-written fixtures of
// tests/data/vdb/ (inflated by scripts/fuzz.sh). A SceneError is the expected answer to bad input;
// anything else is a bug, and so is a grid breaking the invariants below.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/formats/vdb/nanovdb_reader.h"
#include "candela/scene/memory_budget.h"
#include "fuzz_support.h"

namespace {

void require_valid_grid(const candela::VolumeGrid& g) {
    using candela::fuzz::require;
    require(g.nx >= 0 && g.ny >= 0 && g.nz >= 0, "the block's size is not negative");
    require(g.values.size() == g.voxel_count(), "the block holds nx*ny*nz values");
    require((g.voxel_count() == 0) == (g.nx == 0 && g.ny == 0 && g.nz == 0), "an empty block is 0x0x0");
    require(std::isfinite(g.background), "the background is finite");
    for (float v : g.values) require(std::isfinite(v), "every value is finite");
    for (const auto& row : g.index_to_world)
        for (double m : row) require(std::isfinite(m), "the map is finite");
    if (g.voxel_count() > 0)
        for (int a = 0; a < 3; ++a) require(g.world_min[a] <= g.world_max[a], "the world bounds are a box");
}

void read(const std::filesystem::path& file, const std::string& name) {
    candela::MemoryBudget budget(candela::MemoryLimit{uint64_t(64) << 20, "the fuzzer's limit"});
    try {
        require_valid_grid(candela::read_nanovdb_grid(file, name, budget));
    } catch (const candela::SceneError&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static candela::fuzz::ScratchFile scratch(".nvdb");
    const std::filesystem::path& file = scratch.write(data, size);
    std::vector<std::string> names;
    try {
        names = candela::nanovdb_grid_names(file);
    } catch (const candela::SceneError&) {
    }
    for (size_t i = 0; i < names.size() && i < 4; ++i) read(file, names[i]);
    if (std::find(names.begin(), names.end(), "density") == names.end()) read(file, "density");
    return 0;
}
