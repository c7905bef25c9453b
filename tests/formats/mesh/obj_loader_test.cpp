#include "candela/formats/mesh/obj_loader.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "support/fixtures.h"
#include "support/printers.h"

namespace candela {

namespace CANDELA_UNITY_ID {

TriangleMesh parse_fixture(const std::string& name) { return parse_obj(test::read_fixture("meshes/" + name), name); }

SceneError parse_error(const std::string& text) {
    try {
        parse_obj(text, "test.obj");
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "expected a SceneError";
    return SceneError({}, "");
}

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

Vec3f triangle_normal(const TriangleMesh& m, size_t t) {
    const Vec3f a = m.positions[m.indices[3 * t]];
    return cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a);
}

const std::string kThreeVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(ObjLoader, ReadsUnitQuadWithNormalAndUvs) {
    const TriangleMesh m = parse_fixture("quad.obj");
    EXPECT_EQ(m.positions, (std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    EXPECT_EQ(m.uvs, (std::vector<Vec2f>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    EXPECT_EQ(m.normals, std::vector<Vec3f>(4, Vec3f(0, 0, 1)));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(ObjLoader, MakesOneVertexPerPositionUvNormalTriple) {
    // The two faces share the positions of v2 and v3 but not their normals: four corners, six
    // vertices.
    const TriangleMesh m = parse_fixture("normals_uvs.obj");
    EXPECT_EQ(m.positions,
              (std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}}));
    EXPECT_EQ(m.normals,
              (std::vector<Vec3f>{{0, 0, 2}, {0, 0, 2}, {0, 0, 2}, {-1, -1, 1}, {-1, -1, 1}, {-1, -1, 1}}));
    EXPECT_EQ(m.uvs, (std::vector<Vec2f>{{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {0, 1}}));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(ObjLoader, SharesVerticesOfIdenticalCornersWithoutNormals) {
    const TriangleMesh m = parse_fixture("no_normals.obj");
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_TRUE(m.normals.empty());
    EXPECT_EQ(m.uvs, (std::vector<Vec2f>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(ObjLoader, FanTriangulatesQuadsAndPolygonsKeepingWinding) {
    const TriangleMesh m = parse_fixture("polygons.obj");
    EXPECT_EQ(m.positions.size(), 9u);
    EXPECT_EQ(m.positions[6], Vec3f(3.5f, 1, 0));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 4, 7, 8}));
    for (size_t t = 0; t < m.triangle_count(); ++t) EXPECT_GT(triangle_normal(m, t).z, 0.0f) << t;
}

TEST(ObjLoader, ReadsCubeWithOutwardWinding) {
    const TriangleMesh m = parse_fixture("cube.obj");
    EXPECT_EQ(m.positions.size(), 8u);
    ASSERT_EQ(m.triangle_count(), 12u);
    float area = 0.0f;
    for (size_t t = 0; t < m.triangle_count(); ++t) {
        const Vec3f a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
        EXPECT_GT(dot(triangle_normal(m, t), a + b + c), 0.0f) << "triangle " << t;
        area += 0.5f * length(triangle_normal(m, t));
    }
    EXPECT_FLOAT_EQ(area, 24.0f);
}

TEST(ObjLoader, MergesObjectsAndGroupsIntoOneMesh) {
    const TriangleMesh m = parse_fixture("two_objects.obj");
    EXPECT_EQ(m.positions,
              (std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(ObjLoader, IgnoresMaterials) {
    const TriangleMesh m = parse_fixture("missing_material.obj");
    EXPECT_EQ(m.triangle_count(), 1u);
}

TEST(ObjLoader, DropsNormalsWhenSomeCornersLackThem) {
    // Corners that differed only in their normal then share one vertex.
    const TriangleMesh m = parse_fixture("mixed_normals.obj");
    EXPECT_TRUE(m.normals.empty());
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(ObjLoader, DropsUvsWhenSomeCornersLackThem) {
    const TriangleMesh m = parse_obj(
        kThreeVertices + "v 1 1 0\nvt 0.5 0.5\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\nf 2//1 4//1 3//1\n", "t.obj");
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_EQ(m.normals.size(), 4u);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
}

TEST(ObjLoader, RejectsOutOfRangeVertexIndexWithItsLine) {
    const SceneError e = parse_error(test::read_fixture("meshes/bad_index.obj"));
    EXPECT_EQ(e.where().file, "test.obj");
    EXPECT_EQ(e.where().line, 11);
    EXPECT_TRUE(contains(e.message(), "face refers to vertex 7, but the file has 6 v statements"));
}

TEST(ObjLoader, RejectsOutOfRangeNormalAndUvIndices) {
    const SceneError normal = parse_error(test::read_fixture("meshes/bad_normal_index.obj"));
    EXPECT_EQ(normal.where().line, 5);
    EXPECT_TRUE(contains(normal.message(), "normal 2, but the file has 1 vn statements"));
    const SceneError uv = parse_error(kThreeVertices + "vt 0 0\nf 1/1 2/5 3/1\n");
    EXPECT_EQ(uv.where().line, 5);
    EXPECT_TRUE(contains(uv.message(), "texture coordinate 5, but the file has 1 vt statements"));
}

TEST(ObjLoader, RejectsRelativeIndexBeforeTheFirstVertex) {
    const SceneError e = parse_error(kThreeVertices + "f -4 -1 -2\n");
    EXPECT_EQ(e.where().line, 4);
    EXPECT_TRUE(contains(e.message(), "a vertex before the first one"));
}

TEST(ObjLoader, RejectsZeroIndexWithTinyobjloadersLine) {
    const SceneError e = parse_error(kThreeVertices + "\nf 0 1 2\n");
    EXPECT_EQ(e.where().line, 5);
    EXPECT_TRUE(contains(e.message(), "zero value for face index"));
}

TEST(ObjLoader, RejectsFacesOfFewerThanThreeVertices) {
    const SceneError e = parse_error(kThreeVertices + "f 1 2 3\nf 1 2\n");
    EXPECT_EQ(e.where().line, 5);
    EXPECT_TRUE(contains(e.message(), "fewer than 3 vertices"));
}

TEST(ObjLoader, RejectsFacesOfMoreThan255Vertices) {
    // tinyobjloader counts corners in an unsigned char; 256 would wrap to 0.
    std::string text, face = "f";
    for (int i = 0; i < 256; ++i) {
        const double a = 2.0 * 3.14159265358979 * i / 256.0;
        text += fmt::format("v {} {} 0\n", std::cos(a), std::sin(a));
        face += fmt::format(" {}", i + 1);
    }
    const SceneError e = parse_error(text + face + "\n");
    EXPECT_EQ(e.where().line, 257);
    EXPECT_TRUE(contains(e.message(), "more than 255 vertices"));
}

TEST(ObjLoader, CountsLinesEndedByCrLfOrLoneCr) {
    EXPECT_EQ(parse_error("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n\r\nf 1 2 9\r\n").where().line, 5);
    EXPECT_EQ(parse_error("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\rf 1 2 9\r").where().line, 5);
}

}  // namespace
}  // namespace candela
