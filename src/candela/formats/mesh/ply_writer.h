#pragma once
// Writes a mesh as a binary little-endian PLY file that candela's PLY reader reads back to the
// same floats: vertex x y z, nx ny nz and u v where the mesh has them, faces as lists of three
// vertex_indices. `candela convert` writes the meshes of a converted scene with it.
#include <filesystem>

#include "candela/geometry/triangle_mesh.h"

namespace candela {

// Throws SceneError naming the file when it cannot be written.
void write_ply(const std::filesystem::path& file, const TriangleMesh& mesh);

}  // namespace candela
