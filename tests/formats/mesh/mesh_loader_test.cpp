#include "candela/formats/mesh/mesh_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

std::filesystem::path fixture(const std::string& name) {
    return std::filesystem::path(CANDELA_TEST_DATA_DIR) / "meshes" / name;
}

// A scratch folder in the build tree for files that must not be committed.
std::filesystem::path scratch(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(CANDELA_TEST_BINARY_DIR) / "mesh_loader_test";
    std::filesystem::create_directories(dir);
    return dir / name;
}

SceneError load_error(const std::filesystem::path& file) {
    try {
        load_mesh(file);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "expected a SceneError for " << file;
    return SceneError({}, "");
}

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

float surface_area(const TriangleMesh& m) {
    float area = 0.0f;
    for (size_t t = 0; t < m.triangle_count(); ++t) {
        const Vec3f a = m.positions[m.indices[3 * t]];
        area += 0.5f *
                length(cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a));
    }
    return area;
}

TEST(MeshLoader, LoadsObjAndPlyCubesAlike) {
    const TriangleMesh obj = load_mesh(fixture("cube.obj"));
    const TriangleMesh ply = load_mesh(fixture("cube.ply"));
    EXPECT_EQ(obj.triangle_count(), 12u);
    EXPECT_EQ(ply.triangle_count(), 12u);
    EXPECT_FLOAT_EQ(surface_area(obj), 24.0f);
    EXPECT_FLOAT_EQ(surface_area(ply), 24.0f);
    // The same triangles, as position triples, in the same order.
    for (size_t i = 0; i < obj.indices.size(); ++i)
        EXPECT_EQ(obj.positions[obj.indices[i]], ply.positions[ply.indices[i]]) << "corner " << i;
}

TEST(MeshLoader, ChoosesTheFormatByExtensionIgnoringCase) {
    EXPECT_EQ(load_mesh(fixture("upper_case_extension.OBJ")).triangle_count(), 1u);
}

TEST(MeshLoader, NormalizesNormals) {
    const TriangleMesh m = load_mesh(fixture("quads_normals_uvs_ascii.ply"));
    ASSERT_EQ(m.normals.size(), 6u);
    EXPECT_EQ(m.normals[1], Vec3f(0, 0, 1));  // stored as (0, 0, 2)
    const TriangleMesh obj = load_mesh(fixture("normals_uvs.obj"));
    EXPECT_EQ(obj.normals[0], Vec3f(0, 0, 1));
    EXPECT_NEAR(length(obj.normals[3]), 1.0f, 1e-6f);
    EXPECT_NEAR(obj.normals[3].x, -1.0f / std::sqrt(3.0f), 1e-6f);
}

TEST(MeshLoader, DropsAllNormalsWhenOneHasZeroLength) {
    const TriangleMesh m = load_mesh(fixture("zero_normal.ply"));
    EXPECT_TRUE(m.normals.empty());
    EXPECT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.triangle_count(), 1u);
}

TEST(MeshLoader, LoadsObjWhoseMaterialLibraryIsMissing) {
    EXPECT_EQ(load_mesh(fixture("missing_material.obj")).triangle_count(), 1u);
}

TEST(MeshLoader, RejectsUnknownExtensionListingKnownOnes) {
    const SceneError e = load_error(fixture("cube.stl"));
    EXPECT_EQ(e.where().file, fixture("cube.stl").string());
    EXPECT_TRUE(contains(e.message(), "unknown mesh file extension \".stl\"; expected one of: .obj, .ply, .ply.gz"));
    EXPECT_TRUE(contains(load_error(fixture("cube")).message(), "unknown mesh file extension \"\""));
}

TEST(MeshLoader, RejectsMissingFileNamingIt) {
    const SceneError e = load_error(fixture("does_not_exist.ply"));
    EXPECT_EQ(e.where().file, fixture("does_not_exist.ply").string());
    EXPECT_TRUE(contains(e.message(), "no such file"));
    EXPECT_TRUE(contains(e.formatted(), "does_not_exist.ply: cannot read mesh file"));
}

TEST(MeshLoader, RejectsDirectory) {
    const std::filesystem::path dir = scratch("folder.obj");
    std::filesystem::create_directories(dir);
    EXPECT_TRUE(contains(load_error(dir).message(), "not a regular file"));
}

TEST(MeshLoader, RejectsMeshWithoutTriangles) {
    EXPECT_TRUE(contains(load_error(fixture("no_faces.obj")).message(), "no triangles"));
}

TEST(MeshLoader, RejectsNonFinitePositions) {
    const std::filesystem::path file = scratch("nan.ply");
    std::ofstream(file) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                           "end_header\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n";
    const SceneError e = load_error(file);
    EXPECT_EQ(e.where().line, 11);  // the record's line
    EXPECT_TRUE(contains(e.message(), "element \"vertex\", record 2 of 3: the vertex position (1, nan, 0) is not finite"))
        << e.message();
}

TEST(MeshLoader, ReportsErrorsOfBothFormatsWithFileAndLine) {
    const SceneError ply = load_error(fixture("bad_index.ply"));
    EXPECT_EQ(ply.where().file, fixture("bad_index.ply").string());
    EXPECT_EQ(ply.where().line, 14);
    const SceneError obj = load_error(fixture("bad_index.obj"));
    EXPECT_EQ(obj.where().file, fixture("bad_index.obj").string());
    EXPECT_EQ(obj.where().line, 11);
    EXPECT_TRUE(contains(load_error(fixture("truncated_binary.ply")).message(), "unexpected end of file"));
}

}  // namespace
}  // namespace candela
