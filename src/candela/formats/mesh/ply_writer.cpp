#include "candela/formats/mesh/ply_writer.h"

#include <fmt/format.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "candela/core/atomic_file.h"
#include "candela/core/error.h"

namespace candela {
namespace {

static_assert(std::endian::native == std::endian::little, "write_ply writes the machine's floats as they are");

template <class T>
void put(std::string& out, const T& v) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &v, sizeof(T));
    out.append(bytes, sizeof(T));
}

}  // namespace

void write_ply(const std::filesystem::path& file, const TriangleMesh& mesh) {
    const bool normals = !mesh.normals.empty(), uvs = !mesh.uvs.empty();
    std::string out = fmt::format("ply\nformat binary_little_endian 1.0\ncomment written by candela\n"
                                  "element vertex {}\nproperty float x\nproperty float y\nproperty float z\n",
                                  mesh.positions.size());
    if (normals) out += "property float nx\nproperty float ny\nproperty float nz\n";
    if (uvs) out += "property float u\nproperty float v\n";
    out += fmt::format("element face {}\nproperty list uchar uint vertex_indices\nend_header\n", mesh.triangle_count());
    out.reserve(out.size() + mesh.positions.size() * 32 + mesh.triangle_count() * 13);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        put(out, mesh.positions[i].x);
        put(out, mesh.positions[i].y);
        put(out, mesh.positions[i].z);
        if (normals) {
            put(out, mesh.normals[i].x);
            put(out, mesh.normals[i].y);
            put(out, mesh.normals[i].z);
        }
        if (uvs) {
            put(out, mesh.uvs[i].x);
            put(out, mesh.uvs[i].y);
        }
    }
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        put(out, uint8_t(3));
        for (int k = 0; k < 3; ++k) put(out, mesh.indices[3 * t + k]);
    }
    write_contents_atomically(file, out);
}

}  // namespace candela
