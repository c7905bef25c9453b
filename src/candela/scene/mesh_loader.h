#pragma once
// Loads a triangle mesh file in object space, by extension: .obj (tinyobjloader) or .ply.
// Throws SceneError naming the file (and line, where the format has lines) on bad input.
#include <filesystem>

#include "candela/geometry/triangle_mesh.h"

namespace candela {

TriangleMesh load_mesh(const std::filesystem::path& file);

}  // namespace candela
