#pragma once
// Reads one float grid of a NanoVDB file (.nvdb) into a dense VolumeGrid, with our own reader of
// the file format (NanoVDB is not packaged for Debian; nanovdb_layout.h describes the format).
// Uncompressed files of NanoVDB's file format 32 (NanoVDB 32.3, as pbrt-v4 pins it, to 32.9),
// segment files and raw grid buffers; float grids only.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "candela/formats/vdb/volume_grid.h"

namespace candela {

class MemoryBudget;

// The grid named `grid_name` (the first one, if several share it). The dense block is charged to
// `budget` before it is allocated, and the grid's buffer as transient before it is read. Throws
// SceneError naming the file when the file cannot be read, is not NanoVDB, is truncated or
// corrupt, has no grid of that name (listing those it has), when the grid is compressed or not a
// float grid, or when the budget refuses it.
VolumeGrid read_nanovdb_grid(const std::filesystem::path& path, std::string_view grid_name, MemoryBudget& budget);

// The names of the grids in a NanoVDB file, in file order; throws SceneError as above.
std::vector<std::string> nanovdb_grid_names(const std::filesystem::path& path);

}  // namespace candela
