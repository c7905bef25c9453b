#pragma once
// Loads a triangle mesh file in object space, by extension (any case): .obj (tinyobjloader), .ply,
// or .ply.gz (a gzip-compressed PLY, as pbrt-v4 reads them).
// Throws SceneError naming the file (and line, where the format has lines) on bad input.
#include <filesystem>
#include <string>

#include "candela/geometry/triangle_mesh.h"
#include "candela/formats/mesh/mesh_size.h"

namespace candela {

// `check`, when given, sees the mesh's size before it is built, and may throw to refuse it.
TriangleMesh load_mesh(const std::filesystem::path& file, const MeshSizeCheck& check = {});

// What every mesh gets once parsed, whatever its source (a file, or a MeshStore): it must have
// triangles and finite positions and uvs; normals become unit length, or are all dropped when one
// is zero or not finite. Errors name `name`.
void finish_loaded_mesh(TriangleMesh& mesh, const std::string& name);

}  // namespace candela
