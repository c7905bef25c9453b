// Every file in tests/data/bad_scenes/ has exactly one defect; the table says where the loader
// must report it (line, column, JSON pointer) and what the message must say.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <ostream>
#include <set>
#include <string>

#include "candela/core/error.h"
#include "candela/scene/scene_loader.h"

namespace candela {
namespace {

struct BadScene {
    const char* file;
    int line;
    int column;
    const char* pointer;
    const char* message;  // a fragment of the message
};

// gtest prints a failing parameter with this, rather than as raw bytes.
void PrintTo(const BadScene& bad, std::ostream* os) { *os << bad.file; }

// Locations: a bad value is reported at its first character; an unknown or repeated key at its
// opening quote, with the pointer of its object; a missing key at its object's opening brace; a
// JSON syntax error where the parser stopped.
const BadScene kBadScenes[] = {
    {"albedo_out_of_range.json", 3, 48, "/materials/red/albedo/1",
     "expected a number in [0, 1], got 1.2"},
    {"degenerate_quad.json", 4, 72, "/shapes/0/edge2",
     "edge2 [-2, 0, 0] is parallel to edge1 [1, 0, 0]; the quad has no area"},
    {"duplicate_key.json", 5, 5, "/camera",
     "duplicate key \"fov\""},
    {"empty_file.json", 1, 1, "",
     "unexpected end of input"},
    {"environment_file_and_color.json", 3, 57, "/lights/0/color",
     "give \"file\" or \"color\", not both"},
    {"environment_not_hdr.json", 3, 37, "/lights/0/file",
     "expected an .hdr or .exr image (linear radiance), got \"sky.png\""},
    {"environment_without_radiance.json", 3, 5, "/lights/0",
     "an environment needs \"file\" (an .hdr or .exr image) or \"color\""},
    {"exposure_out_of_range.json", 2, 47, "/film/exposure",
     "expected a number in [0, 1), got 1"},
    {"fov_out_of_range.json", 3, 12, "/camera/fov",
     "expected a number in (0, 180), got 180"},
    {"huge_number.json", 2, 30, "/camera/position/1",
     "expected a finite number, got 1e400"},
    {"look_at_equals_position.json", 4, 16, "/camera/look_at",
     "look_at equals position [1, 2, 3]; the camera has no view direction"},
    {"matrix_not_affine.json", 9, 38, "/shapes/0/transform/0/matrix/14",
     "expected 0 (the last row of a transform matrix is [0, 0, 0, 1]), got 0.5"},
    {"max_depth_too_large.json", 2, 45, "/integrator/max_depth",
     "expected an integer <= 2147483647, got 3000000000"},
    {"missing_environment_file.json", 3, 37, "/lights/0/file",
     "environment image file \"missing_sky.hdr\" not found"},
    {"missing_key_near_miss.json", 4, 45, "/shapes/0",
     "unknown key \"radus\" (did you mean \"radius\"?)"},
    {"missing_mesh_file.json", 4, 30, "/shapes/0/file",
     "mesh file \"meshes/missing.obj\" not found"},
    {"missing_required_key.json", 4, 5, "/shapes/0",
     "missing required key \"radius\""},
    {"mix_empty.json", 3, 41, "/materials/nothing/lobes",
     "expected an array of 1 to 4 materials, got an empty array"},
    {"mix_nested.json", 5, 16, "/materials/coated/lobes/1/type",
     "a mix cannot contain a mix; expected one of: dielectric, diffuse, mirror, transmission"},
    {"mix_too_many_lobes.json", 3, 41, "/materials/layered/lobes",
     "expected an array of 1 to 4 materials, got an array of 5 elements"},
    {"mix_unknown_lobe_type.json", 5, 16, "/materials/coated/lobes/1/type",
     "unknown material type \"glossy\"; expected one of: dielectric, diffuse, mirror, transmission"},
    {"near_miss_material_key.json", 5, 7, "/materials/white",
     "unknown key \"albdo\" (did you mean \"albedo\"?)"},
    {"near_miss_top_level_key.json", 2, 3, "",
     "unknown key \"materails\" (did you mean \"materials\"?)"},
    {"negative_emission.json", 5, 39, "/shapes/0/emission",
     "expected a number >= 0, got -2"},
    {"radius_negative.json", 5, 55, "/shapes/1/radius",
     "expected a number > 0, got -1"},
    {"resolution_too_large.json", 2, 34, "/camera/resolution/1",
     "expected an integer in [1, 32768], got 40000"},
    {"resolution_wrong_length.json", 2, 28, "/camera/resolution",
     "expected an array of 2 integers [width, height], got [640]"},
    {"root_not_object.json", 1, 1, "",
     "expected an object, got an array of 1 element"},
    {"seed_negative.json", 2, 23, "/sampler/seed",
     "expected an integer in [0, 18446744073709551615], got -3"},
    {"singular_matrix.json", 6, 31, "/shapes/0/transform/0/matrix",
     "the matrix is singular (determinant 0)"},
    {"sphere_with_transform.json", 5, 6, "/shapes/0",
     "unknown key \"transform\"; expected one of: center, emission, material, radius, reverse_orientation, two_sided, type"},
    {"spp_not_integer.json", 2, 22, "/sampler/spp",
     "expected an integer in [1, 16777216], got 16.5"},
    {"spp_zero.json", 2, 33, "/sampler/spp",
     "expected an integer in [1, 16777216], got 0"},
    {"string_with_braces_before_error.json", 4, 51, "/materials/}{",
     "unknown key \"ior\"; expected one of: albedo, type"},
    {"syntax_missing_colon.json", 2, 21, "",
     "expected ':'"},
    {"trailing_comma.json", 4, 1, "",
     "no comma after the last element"},
    {"transform_step_two_keys.json", 5, 66, "/shapes/0/transform/0",
     "a transform step has one key; put \"scale\" in a step of its own"},
    {"transform_unknown_step.json", 5, 42, "/shapes/0/transform/0",
     "unknown key \"rotat\" (did you mean \"rotate\"?)"},
    {"two_environments.json", 4, 5, "/lights/1",
     "a scene has at most one environment light, and /lights/0 is one"},
    {"undefined_material.json", 7, 70, "/shapes/0/material",
     "unknown material \"whte\"; defined materials: red, white"},
    {"unknown_fresnel.json", 3, 60, "/materials/glass/fresnel",
     "unknown fresnel \"shlick\"; expected one of: exact, schlick"},
    {"unknown_environment_sampling.json", 3, 53, "/lights/0/sampling",
     "unknown environment sampling \"cosine\"; expected one of: importance, uniform"},
    {"unknown_filter.json", 2, 22, "/film/filter",
     "unknown filter \"gausian\"; expected one of: box, gaussian, smallpt, tent"},
    {"unknown_integrator_type.json", 2, 26, "/integrator/type",
     "unknown integrator type \"volpath\"; expected one of: albedo, ao, bsdf, depth, normals, path, whitted"},
    {"unknown_light_type.json", 2, 23, "/lights/0/type",
     "unknown light type \"point\"; expected one of: environment"},
    {"unknown_material_type.json", 3, 21, "/materials/red/type",
     "unknown material type \"glossy\"; expected one of: dielectric, diffuse, mirror, mix, transmission"},
    {"unknown_shape_type.json", 4, 14, "/shapes/0/type",
     "unknown shape type \"shpere\"; expected one of: mesh, quad, sphere"},
    {"unknown_top_level_key.json", 2, 3, "",
     "unknown key \"renderer\"; expected one of: camera, film, integrator, lights, materials, sampler, shapes"},
    {"up_parallel_to_view.json", 5, 11, "/camera/up",
     "up [0, 2, 0] is parallel to the view direction [0, -1, 0]"},
    {"wrong_type_section.json", 2, 11, "/film",
     "expected an object, got [\"box\"]"},
    {"wrong_type_string_for_integer.json", 2, 22, "/sampler/spp",
     "expected an integer in [1, 16777216], got \"16\""},
    {"wrong_vector_length.json", 2, 26, "/camera/position",
     "expected an array of 3 numbers [x, y, z], got [0, 1]"},
    {"zero_rotation_axis.json", 4, 40, "/lights/0/transform/0/rotate/axis",
     "expected a nonzero rotation axis, got [0, 0, 0]"},
    {"zero_scale.json", 6, 60, "/shapes/0/transform/1/scale/1",
     "expected a nonzero scale factor, got 0"},
};

std::filesystem::path bad_scenes_dir() {
    return std::filesystem::path(CANDELA_TEST_DATA_DIR) / "bad_scenes";
}

class BadSceneTest : public testing::TestWithParam<BadScene> {};

TEST_P(BadSceneTest, ReportsDefectAtItsLocation) {
    const BadScene& bad = GetParam();
    const std::filesystem::path file = bad_scenes_dir() / bad.file;
    try {
        load_scene(file);
        FAIL() << bad.file << " loaded without error";
    } catch (const SceneError& e) {
        const SourceLocation& where = e.where();
        EXPECT_EQ(where.file, file.string());
        EXPECT_EQ(where.line, bad.line) << e.what();
        EXPECT_EQ(where.column, bad.column) << e.what();
        EXPECT_EQ(where.json_pointer, bad.pointer) << e.what();
        EXPECT_NE(e.message().find(bad.message), std::string::npos)
            << "message: " << e.message() << "\nexpected to contain: " << bad.message;
        // The one line the CLI prints: file:line:col: /pointer: message.
        std::string prefix = file.string() + ":" + std::to_string(bad.line) + ":" +
                             std::to_string(bad.column) + ": ";
        if (*bad.pointer) prefix += std::string(bad.pointer) + ": ";
        EXPECT_EQ(std::string(e.what()), prefix + e.message());
    }
}

INSTANTIATE_TEST_SUITE_P(BadScenes, BadSceneTest, testing::ValuesIn(kBadScenes),
                         [](const testing::TestParamInfo<BadScene>& p) {
                             std::string name = std::filesystem::path(p.param.file).stem();
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

// A new bad scene without a table entry would otherwise go untested.
TEST(BadScenes, EveryFileHasAnExpectation) {
    std::set<std::string> listed;
    for (const BadScene& bad : kBadScenes) listed.insert(bad.file);
    std::set<std::string> present;
    for (const auto& entry : std::filesystem::directory_iterator(bad_scenes_dir()))
        if (entry.path().extension() == ".json") present.insert(entry.path().filename().string());
    EXPECT_EQ(listed, present);
    EXPECT_GE(present.size(), 25u);
}

}  // namespace
}  // namespace candela
