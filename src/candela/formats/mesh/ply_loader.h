#pragma once
// Stanford PLY meshes (Turk 1994), read by our own small reader: ascii, binary_little_endian and
// binary_big_endian; every scalar type and its sized alias (char/int8 ... double/float64);
// elements and properties in any order, the ones we do not use skipped.
#include <string>
#include <string_view>

#include "candela/geometry/triangle_mesh.h"
#include "candela/formats/mesh/mesh_size.h"

namespace candela {

// Parses the bytes of a PLY file, including those pbrt-v4 reads (TriQuadMesh::ReadPLY: its uv
// names, `face_indices`, triangles and quads). Reads vertex x y z, optional nx ny nz, optional uvs (u/v, s/t,
// texture_u/texture_v or texture_s/texture_t) and the face list `vertex_indices` (or
// `vertex_index`); polygons are fan-triangulated (v0, vi, vi+1), keeping the file's winding.
// Values are as stored: normals are not normalized (load_mesh does that). Throws SceneError naming
// `file_name`, with the line for header and ascii errors (the byte offset for binary ones), on any
// malformed or truncated input, a non-finite position, or counts the file is too short to hold.
// `check`, when given, sees the counts the header declares before any record is read.
TriangleMesh parse_ply(std::string_view bytes, const std::string& file_name, const MeshSizeCheck& check = {});

// The size of the mesh a PLY file will make, from its header alone (`header_bytes`: the file's
// start through its end_header line; more is allowed), checked as parse_ply checks it: for
// refusing a mesh before its data is read or inflated. Throws SceneError as parse_ply does.
MeshSize ply_mesh_size(std::string_view header_bytes, const std::string& file_name);

}  // namespace candela
