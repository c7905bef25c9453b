#pragma once
// What a mesh file will hold, known before its mesh is built (from a PLY header, or from a first
// scan of an OBJ's statements), so that a file too large for the machine can be refused before
// anything is allocated for it (memory_budget.h).
#include <cstdint>
#include <functional>

namespace candela {

struct MeshSize {
    uint64_t vertices = 0;   // OBJ: v statements; PLY: vertex records
    uint64_t triangles = 0;  // after fan triangulation; for PLY a lower bound (one per face)
    uint64_t corners = 0;    // face corners in the file (OBJ; 0 for PLY)
    bool normals = false;
    bool uvs = false;
};

// Called with the size before the mesh is built; throws (SceneError) to refuse it.
using MeshSizeCheck = std::function<void(const MeshSize&)>;

}  // namespace candela
