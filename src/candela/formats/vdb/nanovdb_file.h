#pragma once
// The table of contents of a NanoVDB file (nanovdb_layout.h): which grids it holds, of what type,
// and where their buffers lie, read from the segment headers (or raw grid headers) without
// reading any grid. Every size and offset is checked against the file's length.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace candela {

struct NanoVdbGridEntry {
    std::string name;
    uint32_t grid_type = 0;  // NanoVDB's GridType: 1 float, 2 double, ...
    uint16_t codec = 0;      // 0 none, 1 zip, 2 blosc
    uint64_t grid_size = 0;  // bytes of the grid buffer in memory
    uint64_t file_size = 0;  // bytes of it in the file
    uint64_t offset = 0;     // where it starts in the file
};

struct NanoVdbFile {
    std::string file;  // the path, for errors
    std::ifstream in;
    uint64_t size = 0;
    std::vector<NanoVdbGridEntry> grids;
};

// Opens `path` and reads its table of contents. Throws SceneError naming the file when it cannot
// be opened, is not a little-endian NanoVDB file of major version 32, or is truncated or corrupt.
NanoVdbFile open_nanovdb_file(const std::filesystem::path& path);

// The bytes of grid `entry` of `f` as they are in the file (its buffer when uncompressed).
std::string read_nanovdb_grid_bytes(NanoVdbFile& f, const NanoVdbGridEntry& entry);

// "float", "double", "Vec3f", ...: NanoVDB's name for a GridType.
std::string nanovdb_type_name(uint32_t grid_type);
// "none", "zip", "blosc".
std::string nanovdb_codec_name(uint16_t codec);

}  // namespace candela
