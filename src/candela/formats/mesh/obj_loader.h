#pragma once
// Wavefront OBJ meshes, parsed by tinyobjloader and turned into one indexed triangle mesh.
#include <string>
#include <string_view>

#include "candela/geometry/triangle_mesh.h"
#include "candela/formats/mesh/mesh_size.h"

namespace candela {

// Parses the text of an OBJ file. All objects and groups merge into one mesh; materials (mtllib,
// usemtl) are ignored. Each distinct (v, vt, vn) triple becomes one vertex. Polygons are
// fan-triangulated (v0, vi, vi+1), keeping the file's winding. Normals (uvs) are kept only if
// every face corner has one; otherwise the mesh has none. Values are as stored: normals are not
// normalized (load_mesh does that). Throws SceneError naming `file_name` and the line of the
// offending statement on malformed input (a coordinate that is not a finite number, a face
// corner that is not an index) or out-of-range indices. `check`, when given, sees the mesh's
// size after a first scan of the text and before anything is built.
TriangleMesh parse_obj(std::string_view text, const std::string& file_name, const MeshSizeCheck& check = {});

}  // namespace candela
