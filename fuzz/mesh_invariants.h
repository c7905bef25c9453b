#pragma once
// What every mesh a loader returns must satisfy, whatever the file said: the renderer and
// Embree index positions, normals and uvs with these indices without further checks.
#include "candela/geometry/triangle_mesh.h"
#include "fuzz_support.h"

namespace candela::fuzz {

inline void require_valid_mesh(const TriangleMesh& mesh) {
    require(mesh.indices.size() % 3 == 0, "three indices per triangle");
    require(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size(), "one normal per vertex or none");
    require(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size(), "one uv per vertex or none");
    for (const uint32_t i : mesh.indices) require(i < mesh.positions.size(), "indices within the vertices");
}

}  // namespace candela::fuzz
