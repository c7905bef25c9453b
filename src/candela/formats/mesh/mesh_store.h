#pragma once
// Meshes held in memory under the file names a scene document gives them: a scene translated from
// another format (a pbrt-v4 `trianglemesh`, a subdivided `loopsubdiv`) names its meshes as files
// that `candela convert` writes beside the converted scene. The JSON loader looks a `file` up here
// before the disk and finishes the mesh exactly as it finishes one read from a file
// (finish_loaded_mesh), so a converted scene and the scene it came from load the same bits.
#include <map>
#include <string>

#include "candela/geometry/triangle_mesh.h"

namespace candela {

using MeshStore = std::map<std::string, TriangleMesh>;

}  // namespace candela
