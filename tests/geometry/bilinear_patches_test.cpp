#include "candela/geometry/bilinear_patches.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

Vec3f winding(const TriangleMesh& m, size_t t) {
    const Vec3f a = m.positions[m.indices[3 * t]];
    return cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a);
}

// pbrt-v4's patch normal cross(dp/du, dp/dv) at (u, v), for p bilinear in v00 v10 v01 v11.
Vec3f patch_normal(const std::vector<Vec3f>& c, float u, float v) {
    const Vec3f dpdu = (1 - v) * (c[1] - c[0]) + v * (c[3] - c[2]);
    const Vec3f dpdv = (1 - u) * (c[2] - c[0]) + u * (c[3] - c[1]);
    return cross(dpdu, dpdv);
}

std::string error_of(const std::vector<Vec3f>& p, const std::vector<int>& indices, const std::vector<Vec3f>& n = {},
                     const std::vector<Vec2f>& uv = {}) {
    try {
        bilinear_patches_to_triangles(p, indices, n, uv);
    } catch (const SceneError& e) {
        EXPECT_TRUE(e.where().file.empty());
        return e.message();
    }
    ADD_FAILURE() << "expected a SceneError";
    return "";
}

TEST(BilinearPatches, OnePatchWithoutIndicesIsPbrtsDefaultPatch) {
    const std::vector<Vec3f> p = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {2, 1, 0}};
    const TriangleMesh m = bilinear_patches_to_triangles(p, {});
    EXPECT_EQ(m.positions, p);
    EXPECT_EQ(m.uvs, (std::vector<Vec2f>{{0, 0}, {1, 0}, {0, 1}, {1, 1}}));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 3, 0, 3, 2}));
    EXPECT_TRUE(m.normals.empty());
    for (size_t t = 0; t < 2; ++t) {
        EXPECT_EQ(normalize(winding(m, t)), Vec3f(0, 0, 1)) << "triangle " << t;  // cross(dp/du, dp/dv)
        EXPECT_FLOAT_EQ(length(winding(m, t)), 2.0f);                             // half the 2x1 patch each
    }
}

TEST(BilinearPatches, RepeatsSharedCornersPerPatchForPbrtsDefaultUv) {
    // Two patches sharing the edge (1, 4): without uvs each patch's corners get their own (u, v).
    const std::vector<Vec3f> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    const std::vector<Vec3f> n(6, Vec3f(0, 0, 1));
    const TriangleMesh m = bilinear_patches_to_triangles(p, std::vector<int>{0, 1, 3, 4, 1, 2, 4, 5}, n);
    EXPECT_EQ(m.positions, (std::vector<Vec3f>{p[0], p[1], p[3], p[4], p[1], p[2], p[4], p[5]}));
    EXPECT_EQ(m.normals, std::vector<Vec3f>(8, Vec3f(0, 0, 1)));
    EXPECT_EQ(m.uvs, (std::vector<Vec2f>{{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 0}, {1, 0}, {0, 1}, {1, 1}}));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 3, 0, 3, 2, 4, 5, 7, 4, 7, 6}));
}

TEST(BilinearPatches, KeepsCornersSharedWhenUvsAreGiven) {
    const std::vector<Vec3f> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    const std::vector<Vec2f> uv = {{0, 0}, {0.5f, 0}, {1, 0}, {0, 1}, {0.5f, 1}, {1, 1}};
    const TriangleMesh m = bilinear_patches_to_triangles(p, std::vector<int>{0, 1, 3, 4, 1, 2, 4, 5}, {}, uv);
    EXPECT_EQ(m.positions, p);
    EXPECT_EQ(m.uvs, uv);
    EXPECT_TRUE(m.normals.empty());
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4}));
}

TEST(BilinearPatches, KeepsPbrtsFrontOnTwistedAndMirroredPatches) {
    // A saddle, and the same patch with u mirrored (v10 <-> v00, v11 <-> v01): pbrt's front flips
    // with it, and so must the triangles'.
    const std::vector<Vec3f> saddle = {{0, 0, 0}, {1, 0, 0.3f}, {0, 1, 0.3f}, {1, 1, 0}};
    const std::vector<Vec3f> mirrored = {saddle[1], saddle[0], saddle[3], saddle[2]};
    for (const std::vector<Vec3f>& c : {saddle, mirrored}) {
        const TriangleMesh m = bilinear_patches_to_triangles(c, {});
        const Vec3f centre = patch_normal(c, 0.5f, 0.5f);
        for (size_t t = 0; t < 2; ++t) EXPECT_GT(dot(winding(m, t), centre), 0.0f) << "triangle " << t;
    }
}

TEST(BilinearPatches, RejectsWhatPbrtRejects) {
    const std::vector<Vec3f> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 0, 0}};
    EXPECT_EQ(error_of(p, {}), "a bilinear patch mesh needs \"indices\" (four per patch)");
    EXPECT_EQ(error_of(p, {0, 1, 2, 3, 4}), "a bilinear patch mesh needs four indices per patch; got 5");
    EXPECT_EQ(error_of(p, {0, 1, 2, 5}), "bilinear patch index 5 (number 4) is out of range; there are 5 positions");
    EXPECT_EQ(error_of(p, {0, -1, 2, 3}), "bilinear patch index -1 (number 2) is out of range; there are 5 positions");
    EXPECT_EQ(error_of(p, {0, 1, 2, 3}, {{0, 0, 1}}), "a bilinear patch mesh has 1 normals for 5 positions");
    EXPECT_EQ(error_of(p, {0, 1, 2, 3}, {}, {{0, 0}}), "a bilinear patch mesh has 1 uvs for 5 positions");
}

}  // namespace
}  // namespace candela
