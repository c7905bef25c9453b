// The PLY files pbrt-v4 reads (TriQuadMesh::ReadPLY in src/pbrt/util/mesh.cpp) load in candela,
// with the surface and the front side pbrt-v4 renders.
#include <gtest/gtest.h>

#include <cstdint>
#include <algorithm>
#include <bit>
#include <cstring>
#include <string>
#include <vector>

#include "candela/formats/mesh/ply_loader.h"
#include "candela/geometry/bilinear_patches.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Appends little-endian binary values (the byte order pbrt-v4's exporters write).
class LittleEndianWriter {
  public:
    explicit LittleEndianWriter(std::string start) : bytes_(std::move(start)) {}
    template <class... T>
    LittleEndianWriter& put(T... values) {
        (put_one(values), ...);
        return *this;
    }
    const std::string& bytes() const { return bytes_; }

  private:
    template <class T>
    void put_one(T value) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
        bytes_.append(reinterpret_cast<const char*>(b), sizeof(T));
    }
    std::string bytes_;
};

TEST(PbrtPly, ReadsPbrtV4sBinaryLayoutWithFaceIndicesAndMixedTrianglesAndQuads) {
    // As pbrt-v4's exporters write: uint8 counts, int indices, a per-face `face_indices` (pbrt
    // uses it for ptex; candela skips it), a triangle and a quad.
    LittleEndianWriter w(
        "ply\nformat binary_little_endian 1.0\ncomment written like pbrt-v4's plytool\n"
        "element vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nproperty float nz\nproperty float u\nproperty float v\n"
        "element face 2\nproperty list uint8 int vertex_indices\nproperty int face_indices\nend_header\n");
    const std::vector<Vec3f> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
    for (size_t i = 0; i < p.size(); ++i)
        w.put(p[i].x, p[i].y, p[i].z, 0.0f, 0.0f, 1.0f, p[i].x / 2, p[i].y);
    w.put(uint8_t{3}, int32_t{0}, int32_t{1}, int32_t{2}, int32_t{7});
    w.put(uint8_t{4}, int32_t{1}, int32_t{3}, int32_t{4}, int32_t{2}, int32_t{8});
    const TriangleMesh m = parse_ply(w.bytes(), "pbrt.ply");
    EXPECT_EQ(m.positions, p);
    EXPECT_EQ(m.normals, std::vector<Vec3f>(5, Vec3f(0, 0, 1)));
    EXPECT_EQ(m.uvs[4], Vec2f(1, 1));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 4, 1, 4, 2}));
}

TEST(PbrtPly, ReadsEveryUvNamingPbrtV4Reads) {
    for (const auto& [u, v] : std::vector<std::pair<std::string, std::string>>{
             {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}) {
        SCOPED_TRACE(u);
        const std::string bytes = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                  "property float z\nproperty float " + u + "\nproperty float " + v +
                                  "\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                  "0 0 0 0.25 0.5\n1 0 0 0.75 0.5\n0 1 0 0.25 1\n3 0 1 2\n";
        EXPECT_EQ(parse_ply(bytes, "uv.ply").uvs, (std::vector<Vec2f>{{0.25f, 0.5f}, {0.75f, 0.5f}, {0.25f, 1}}));
    }
}

TEST(PbrtPly, SplitsAQuadAsPbrtsBilinearPatchWithTheSameFront) {
    // pbrt-v4 keeps PLY quad (v0 v1 v2 v3) as the bilinear patch v00 v10 v01 v11 = v0 v1 v3 v2,
    // whose normal is cross(dp/du, dp/dv); a planar patch is the quad's surface.
    const std::string bytes = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                              "property float z\nproperty float u\nproperty float v\nelement face 1\n"
                              "property list uchar int vertex_indices\nend_header\n"
                              "0 0 1 0 0\n2 0 1 1 0\n2 1 1 1 1\n0 1 1 0 1\n4 0 1 2 3\n";
    const TriangleMesh quad = parse_ply(bytes, "quad.ply");
    const std::vector<int> patch = {0, 1, 3, 2};
    const TriangleMesh blp = bilinear_patches_to_triangles(quad.positions, patch, {}, quad.uvs);
    EXPECT_EQ(quad.indices, blp.indices);
    const Vec3f dpdu = quad.positions[1] - quad.positions[0], dpdv = quad.positions[3] - quad.positions[0];
    for (size_t t = 0; t < quad.triangle_count(); ++t) {
        const Vec3f a = quad.positions[quad.indices[3 * t]];
        const Vec3f n = cross(quad.positions[quad.indices[3 * t + 1]] - a, quad.positions[quad.indices[3 * t + 2]] - a);
        EXPECT_GT(dot(n, cross(dpdu, dpdv)), 0.0f) << "triangle " << t;
    }
}

}  // namespace
}  // namespace candela
