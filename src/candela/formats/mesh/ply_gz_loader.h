#pragma once
// gzip-compressed PLY files (.ply.gz), as pbrt-v4 reads them (its rply inflates through zlib).
#include <string>
#include <string_view>

#include "candela/formats/mesh/mesh_size.h"
#include "candela/geometry/triangle_mesh.h"

namespace candela {

// Parses the bytes of a .ply.gz file: the PLY header is inflated first and `check` called (once)
// with the size it declares, so a mesh too large is refused before its data is inflated; the rest
// is then inflated into memory and parsed by parse_ply, whose errors it throws unchanged (located
// in the inflated PLY). Bytes that are not gzip-compressed are parsed as a plain PLY, as zlib's
// gzread (and so pbrt-v4) reads them. Truncated or corrupt gzip data throws SceneError naming
// `file_name` (GzipStream's messages).
TriangleMesh parse_ply_gz(std::string_view bytes, const std::string& file_name, const MeshSizeCheck& check = {});

}  // namespace candela
