#include "candela/geometry/bilinear_patches.h"

#include <fmt/format.h>

#include <array>
#include <cstdint>

#include "candela/core/error.h"

namespace candela {
namespace {

[[noreturn]] void reject(const std::string& message) { throw SceneError(SourceLocation{}, message); }

// The two triangles of a patch, as corners 0..3 = v00 v10 v01 v11 (see the header).
constexpr std::array<int, 6> kPatchTriangles = {0, 1, 3, 0, 3, 2};

}  // namespace

TriangleMesh bilinear_patches_to_triangles(std::span<const Vec3f> positions, std::span<const int> indices,
                                           std::span<const Vec3f> normals, std::span<const Vec2f> uvs) {
    constexpr std::array<int, 4> kOnePatch = {0, 1, 2, 3};
    if (indices.empty() && positions.size() == 4) indices = kOnePatch;
    if (indices.empty()) reject("a bilinear patch mesh needs \"indices\" (four per patch)");
    if (indices.size() % 4 != 0)
        reject(fmt::format("a bilinear patch mesh needs four indices per patch; got {}", indices.size()));
    if (!normals.empty() && normals.size() != positions.size())
        reject(fmt::format("a bilinear patch mesh has {} normals for {} positions", normals.size(), positions.size()));
    if (!uvs.empty() && uvs.size() != positions.size())
        reject(fmt::format("a bilinear patch mesh has {} uvs for {} positions", uvs.size(), positions.size()));
    for (size_t i = 0; i < indices.size(); ++i)
        if (indices[i] < 0 || static_cast<size_t>(indices[i]) >= positions.size())
            reject(fmt::format("bilinear patch index {} (number {}) is out of range; there are {} positions",
                             indices[i], i + 1, positions.size()));

    const size_t patches = indices.size() / 4;
    TriangleMesh mesh;
    mesh.indices.reserve(6 * patches);
    if (!uvs.empty()) {
        // Shared corners: the mesh is the patches' positions, normals and uvs as given.
        mesh.positions.assign(positions.begin(), positions.end());
        mesh.normals.assign(normals.begin(), normals.end());
        mesh.uvs.assign(uvs.begin(), uvs.end());
        for (size_t p = 0; p < patches; ++p)
            for (const int corner : kPatchTriangles)
                mesh.indices.push_back(static_cast<uint32_t>(indices[4 * p + static_cast<size_t>(corner)]));
        return mesh;
    }
    // pbrt's default uv is the patch's own (u, v), so each patch gets its own four corners.
    constexpr std::array<Vec2f, 4> kCornerUv = {Vec2f(0, 0), Vec2f(1, 0), Vec2f(0, 1), Vec2f(1, 1)};
    mesh.positions.reserve(4 * patches);
    mesh.uvs.reserve(4 * patches);
    if (!normals.empty()) mesh.normals.reserve(4 * patches);
    for (size_t p = 0; p < patches; ++p) {
        const auto first = static_cast<uint32_t>(mesh.positions.size());
        for (size_t corner = 0; corner < 4; ++corner) {
            const auto index = static_cast<size_t>(indices[4 * p + corner]);
            mesh.positions.push_back(positions[index]);
            if (!normals.empty()) mesh.normals.push_back(normals[index]);
            mesh.uvs.push_back(kCornerUv[corner]);
        }
        for (const int corner : kPatchTriangles) mesh.indices.push_back(first + static_cast<uint32_t>(corner));
    }
    return mesh;
}

}  // namespace candela
