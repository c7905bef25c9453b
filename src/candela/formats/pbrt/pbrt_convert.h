#pragma once
// `candela convert`: writes the candela scene a pbrt-v4 scene imports as (its JSON document, with
// file names made relative to the output's folder) and its inline meshes as binary PLY files
// beside it (meshes/*.ply). Loading the written scene gives the same Scene, bit for bit, as
// loading the pbrt-v4 file (the meshes' floats are written exactly and finished the same way).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace candela::pbrt {

struct ConvertResult {
    std::vector<std::string> warnings;  // as loading the scene gives them
    size_t mesh_files = 0;
};

// Throws SceneError for a scene that does not load, or a file that cannot be written.
ConvertResult convert_pbrt_scene(const std::filesystem::path& in, const std::filesystem::path& out);

}  // namespace candela::pbrt
