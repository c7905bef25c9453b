#pragma once
// Reads one float grid of an OpenVDB file (.vdb) into a dense VolumeGrid, through Debian's
// libopenvdb (io::File). The only file that includes OpenVDB's headers.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "candela/formats/vdb/volume_grid.h"

namespace candela {

class MemoryBudget;

// The grid named `grid_name`. The dense block is charged to `budget` before it is allocated (and,
// when the file's metadata says the grid's size, before its tree is read). Throws SceneError
// naming the file when OpenVDB cannot read it, it has no grid of that name (listing those it
// has), the grid is not a float grid, its transform is not affine (a frustum), a value is not
// finite, or the budget refuses it.
VolumeGrid read_openvdb_grid(const std::filesystem::path& path, std::string_view grid_name, MemoryBudget& budget);

// The names of the grids in an OpenVDB file, in file order; throws SceneError as above.
std::vector<std::string> openvdb_grid_names(const std::filesystem::path& path);

}  // namespace candela
