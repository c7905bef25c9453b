#include "candela/scene/mesh_loader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

#include "candela/core/error.h"
#include "candela/scene/obj_loader.h"
#include "candela/scene/ply_loader.h"

namespace candela {
namespace {

using MeshParser = TriangleMesh (*)(std::string_view bytes, const std::string& file_name);

struct MeshFormat {
    std::string_view extension;  // lower case, with the dot
    MeshParser parse;
};

// The one table of mesh formats: dispatch and the error message both read it.
constexpr MeshFormat kMeshFormats[] = {{".obj", parse_obj}, {".ply", parse_ply}};

std::string lower_case(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string read_file(const std::filesystem::path& file, const std::string& name) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status))
        throw SceneError(SourceLocation{name, 0, 0, {}}, "cannot read mesh file: no such file");
    if (!std::filesystem::is_regular_file(status))
        throw SceneError(SourceLocation{name, 0, 0, {}}, "cannot read mesh file: not a regular file");
    std::ifstream in(file, std::ios::binary);
    const auto size = std::filesystem::file_size(file, ec);
    std::string bytes;
    if (in && !ec) {
        bytes.resize(size);
        in.read(bytes.data(), static_cast<std::streamsize>(size));
    }
    if (!in || ec || static_cast<size_t>(in.gcount()) != size)
        throw SceneError(SourceLocation{name, 0, 0, {}}, "cannot read mesh file: reading failed");
    return bytes;
}

// What both formats share once parsed: a mesh must have triangles and finite values, and its
// normals are made unit length. A zero-length or non-finite normal has no direction to give, so
// the whole mesh then drops its normals and renders with geometric normals (flat shading), rather
// than mixing interpolated and made-up ones; files with such normals exist (degenerate regions of
// scans), and refusing them would refuse usable geometry.
void finish(TriangleMesh& mesh, const std::string& name) {
    if (mesh.triangle_count() == 0)
        throw SceneError(SourceLocation{name, 0, 0, {}}, "the mesh file has no triangles");
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        if (!is_finite(mesh.positions[i]))
            throw SceneError(SourceLocation{name, 0, 0, {}},
                             fmt::format("vertex {} has a non-finite position", i + 1));
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!std::isfinite(mesh.uvs[i].x) || !std::isfinite(mesh.uvs[i].y))
            throw SceneError(SourceLocation{name, 0, 0, {}},
                             fmt::format("vertex {} has a non-finite uv", i + 1));
    const bool normals_usable = std::all_of(mesh.normals.begin(), mesh.normals.end(), [](const Vec3f& n) {
        const float l2 = length_squared(n);
        return std::isfinite(l2) && l2 > 0.0f;
    });
    if (!normals_usable) {
        mesh.normals.clear();
        return;
    }
    for (Vec3f& n : mesh.normals) n = normalize(n);
}

}  // namespace

TriangleMesh load_mesh(const std::filesystem::path& file) {
    const std::string name = file.string();
    const std::string extension = lower_case(file.extension().string());
    for (const MeshFormat& format : kMeshFormats) {
        if (format.extension != extension) continue;
        TriangleMesh mesh = format.parse(read_file(file, name), name);
        finish(mesh, name);
        return mesh;
    }
    std::string known;
    for (const MeshFormat& format : kMeshFormats) {
        if (!known.empty()) known += ", ";
        known += format.extension;
    }
    throw SceneError(SourceLocation{name, 0, 0, {}},
                     fmt::format("unknown mesh file extension \"{}\"; expected one of: {}",
                                 file.extension().string(), known));
}

}  // namespace candela
