// The bad-input corpus (tests/data/bad_inputs/, docs/RELIABILITY.md): every scene there has
// exactly one defect, in the scene or in a mesh or image file next to it. The table says whether
// it is an error or a warning with a documented fallback, where it is reported, and what the
// message says. Each entry is checked twice: through load_scene_file (the located SceneError, or
// the line in Scene::warnings) and through the real CLI at 2x2 pixels and 1 spp (errors: exit code 2
// and exactly one line on stderr; warnings: exit code 0; never a signal, never a hang).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "candela/core/error.h"
#include "candela/formats/scene_file.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

// The kinds of malformed input issue 6 lists; each must have an entry.
enum Kind {
    kJsonSyntax, kEncoding, kDeepNesting, kStructure, kUnknownName, kNumber, kCamera, kLight,
    kDegenerate, kFileAccess, kObj, kPly, kImage, kPbrt, kMedium, kKindCount
};
enum Outcome { kError, kWarning };

struct BadInput {
    const char* scene;  // the scene file to load
    Kind kind;
    Outcome outcome;
    const char* where;  // the file the problem is reported in: "" for the scene itself, else the
                        // mesh or image it references (errors inside those keep their own location)
    int line;           // 1-based; 0 where the format has no lines (binary data, whole-file problems)
    int column;         // 1-based; 0 where there is none
    const char* pointer;
    const char* message;  // a fragment of the message
};

// gtest prints a failing parameter with this, rather than as raw bytes.
void PrintTo(const BadInput& bad, std::ostream* os) { *os << bad.scene; }

// Locations in a scene file: a bad value is reported at its first character; an unknown or
// repeated key at its opening quote, with the pointer of its object; a missing key at its
// object's opening brace; a JSON syntax error where the parser stopped. In a mesh or image file:
// the line (OBJ, ASCII PLY, PLY headers), or the element, record and byte offset (binary PLY).
const BadInput kBadInputs[] = {
    // --- participating media (issue 24)
    {"medium_negative_sigma.json", kMedium, kError, "", 2, 55, "/media/fog/sigma_a", "expected a number >= 0, got -0.1"},
    {"medium_unknown_name.json", kMedium, kError, "", 3, 24, "/camera/medium",
     "unknown medium \"smoke\"; defined media: fog"},
    {"medium_unknown_type.json", kMedium, kError, "", 2, 29, "/media/fog/type",
     "unknown medium type \"vdb\"; expected one of: cloud, homogeneous, nanovdb, openvdb, rgbgrid, uniformgrid"},
    {"medium_sigma_overflows.json", kMedium, kError, "", 2, 55, "/media/fog/sigma_s", "1e+39"},
    {"medium_grid_size_mismatch.json", kMedium, kError, "", 2, 76, "/media/smoke/density",
     "\"density\" has 7 numbers; size 2 x 2 x 2 needs 8"},
    {"medium_grid_negative_density.json", kMedium, kError, "", 2, 80, "/media/smoke/density/1",
     "expected a number >= 0, got -1"},
    {"medium_grid_huge_size.json", kMedium, kError, "", 2, 50, "/media/smoke/size",
     "a grid of 100000 x 100000 x 100000 voxels is beyond any memory"},
    // --- JSON syntax (7)
    {"comment.json", kJsonSyntax, kError, "", 2, 27, "",
     "(JSON allows no comments)"},
    {"duplicate_key.json", kJsonSyntax, kError, "", 5, 5, "/camera",
     "duplicate key \"fov\""},
    {"empty_file.json", kJsonSyntax, kError, "", 1, 1, "",
     "unexpected end of input"},
    {"single_quotes.json", kJsonSyntax, kError, "", 2, 3, "",
     "(JSON strings take double quotes)"},
    {"syntax_missing_colon.json", kJsonSyntax, kError, "", 2, 21, "",
     "expected ':'"},
    {"trailing_comma.json", kJsonSyntax, kError, "", 4, 1, "",
     "no comma after the last element"},
    {"truncated_json.json", kJsonSyntax, kError, "", 4, 1, "",
     "unexpected end of input; expected '}'"},
    // --- text that is not UTF-8 JSON (3)
    {"control_character_in_string.json", kEncoding, kError, "", 2, 19, "",
     "control character U+0009 (HT) must be escaped"},
    {"non_utf8_name.json", kEncoding, kError, "", 2, 20, "",
     "ill-formed UTF-8 byte; last read: '\"r\\xE9d'; expected string literal (scene files must be UTF-8)"},
    {"utf16_file.json", kEncoding, kError, "", 1, 1, "",
     "the file is UTF-16 text (it starts with a byte order mark or a NUL byte); scene files must be UTF-8"},
    // --- deep nesting (no reader may recurse per level) (3)
    {"deep_nesting_arrays.json", kDeepNesting, kError, "", 1, 25, "/camera/position",
     "expected an array of 3 numbers [x, y, z], got an array of 1 element"},
    {"deep_nesting_then_duplicate_key.json", kDeepNesting, kError, "", 3, 2, "",
     "duplicate key \"film\""},
    {"deep_nesting_unclosed.json", kDeepNesting, kError, "", 1, 100001, "",
     "JSON syntax error while parsing value - unexpected end of input"},
    // --- wrong types and shapes of values (25)
    {"cylinder_cut_out.json", kStructure, kError, "", 3, 85, "/shapes/0/material",
     "a cylinder cannot be cut out: material \"leaf\" has alpha < 1"},
    {"boolean_for_number.json", kStructure, kError, "", 2, 21, "/camera/fov",
     "expected a number in (0, 180), got true"},
    {"coated_conductor_reflectance_and_eta.json", kStructure, kError, "", 3, 61, "/materials/copper/conductor_eta",
     "give \"conductor_eta\" and \"conductor_k\" or \"reflectance\", not both"},
    {"conductor_eta_and_reflectance.json", kStructure, kError, "", 4, 21, "/materials/gold/eta",
     "give \"eta\" and \"k\" or \"reflectance\", not both"},
    {"environment_file_and_color.json", kStructure, kError, "", 3, 57, "/lights/0/color",
     "give \"file\" or \"color\", not both"},
    {"environment_without_radiance.json", kStructure, kError, "", 3, 5, "/lights/0",
     "an environment needs \"file\" (an .hdr or .exr image) or \"color\""},
    {"normal_map_and_bump_map.json", kStructure, kError, "", 4, 27, "/materials/bumpy/bump_map",
     "give \"normal_map\" or \"bump_map\", not both"},
    {"materials_not_object.json", kStructure, kError, "", 2, 16, "/materials",
     "expected an object, got an array of 1 element"},
    {"missing_required_key.json", kStructure, kError, "", 4, 5, "/shapes/0",
     "missing required key \"radius\""},
    {"mix_empty.json", kStructure, kError, "", 3, 41, "/materials/nothing/lobes",
     "expected an array of 1 to 4 materials, got an empty array"},
    {"mix_too_many_lobes.json", kStructure, kError, "", 3, 41, "/materials/layered/lobes",
     "expected an array of 1 to 4 materials, got an array of 5 elements"},
    {"null_value.json", kStructure, kError, "", 2, 22, "/sampler/spp",
     "expected an integer in [1, 16777216], got null"},
    {"resolution_wrong_length.json", kStructure, kError, "", 2, 28, "/camera/resolution",
     "expected an array of 2 integers [width, height], got [640]"},
    {"root_not_object.json", kStructure, kError, "", 1, 1, "",
     "expected an object, got an array of 1 element"},
    {"shapes_not_array.json", kStructure, kError, "", 3, 13, "/shapes",
     "expected an array, got an object"},
    {"string_for_vector.json", kStructure, kError, "", 2, 26, "/camera/position",
     "expected an array of 3 numbers [x, y, z], got \"0 1 5\""},
    {"transform_step_two_keys.json", kStructure, kError, "", 5, 66, "/shapes/0/transform/0",
     "a transform step has one key; put \"scale\" in a step of its own"},
    {"texture_cycle.json", kStructure, kError, "", 4, 46, "/textures/b/tex1/texture",
     "textures form a cycle: \"a\" -> \"b\" -> \"a\""},
    {"blend_cycle.json", kStructure, kError, "", 5, 42, "/materials/q/materials/0",
     "blends form a cycle: \"p\" -> \"q\" -> \"p\""},
    {"two_environments.json", kStructure, kError, "", 4, 5, "/lights/1",
     "a scene has at most one environment light, and /lights/0 is one"},
    {"wrong_type_section.json", kStructure, kError, "", 2, 11, "/film",
     "expected an object, got [\"box\"]"},
    {"wrong_type_string_for_integer.json", kStructure, kError, "", 2, 22, "/sampler/spp",
     "expected an integer in [1, 16777216], got \"16\""},
    {"wrong_vector_length.json", kStructure, kError, "", 2, 26, "/camera/position",
     "expected an array of 3 numbers [x, y, z], got [0, 1]"},
    {"object_shape_emission.json", kStructure, kError, "", 5, 83, "/objects/lamp/shapes/0",
     "the shapes of object \"lamp\" cannot emit: instances are not lights"},
    {"object_nested_instance.json", kStructure, kError, "", 5, 35, "/objects/grove/shapes/0/type",
     "object \"grove\" cannot hold an instance: objects do not nest"},
    // --- unknown keys, types and names (24)
    {"aov_space_unknown.json", kUnknownName, kError, "", 2, 47, "/film/aov_space",
     "unknown AOV space \"screen\"; expected one of: camera, world"},
    {"aov_unknown.json", kUnknownName, kError, "", 3, 31, "/film/aovs/1",
     "unknown AOV layer \"normals\"; expected one of: albedo, depth, normal, position, spp, variance"},
    {"environment_unknown_mapping.json", kUnknownName, kError, "", 3, 52, "/lights/0/mapping",
     "unknown environment mapping \"octahedral\"; expected one of: equal_area, equirectangular"},
    {"missing_key_near_miss.json", kUnknownName, kError, "", 4, 45, "/shapes/0",
     "unknown key \"radus\" (did you mean \"radius\"?)"},
    {"mix_nested.json", kUnknownName, kError, "", 5, 16, "/materials/coated/lobes/1/type",
     "a mix cannot contain a mix; expected one of: coated_conductor, coated_diffuse, conductor, dielectric, diffuse, diffuse_transmission, hair, mirror, thin_dielectric, transmission"},
    {"mix_unknown_lobe_type.json", kUnknownName, kError, "", 5, 16, "/materials/coated/lobes/1/type",
     "unknown material type \"glossy\"; expected one of: coated_conductor, coated_diffuse, conductor, dielectric, diffuse, diffuse_transmission, hair, mirror, thin_dielectric, transmission"},
    {"near_miss_material_key.json", kUnknownName, kError, "", 5, 7, "/materials/white",
     "unknown key \"albdo\" (did you mean \"albedo\"?)"},
    {"near_miss_top_level_key.json", kUnknownName, kError, "", 2, 3, "",
     "unknown key \"materails\" (did you mean \"materials\"?)"},
    {"sphere_with_transform.json", kUnknownName, kError, "", 5, 6, "/shapes/0",
     "unknown key \"transform\"; expected one of: center, emission, emission_scale, exterior, interior, material, motion, phi_max, radius, reverse_orientation, two_sided, type, z_max, z_min"},
    {"string_with_braces_before_error.json", kUnknownName, kError, "", 4, 51, "/materials/}{",
     "unknown key \"ior\"; expected one of: albedo, alpha, bump_map, normal_map, normal_map_convention, type"},
    {"transform_unknown_step.json", kUnknownName, kError, "", 5, 42, "/shapes/0/transform/0",
     "unknown key \"rotat\" (did you mean \"rotate\"?)"},
    {"undefined_material.json", kUnknownName, kError, "", 7, 70, "/shapes/0/material",
     "unknown material \"whte\"; defined materials: red, white"},
    {"unknown_camera_type.json", kUnknownName, kError, "", 2, 22, "/camera/type",
     "unknown camera type \"fisheye\"; expected one of: orthographic, perspective"},
    {"unknown_environment_sampling.json", kUnknownName, kError, "", 3, 53, "/lights/0/sampling",
     "unknown environment sampling \"cosine\"; expected one of: importance, uniform"},
    {"unknown_filter.json", kUnknownName, kError, "", 2, 22, "/film/filter",
     "unknown filter \"gausian\"; expected one of: box, gaussian, smallpt, tent"},
    {"unknown_fov_axis.json", kUnknownName, kError, "", 2, 37, "/camera/fov_axis",
     "unknown fov axis \"horizontal\"; expected one of: diagonal, larger, smaller, x, y"},
    {"unknown_fresnel.json", kUnknownName, kError, "", 3, 60, "/materials/glass/fresnel",
     "unknown fresnel \"shlick\"; expected one of: exact, schlick"},
    {"unknown_integrator_type.json", kUnknownName, kError, "", 2, 26, "/integrator/type",
     "unknown integrator type \"bdpt\"; expected one of: albedo, ao, bsdf, depth, normals, path, volpath, whitted"},
    {"unknown_light_type.json", kUnknownName, kError, "", 2, 23, "/lights/0/type",
     "unknown light type \"sun\"; expected one of: directional, environment, point, spot"},
    {"unknown_material_type.json", kUnknownName, kError, "", 3, 21, "/materials/red/type",
     "unknown material type \"glossy\"; expected one of: blend, coated_conductor, coated_diffuse, conductor, dielectric, diffuse, diffuse_transmission, hair, interface, mirror, mix, subsurface, thin_dielectric, transmission"},
    {"unknown_metal.json", kUnknownName, kError, "", 3, 44, "/materials/gold/metal",
     "unknown metal \"Gold\"; expected one of: Ag, Al, Au, Cr, Cu, CuZn, Fe, Ti"},
    {"unknown_shape_type.json", kUnknownName, kError, "", 4, 14, "/shapes/0/type",
     "unknown shape type \"shpere\"; expected one of: curves, cylinder, disk, instance, mesh, quad, sphere"},
    {"unknown_top_level_key.json", kUnknownName, kError, "", 2, 3, "",
     "unknown key \"renderer\"; expected one of: camera, film, integrator, lights, materials, media, objects, sampler, shapes, textures"},
    {"instance_unknown_object.json", kUnknownName, kError, "", 5, 36, "/shapes/0/object",
     "unknown object \"tre\" (did you mean \"tree\"?)"},
    {"unknown_texture.json", kUnknownName, kError, "", 3, 64, "/materials/m/albedo/texture",
     "unknown texture \"wod\"; defined textures: wood"},
    // --- numbers: negative, zero, NaN/Inf, beyond range (41)
    {"adaptive_threshold_negative.json", kNumber, kError, "", 2, 53, "/sampler/adaptive/threshold",
     "expected a number in (0, 1), got -0.01"},
    {"albedo_out_of_range.json", kNumber, kError, "", 3, 48, "/materials/red/albedo/1",
     "expected a number in [0, 1], got 1.2"},
    {"blend_amount_out_of_range.json", kNumber, kError, "", 5, 63, "/materials/m/amount",
     "expected a number in [0, 1], got 1.5"},
    {"alpha_out_of_range.json", kNumber, kError, "", 3, 57, "/materials/leaf/alpha",
     "expected a number in [0, 1], got 1.5"},
    {"camera_shutter_degenerate.json", kCamera, kError, "", 2, 40, "/camera/shutter/1",
     "close must be after open (1), got 0.5"},
    {"camera_motion_no_frame.json", kCamera, kError, "", 2, 35, "/camera/motion",
     "the end frame needs position, look_at or up"},
    {"camera_motion_look_at_equals_position.json", kCamera, kError, "", 2, 47, "/camera/motion/look_at",
     "look_at equals position"},
    {"shape_motion_emits.json", kStructure, kError, "", 2, 84, "/shapes/0", "a moving shape cannot emit"},
    {"shape_motion_mirrors.json", kStructure, kError, "", 4, 39, "/shapes/0/motion/transform",
     "the end transform mirrors space and the start transform does not"},
    {"shape_motion_in_object.json", kStructure, kError, "", 4, 43, "/objects/o/shapes/0/motion",
     "a shape of object \"o\" cannot move"},
    {"instance_motion_no_transform.json", kStructure, kError, "", 4, 60, "/shapes/0/motion",
     "missing required key \"transform\""},
    {"aperture_radius_negative.json", kNumber, kError, "", 2, 44, "/camera/aperture_radius",
     "expected a number >= 0, got -0.05"},
    {"filter_radius_negative.json", kNumber, kError, "", 2, 57, "/film/filter/radius/1",
     "expected a number in (0, 1024], got -1"},
    {"crop_window_empty.json", kNumber, kError, "", 3, 33, "/film/crop_window/1",
     "expected a number > 0.5 (x0), got 0.5"},
    {"screen_window_reversed.json", kCamera, kError, "", 2, 53, "/camera/screen_window/3",
     "expected a number > 1 (ymin), got -1"},
    {"camera_transform_and_position.json", kCamera, kError, "", 2, 55, "/camera",
     "\"position\" and \"transform\" both place the camera; give one of them"},
    {"disk_negative_radius.json", kNumber, kError, "", 3, 85, "/shapes/0/radius",
     "expected a number > 0, got -1"},
    {"sphere_phi_max_zero.json", kNumber, kError, "", 3, 78, "/shapes/0/phi_max",
     "expected a number in (0, 360], got 0"},
    {"disk_inner_radius_too_large.json", kNumber, kError, "", 3, 102, "/shapes/0/inner_radius",
     "expected inner_radius < radius (1), got 1"},
    {"environment_scale_negative.json", kNumber, kError, "", 2, 59, "/lights/0/scale",
     "expected a number >= 0, got -1"},
    {"exposure_out_of_range.json", kNumber, kError, "", 2, 47, "/film/exposure",
     "expected a number in [0, 1), got 1"},
    {"exposure_time_negative.json", kNumber, kError, "", 2, 41, "/film/exposure_time",
     "expected a number > 0, got -0.01"},
    {"focus_distance_zero.json", kNumber, kError, "", 2, 56, "/camera/focus_distance",
     "expected a number > 0, got 0"},
    {"fov_out_of_range.json", kNumber, kError, "", 3, 12, "/camera/fov",
     "expected a number in (0, 180), got 180"},
    {"fov_zero.json", kNumber, kError, "", 2, 21, "/camera/fov",
     "expected a number in (0, 180), got 0"},
    {"gamma_zero.json", kNumber, kError, "", 2, 42, "/film/gamma",
     "expected a number > 0, got 0"},
    {"huge_number.json", kNumber, kError, "", 2, 30, "/camera/position/1",
     "expected a finite number, got 1e400"},
    {"infinity_literal.json", kNumber, kError, "", 3, 30, "",
     "(JSON has no NaN or Infinity; give a finite number)"},
    {"ior_beyond_float.json", kNumber, kError, "", 2, 56, "/materials/glass/ior",
     "expected a number within float range (magnitude <= 3.4028235e+38), got 1e+39"},
    {"ior_zero.json", kNumber, kError, "", 2, 56, "/materials/glass/ior",
     "expected a number > 0, got 0"},
    {"matrix_not_affine.json", kNumber, kError, "", 9, 38, "/shapes/0/transform/0/matrix/14",
     "expected 0 (the last row of a transform matrix is [0, 0, 0, 1]), got 0.5"},
    {"mesh_transform_overflows.json", kNumber, kError, "", 4, 28, "/shapes/0/transform",
     "the transform moves vertex 2 of mesh file \"mesh_transform_overflows.obj\" beyond float range"},
    {"max_depth_too_large.json", kNumber, kError, "", 2, 45, "/integrator/max_depth",
     "expected an integer <= 2147483647, got 3000000000"},
    {"max_depth_zero.json", kNumber, kError, "", 2, 31, "/integrator/max_depth",
     "expected an integer >= 1, got 0"},
    {"nan_literal.json", kNumber, kError, "", 2, 21, "",
     "(JSON has no NaN or Infinity; give a finite number)"},
    {"negative_emission.json", kNumber, kError, "", 5, 39, "/shapes/0/emission",
     "expected a number >= 0, got -2"},
    {"orthographic_height_negative.json", kNumber, kError, "", 2, 48, "/camera/height",
     "expected a number > 0, got -2"},
    {"position_beyond_float.json", kNumber, kError, "", 2, 27, "/camera/position/0",
     "expected a number within float range"},
    {"radius_negative.json", kNumber, kError, "", 5, 55, "/shapes/1/radius",
     "expected a number > 0, got -1"},
    {"resolution_negative.json", kNumber, kError, "", 2, 34, "/camera/resolution/1",
     "expected an integer in [1, 32768], got -480"},
    {"resolution_too_large.json", kNumber, kError, "", 2, 34, "/camera/resolution/1",
     "expected an integer in [1, 32768], got 40000"},
    {"resolution_zero.json", kNumber, kError, "", 2, 29, "/camera/resolution/0",
     "expected an integer in [1, 32768], got 0"},
    {"roughness_negative.json", kNumber, kError, "", 2, 87, "/materials/metal/roughness/1",
     "expected a number >= 0, got -0.2"},
    {"rr_zero.json", kNumber, kError, "", 2, 24, "/integrator/rr",
     "expected a number in (0, 1], got 0"},
    {"seed_fraction.json", kNumber, kError, "", 2, 23, "/sampler/seed",
     "expected an integer in [0, 18446744073709551615], got 1.5"},
    {"seed_negative.json", kNumber, kError, "", 2, 23, "/sampler/seed",
     "expected an integer in [0, 18446744073709551615], got -3"},
    {"singular_matrix.json", kNumber, kError, "", 6, 31, "/shapes/0/transform/0/matrix",
     "the matrix is singular (determinant 0)"},
    {"spp_huge.json", kNumber, kError, "", 2, 22, "/sampler/spp",
     "expected an integer in [1, 16777216], got 1000000000000.0"},
    {"spp_not_integer.json", kNumber, kError, "", 2, 22, "/sampler/spp",
     "expected an integer in [1, 16777216], got 16.5"},
    {"spp_zero.json", kNumber, kError, "", 2, 33, "/sampler/spp",
     "expected an integer in [1, 16777216], got 0"},
    {"thin_lens_rays_overflow.json", kNumber, kError, "", 2, 68, "/camera/focus_distance",
     "a thin lens of aperture_radius 0.1 focused at 1e+37 gives rays beyond float range"},
    {"sensor_unknown.json", kUnknownName, kError, "", 2, 41, "/film/sensor",
     "unknown sensor \"canon_eos_5d_mk4\"; expected one of: canon_eos_100d, canon_eos_1dx_mkii, "},
    {"white_balance_too_low.json", kNumber, kError, "", 2, 48, "/film/white_balance",
     "expected 0 (no white balance) or a temperature >= 1000 (kelvin), got 500"},
    {"zero_rotation_axis.json", kNumber, kError, "", 4, 40, "/lights/0/transform/0/rotate/axis",
     "expected a nonzero rotation axis, got [0, 0, 0]"},
    {"zero_scale.json", kNumber, kError, "", 6, 60, "/shapes/0/transform/1/scale/1",
     "expected a nonzero scale factor, got 0"},
    // --- cameras without a frame, or with the keys of another camera type (7)
    {"camera_view_overflows.json", kCamera, kError, "", 2, 51, "/camera/look_at",
     "look_at [-3e+38, 0, 0] is too far from position [3e+38, 0, 0]: the view direction overflows float range"},
    {"fov_on_orthographic_camera.json", kCamera, kError, "", 3, 14, "/camera",
     "\"fov\" is a key of the perspective camera; an orthographic camera takes \"height\" (the image's height in scene units)"},
    {"height_on_perspective_camera.json", kCamera, kError, "", 2, 48, "/camera",
     "\"height\" is a key of the orthographic camera; a perspective camera takes \"fov\" (degrees)"},
    {"look_at_equals_position.json", kCamera, kError, "", 4, 16, "/camera/look_at",
     "look_at equals position [1, 2, 3]; the camera has no view direction"},
    {"orthographic_without_height.json", kCamera, kError, "", 2, 13, "/camera",
     "missing required key \"height\""},
    {"up_parallel_to_view.json", kCamera, kError, "", 5, 11, "/camera/up",
     "up [0, 2, 0] is parallel to the view direction [0, -1, 0]"},
    {"up_zero.json", kCamera, kError, "", 2, 65, "/camera/up",
     "expected a nonzero up vector, got [0, 0, 0]"},
    // --- lights that emit nothing, have no area or no direction, or cannot be seen (11)
    {"environment_illuminance_dark.json", kLight, kError, "", 5, 65, "/lights/0/illuminance",
     "the environment gives no light to a surface facing its up direction (+y), so no scale can make its illuminance 2"},
    {"bsdf_integrator_point_light.json", kLight, kError, "", 2, 26, "/integrator/type",
     "the bsdf integrator finds light only by hitting it, so it cannot see the point light at /lights/0 (point, spot and directional lights have no area); use path or whitted, or an area light (a shape with emission)"},
    {"directional_zero_direction.json", kLight, kError, "", 4, 51, "/lights/0/direction",
     "expected a nonzero direction, got [0, 0, 0]"},
    {"environment_black_image.json", kLight, kWarning, "", 5, 14, "/lights/0",
     "the environment light emits nothing (its image is black); it is ignored"},
    {"environment_scale_zero.json", kLight, kWarning, "", 5, 14, "/lights/0",
     "the environment light emits nothing (its scale is 0); it is ignored"},
    {"point_light_zero_intensity.json", kLight, kWarning, "", 5, 14, "/lights/0",
     "the point light emits nothing (its intensity is 0); it is ignored"},
    {"spot_cone_delta_wider_than_cone.json", kLight, kError, "", 5, 47, "/lights/0/cone_delta",
     "cone_delta 30 is larger than cone_angle 20: the falloff must lie inside the cone (expected a number in [0, 20])"},
    {"spot_look_at_position.json", kLight, kError, "", 4, 66, "/lights/0/look_at",
     "look_at equals position [0, 2, -3]; the spot light has no direction"},
    {"no_lights.json", kLight, kWarning, "", 0, 0, "",
     "the scene has no lights (no shape has an emission and there is no environment, point, spot or directional light); the path integrator will render a black image"},
    {"zero_area_quad_light.json", kLight, kError, "", 3, 86, "/shapes/0/edge2",
     "the quad has no area in float precision (its edges are too short)"},
    {"zero_emission.json", kLight, kWarning, "", 5, 27, "/shapes/1/emission",
     "emission 0: the shape is not a light"},
    // --- degenerate geometry (7)
    {"degenerate_quad.json", kDegenerate, kError, "", 4, 72, "/shapes/0/edge2",
     "edge2 [-2, 0, 0] is parallel to edge1 [1, 0, 0]; the quad has no area"},
    {"disk_zero_normal.json", kDegenerate, kError, "", 3, 63, "/shapes/0/normal",
     "expected a nonzero normal, got [0, 0, 0]"},
    {"cylinder_z_range_reversed.json", kDegenerate, kError, "", 3, 69, "/shapes/0/z_max",
     "expected z_min < z_max, got z_min 1 and z_max -1"},
    {"sphere_z_range_misses.json", kDegenerate, kError, "", 3, 76, "/shapes/0/z_min",
     "the z range [1.5, 2] misses the sphere of radius 1"},
    {"degenerate_triangles.json", kDegenerate, kWarning, "", 3, 39, "/shapes/0/file",
     "mesh file \"degenerate_triangles.obj\": skipped 2 of 4 triangles that have zero area (degenerate; the first is triangle 2)"},
    {"emitter_all_degenerate.json", kDegenerate, kError, "", 3, 39, "/shapes/0/file",
     "all 2 triangles of mesh file \"emitter_all_degenerate.obj\" have zero area (degenerate)"},
    {"quad_transform_overflows.json", kDegenerate, kError, "", 4, 28, "/shapes/0/transform",
     "the transform leaves the quad with no area in float precision"},
    // --- referenced files: missing, empty, folders, unreadable, unknown kind (13)
    {"environment_is_folder.json", kFileAccess, kError, "", 2, 46, "/lights/0/file",
     "environment image file \"environment_is_folder.hdr\" is a folder, not a file"},
    {"exr_empty.json", kFileAccess, kError, "exr_empty.exr", 0, 0, "",
     "not an OpenEXR image (bad magic number or truncated header)"},
    {"hdr_empty.json", kFileAccess, kError, "hdr_empty.hdr", 0, 0, "",
     "not a Radiance HDR image: expected \"#?RADIANCE\" at the start"},
    {"mesh_binary_garbage.json", kFileAccess, kError, "mesh_binary_garbage.obj", 0, 0, "",
     "the mesh file has no triangles"},
    {"mesh_empty_obj.json", kFileAccess, kError, "mesh_empty.obj", 0, 0, "",
     "the mesh file has no triangles"},
    {"mesh_empty_ply.json", kFileAccess, kError, "mesh_empty.ply", 1, 0, "",
     "not a PLY file: expected \"ply\" on the first line"},
    {"mesh_is_folder.json", kFileAccess, kError, "", 3, 39, "/shapes/0/file",
     "mesh file \"mesh_is_folder.obj\" is a folder, not a file"},
    {"mesh_unknown_extension.json", kFileAccess, kError, "mesh_unknown_extension.stl", 0, 0, "",
     "unknown mesh file extension \".stl\"; expected one of: .obj, .ply, .ply.gz"},
    {"mesh_unreadable.json", kFileAccess, kError, "mesh_unreadable.ply", 0, 0, "",
     "cannot read mesh file: Permission denied"},
    {"missing_environment_file.json", kFileAccess, kError, "", 3, 37, "/lights/0/file",
     "environment image file \"missing_sky.hdr\" not found"},
    {"missing_mesh_file.json", kFileAccess, kError, "", 4, 30, "/shapes/0/file",
     "mesh file \"meshes/missing.obj\" not found"},
    {"missing_texture_file.json", kFileAccess, kError, "", 2, 47, "/textures/t/file",
     "texture image file \"missing_texture.png\" not found"},
    {"scene_is_folder.json", kFileAccess, kError, "", 0, 0, "",
     "is a folder, not a scene file"},
    // --- OBJ meshes (11)
    {"obj_face_index_before_first.json", kObj, kError, "obj_face_index_before_first.obj", 5, 0, "",
     "face refers to a vertex before the first one, but the file has 3 v statements"},
    {"obj_face_index_out_of_range.json", kObj, kError, "obj_face_index_out_of_range.obj", 6, 0, "",
     "face refers to vertex 4, but the file has 3 v statements"},
    {"obj_face_index_overflow.json", kObj, kError, "obj_face_index_overflow.obj", 5, 0, "",
     "face index 99999999999 is out of range"},
    {"obj_face_index_zero.json", kObj, kError, "obj_face_index_zero.obj", 5, 0, "",
     "zero value for face index"},
    {"obj_face_not_indices.json", kObj, kError, "obj_face_not_indices.obj", 5, 0, "",
     "face corner \"a\" is not v, v/vt, v//vn or v/vt/vn with integer indices"},
    {"obj_face_two_corners.json", kObj, kError, "obj_face_two_corners.obj", 5, 0, "",
     "a face has fewer than 3 vertices (2)"},
    {"obj_normal_index_out_of_range.json", kObj, kError, "obj_normal_index_out_of_range.obj", 6, 0, "",
     "face refers to normal 2, but the file has 1 vn statements"},
    {"obj_vertex_beyond_float.json", kObj, kError, "obj_vertex_beyond_float.obj", 4, 0, "",
     "a vertex position (v x y z): \"1e39\" is not a finite number within float range"},
    {"obj_vertex_missing_coordinate.json", kObj, kError, "obj_vertex_missing_coordinate.obj", 3, 0, "",
     "a vertex position (v x y z): expected 3 numbers, got 2"},
    {"obj_vertex_nan.json", kObj, kError, "obj_vertex_nan.obj", 3, 0, "",
     "a vertex position (v x y z): \"nan\" is not a finite number within float range"},
    {"obj_vertex_not_number.json", kObj, kError, "obj_vertex_not_number.obj", 4, 0, "",
     "a vertex position (v x y z): expected a number, got \"one\""},
    // --- PLY meshes (16)
    {"ply_absurd_face_count.json", kPly, kError, "ply_absurd_face_count.ply", 7, 0, "",
     "element \"face\" declares 10000000000 records of at least 1 bytes each, but the data after the header has only 49 bytes"},
    {"ply_absurd_list_length.json", kPly, kError, "ply_absurd_list_length.ply", 0, 0, "",
     "element \"face\", record 1 of 1: unexpected end of file (file truncated?) (at byte 52"},
    {"ply_absurd_vertex_count.json", kPly, kError, "ply_absurd_vertex_count.ply", 3, 0, "",
     "element \"vertex\" declares 4000000000 records of at least 12 bytes each, but the data after the header has only 49 bytes"},
    {"ply_ascii_bad_value.json", kPly, kError, "ply_ascii_bad_value.ply", 11, 0, "",
     "element \"vertex\", record 2 of 3: expected a value of type float, got \"zero\""},
    {"ply_ascii_index_out_of_range.json", kPly, kError, "ply_ascii_index_out_of_range.ply", 13, 0, "",
     "element \"face\", record 1 of 1: vertex index 3 is out of range; the file has 3 vertices"},
    {"ply_gz_truncated.json", kPly, kError, "ply_gz_truncated.ply.gz", 0, 0, "",
     "the gzip data ends before the stream does (file truncated?)"},
    {"ply_index_out_of_range.json", kPly, kError, "ply_index_out_of_range.ply", 0, 0, "",
     "element \"face\", record 1 of 1: vertex index 7 is out of range; the file has 3 vertices (at byte 49 of the data after the header)"},
    {"ply_missing_end_header.json", kPly, kError, "ply_missing_end_header.ply", 6, 0, "",
     "the PLY header has no \"end_header\" line"},
    {"ply_nan_position.json", kPly, kError, "ply_nan_position.ply", 0, 0, "",
     "element \"vertex\", record 2 of 3: the vertex position (nan, 0, 0) is not finite (at byte 24"},
    {"ply_negative_index.json", kPly, kError, "ply_negative_index.ply", 0, 0, "",
     "vertex index -1 is out of range; the file has 3 vertices (at byte 45"},
    {"ply_no_faces.json", kPly, kError, "ply_no_faces.ply", 7, 0, "",
     "the PLY header declares no \"face\" element"},
    {"ply_not_ply.json", kPly, kError, "ply_not_ply.ply", 1, 0, "",
     "not a PLY file: expected \"ply\" on the first line"},
    {"ply_truncated_binary.json", kPly, kError, "ply_truncated_binary.ply", 0, 0, "",
     "element \"face\", record 1 of 1: unexpected end of file (file truncated?) (at byte 41 of the data after the header)"},
    {"ply_two_corner_face.json", kPly, kError, "ply_two_corner_face.ply", 0, 0, "",
     "a face has 2 vertices; expected at least 3 (at byte 37"},
    {"ply_unknown_format.json", kPly, kError, "ply_unknown_format.ply", 2, 0, "",
     "unknown PLY format \"binary_middle_endian\""},
    {"ply_vertex_count_beyond_index.json", kPly, kError, "ply_vertex_count_beyond_index.ply", 3, 0, "",
     "1000000000000 vertices are more than the 2^32 - 1 a mesh can index"},
    // --- HDR, EXR and texture images (13)
    {"environment_equal_area_not_square.json", kImage, kError, "", 3, 37, "/lights/0/file",
     "environment image \"environment_equal_area_not_square.hdr\" is 2x1; an equal_area map must be square"},
    {"environment_not_hdr.json", kImage, kError, "", 3, 37, "/lights/0/file",
     "expected an .hdr or .exr image (linear radiance), got \"sky.png\""},
    {"exr_absurd_size.json", kImage, kError, "exr_absurd_size.exr", 0, 0, "",
     "truncated or corrupt OpenEXR image: the pixel data of row 0 is missing"},
    {"exr_bad_magic.json", kImage, kError, "exr_bad_magic.exr", 0, 0, "",
     "not an OpenEXR image (bad magic number or truncated header)"},
    {"exr_truncated_data.json", kImage, kError, "exr_truncated_data.exr", 0, 0, "",
     "truncated or corrupt OpenEXR image: the pixel data of row 1 is missing"},
    {"exr_truncated_header.json", kImage, kError, "exr_truncated_header.exr", 0, 0, "",
     "corrupt OpenEXR header"},
    {"hdr_absurd_size.json", kImage, kError, "hdr_absurd_size.hdr", 0, 0, "",
     "truncated Radiance HDR image: data ends in row 0 of 4096"},
    {"hdr_bad_magic.json", kImage, kError, "hdr_bad_magic.hdr", 0, 0, "",
     "not a Radiance HDR image: expected \"#?RADIANCE\" at the start"},
    {"hdr_bad_resolution_line.json", kImage, kError, "hdr_bad_resolution_line.hdr", 0, 0, "",
     "unsupported or corrupt Radiance HDR resolution line \"+X 2 -Y 1\"; expected \"-Y height +X width\""},
    {"hdr_truncated_data.json", kImage, kError, "hdr_truncated_data.hdr", 0, 0, "",
     "truncated Radiance HDR image: data ends in row 1 of 2"},
    {"hdr_truncated_header.json", kImage, kError, "hdr_truncated_header.hdr", 0, 0, "",
     "truncated Radiance HDR header"},
    {"hdr_zero_size.json", kImage, kError, "hdr_zero_size.hdr", 0, 0, "",
     "image has zero size (2x0)"},
    {"texture_corrupt.json", kImage, kError, "texture_corrupt.png", 0, 0, "",
     "not a PNG, JPEG, TGA or BMP image, or a corrupt one"},
    // --- pbrt-v4 scenes, through the importer (18): the parser's syntax errors and pbrt-v4's
    // semantics (blocks, names, indices), located at the directive or value at fault
    {"pbrt_binary_scene.pbrt", kPbrt, kError, "", 0, 0, "",
     "is a binary file, not pbrt-v4 scene text (ill-formed UTF-8 (0x89 at byte 1))"},
    {"pbrt_gzip_include_error.pbrt", kPbrt, kError, "pbrt_gzip_include_error_geometry.pbrt.gz", 3, 16, "",
     "unknown parameter type \"flaot\" in \"flaot radius\""},
    {"pbrt_transform_times_degenerate.pbrt", kPbrt, kError, "", 2, 1, "",
     "TransformTimes: the end time (1) must be after the start (1)"},
    {"pbrt_animated_area_light.pbrt", kPbrt, kError, "", 10, 1, "",
     "Shape: animated area lights are not supported (as in pbrt-v4)"},
    {"pbrt_attribute_end_unmatched.pbrt", kPbrt, kError, "", 8, 1, "",
     "AttributeEnd without a matching AttributeBegin"},
    {"pbrt_attribute_unclosed.pbrt", kPbrt, kError, "", 7, 1, "",
     "AttributeBegin without a matching AttributeEnd"},
    {"pbrt_gbuffer_coordinate_system.pbrt", kPbrt, kError, "", 5, 3, "",
     "unknown coordinate system \"raster\" for the gbuffer film; expected \"camera\" or \"world\""},
    {"pbrt_include_cycle.pbrt", kPbrt, kError, "", 8, 1, "",
     "pbrt_include_cycle.pbrt -> "},  // "include cycle: A -> A", the files as opened
    {"pbrt_malformed_parameter.pbrt", kPbrt, kError, "", 7, 16, "",
     "parameter \"radius\" has no type (expected \"type name\", e.g. \"float radius\")"},
    {"pbrt_mesh_index_out_of_range.pbrt", kPbrt, kError, "", 8, 5, "",
     "trianglemesh: index 3 is out of range (P has 3 points)"},
    {"pbrt_unknown_light_sampler.pbrt", kPbrt, kError, "", 5, 19, "",
     "unknown lightsampler \"bhv\"; expected one of: bvh, exhaustive, power, uniform"},
    {"pbrt_missing_include.pbrt", kPbrt, kError, "", 7, 1, "",
     "pbrt_missing_include_geometry.pbrt\": No such file or directory"},
    {"pbrt_number_overflow.pbrt", kPbrt, kError, "", 7, 31, "",
     "\"float radius\": \"1e999\" is beyond the range of a double"},
    {"pbrt_shape_before_world.pbrt", kPbrt, kError, "", 5, 1, "",
     "Shape must come after WorldBegin"},
    {"pbrt_curve_too_few_points.pbrt", kPbrt, kError, "", 7, 15, "",
     "curve: 3 control points do not make a degree 3 Bezier curve (4 + n * 3 are needed, n >= 0)"},
    {"pbrt_undefined_named_material.pbrt", kPbrt, kError, "", 8, 1, "",
     "NamedMaterial: no material named \"whte\""},
    {"pbrt_undefined_object.pbrt", kPbrt, kError, "", 10, 1, "",
     "ObjectInstance: no object named \"tre\""},
    {"pbrt_unknown_directive.pbrt", kPbrt, kError, "", 8, 1, "",
     "unknown directive \"AttributeBeginn\""},
    {"pbrt_unknown_texture.pbrt", kPbrt, kError, "", 8, 20, "",
     "texture \"wod\" is not defined"},
    {"pbrt_unknown_sensor.pbrt", kPbrt, kError, "", 5, 3, "",
     "unknown sensor \"nikon_d800\"; expected one of: canon_eos_100d, "},
    {"pbrt_unsupported_shape.pbrt", kPbrt, kWarning, "", 8, 1, "",
     "Shape \"hyperboloid\" is not supported; skipped"},
    {"pbrt_cylinder_empty_z_range.pbrt", kPbrt, kWarning, "", 8, 1, "",
     "cylinder: an empty z range or phimax 0 leaves no surface; skipped, as pbrt-v4 renders nothing"},
    {"pbrt_unterminated_string.pbrt", kPbrt, kError, "", 8, 7, "",
     "unterminated string (a line break inside it)"},
    {"pbrt_wrong_parameter_type.pbrt", kPbrt, kError, "", 7, 31, "",
     "\"float radius\": expected a number, got the string \"one\""},
};

// mesh_unreadable.json's mesh is committed readable (git keeps no permissions); the test reads a
// copy whose permissions are taken away.
constexpr const char* kUnreadableScene = "mesh_unreadable.json";
constexpr const char* kUnreadableMesh = "mesh_unreadable.ply";
constexpr uid_t kNobody = 65534;

fs::path corpus_dir() { return fs::path(CANDELA_TEST_DATA_DIR) / "bad_inputs"; }

// The folder the scene of `bad` is read from: the corpus, or a copy for the unreadable mesh (one
// per test, `use`, as ctest may run them at once).
fs::path scene_dir(const BadInput& bad, const char* use) {
    if (std::string(bad.scene) != kUnreadableScene) return corpus_dir();
    const fs::path dir = fs::path(CANDELA_TEST_BINARY_DIR) / (std::string("bad_inputs_unreadable_") + use);
    fs::create_directories(dir);
    for (const char* name : {kUnreadableScene, kUnreadableMesh}) {
        fs::remove(dir / name);
        fs::copy_file(corpus_dir() / name, dir / name);
    }
    fs::permissions(dir / kUnreadableMesh, fs::perms::none);
    return dir;
}

// root reads any file whatever its permissions, so as root the unreadable case runs as nobody.
bool must_drop_root(const BadInput& bad) { return std::string(bad.scene) == kUnreadableScene && geteuid() == 0; }

void drop_root() {
    if (setgid(kNobody) != 0 || setuid(kNobody) != 0) _exit(125);
}

// "file:line:col: /pointer: " as SceneError::what() starts.
std::string location_prefix(const BadInput& bad, const fs::path& dir) {
    const fs::path file = dir / (*bad.where ? bad.where : bad.scene);
    std::string prefix = file.string();
    if (bad.line > 0) prefix += ":" + std::to_string(bad.line);
    if (bad.column > 0) prefix += ":" + std::to_string(bad.column);
    prefix += ": ";
    if (*bad.pointer) prefix += std::string(bad.pointer) + ": ";
    return prefix;
}

// What load_scene_file (JSON, or the importer for .pbrt) did with one entry: the error's what()
// and parts, or the warnings.
struct LoadResult {
    bool failed = false;
    std::string what;
    SourceLocation where;
    std::string message;
    std::vector<std::string> warnings;
};

LoadResult load(const fs::path& scene) {
    LoadResult r;
    try {
        r.warnings = load_scene_file(scene).warnings;
    } catch (const SceneError& e) {
        r.failed = true;
        r.what = e.what();
        r.where = e.where();
        r.message = e.message();
    }
    return r;
}

// load(), in a child process that drops root first: its result comes back through a pipe.
LoadResult load_without_root(const fs::path& scene) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        drop_root();
        const LoadResult r = load(scene);
        std::string out = r.failed ? "E" + r.where.file + "\n" + std::to_string(r.where.line) + "\n" + r.message
                                   : std::string("L");
        (void)!write(fds[1], out.data(), out.size());
        _exit(0);
    }
    close(fds[1]);
    std::string in;
    char buffer[4096];
    for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) in.append(buffer, size_t(n));
    close(fds[0]);
    waitpid(pid, nullptr, 0);
    LoadResult r;
    if (in.empty() || in[0] != 'E') return r;
    std::istringstream lines(in.substr(1));
    std::string line;
    std::getline(lines, r.where.file);
    std::getline(lines, line);
    r.where.line = std::stoi(line);
    std::getline(lines, r.message, '\0');
    r.failed = true;
    r.what = r.where.file + ": " + r.message;  // line 0: no line in what()
    return r;
}

class BadInputTest : public testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, LoadSceneReportsItWhereItIs) {
    const BadInput& bad = GetParam();
    const fs::path dir = scene_dir(bad, "load");
    const LoadResult r = must_drop_root(bad) ? load_without_root(dir / bad.scene) : load(dir / bad.scene);
    const std::string prefix = location_prefix(bad, dir);
    if (bad.outcome == kWarning) {
        ASSERT_FALSE(r.failed) << r.what;
        const auto found = std::find_if(r.warnings.begin(), r.warnings.end(), [&](const std::string& w) {
            return w.starts_with(prefix) && w.find(bad.message) != std::string::npos;
        });
        EXPECT_NE(found, r.warnings.end()) << "expected a warning starting with " << prefix << " and containing "
                                           << bad.message << "; got " << testing::PrintToString(r.warnings);
        return;
    }
    ASSERT_TRUE(r.failed) << bad.scene << " loaded without error";
    EXPECT_EQ(r.where.file, (dir / (*bad.where ? bad.where : bad.scene)).string()) << r.what;
    EXPECT_EQ(r.where.line, bad.line) << r.what;
    if (!must_drop_root(bad)) {
        EXPECT_EQ(r.where.column, bad.column) << r.what;
        EXPECT_EQ(r.where.json_pointer, bad.pointer) << r.what;
    }
    EXPECT_NE(r.message.find(bad.message), std::string::npos)
        << "message: " << r.message << "\nexpected to contain: " << bad.message;
    // The one line the CLI prints: file:line:col: /pointer: message.
    EXPECT_EQ(r.what, prefix + r.message);
    // An error inside a referenced file also names the scene key that referenced it (a pbrt-v4
    // scene's included file: the Include directive).
    if (*bad.where) {
        const char* reference = bad.kind == kPbrt ? " (included from " : " (referenced by /";
        EXPECT_NE(r.message.find(reference), std::string::npos) << r.message;
    }
}

// The CLI's exit status, stderr and wall time; a run past the time limit is killed.
struct CliRun {
    int status = 0;  // as waitpid gives it
    std::string err;
    double seconds = 0;
    bool timed_out = false;
};

CliRun run_cli(const fs::path& scene, const fs::path& out_dir, bool drop) {
    fs::create_directories(out_dir);
    const fs::path err_file = out_dir / "stderr.txt";
    const std::string image = (out_dir / "out.png").string();
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
        const int err = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_WRONLY);
        if (err < 0 || null < 0 || dup2(err, 2) < 0 || dup2(null, 1) < 0) _exit(126);
        if (drop) drop_root();
        execl(CANDELA_CLI, CANDELA_CLI, "render", scene.c_str(), "--resolution", "2x2", "--spp", "1", "--threads", "1",
              "-o", image.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    CliRun run;
    constexpr double kLimitSeconds = 60;
    for (;;) {
        const pid_t done = waitpid(pid, &run.status, WNOHANG);
        run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (done == pid) break;
        if (run.seconds > kLimitSeconds) {
            kill(pid, SIGKILL);
            waitpid(pid, &run.status, 0);
            run.timed_out = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::ifstream in(err_file, std::ios::binary);
    run.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return run;
}

TEST_P(BadInputTest, CliExitsTwoWithOneLineOrWarnsAndRenders) {
    const BadInput& bad = GetParam();
    const fs::path dir = scene_dir(bad, "cli");
    const fs::path out_dir = fs::path(CANDELA_TEST_BINARY_DIR) / "bad_inputs_cli" / fs::path(bad.scene).stem();
    fs::remove_all(out_dir);
    const CliRun run = run_cli(dir / bad.scene, out_dir, must_drop_root(bad));
    ASSERT_FALSE(run.timed_out) << "candela hung on " << bad.scene;
    ASSERT_FALSE(WIFSIGNALED(run.status)) << "candela died of signal " << WTERMSIG(run.status) << "\n" << run.err;
    ASSERT_TRUE(WIFEXITED(run.status));
    EXPECT_LT(run.seconds, 10.0);  // a bad input is found at once, not after a render
    const std::string prefix = location_prefix(bad, dir);
    if (bad.outcome == kWarning) {
        EXPECT_EQ(WEXITSTATUS(run.status), 0) << run.err;
        EXPECT_NE(run.err.find("candela: warning: " + prefix), std::string::npos) << run.err;
        EXPECT_NE(run.err.find(bad.message), std::string::npos) << run.err;
        EXPECT_TRUE(fs::exists(out_dir / "out.png"));
        return;
    }
    EXPECT_EQ(WEXITSTATUS(run.status), 2) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_TRUE(run.err.starts_with("candela: error: " + prefix)) << run.err;
    EXPECT_NE(run.err.find(bad.message), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out_dir / "out.png"));
}

INSTANTIATE_TEST_SUITE_P(BadInputs, BadInputTest, testing::ValuesIn(kBadInputs),
                         [](const testing::TestParamInfo<BadInput>& p) {
                             std::string name = fs::path(p.param.scene).stem();
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

// A new scene without a table entry would otherwise go untested, and a mesh or image no scene
// names would be dead weight.
TEST(BadInputs, EveryFileHasAnExpectation) {
    std::set<std::string> listed;
    for (const BadInput& bad : kBadInputs) EXPECT_TRUE(listed.insert(bad.scene).second) << bad.scene;
    std::set<std::string> scenes;
    std::string all_scene_text;
    std::vector<std::string> others;
    for (const auto& entry : fs::directory_iterator(corpus_dir())) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".json") {
            scenes.insert(name);
            if (entry.is_directory()) continue;  // scene_is_folder.json
            std::ifstream in(entry.path(), std::ios::binary);
            all_scene_text.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        } else if (entry.path().extension() == ".pbrt") {
            scenes.insert(name);  // pbrt-v4 scenes (issue 15), loaded through the importer
            std::ifstream in(entry.path(), std::ios::binary);
            all_scene_text.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        } else if (name != "README.md" && name != "make_bad_inputs.py") {
            others.push_back(name);
        }
    }
    EXPECT_EQ(listed, scenes);
    for (const std::string& name : others)
        EXPECT_NE(all_scene_text.find("\"" + name + "\""), std::string::npos) << name << " is named by no scene";
    EXPECT_GE(scenes.size(), 100u);
}

TEST(BadInputs, EveryKindHasAnEntry) {
    std::map<int, int> per_kind;
    for (const BadInput& bad : kBadInputs) ++per_kind[bad.kind];
    for (int k = 0; k < kKindCount; ++k) EXPECT_GT(per_kind[k], 0) << "kind " << k;
}

}  // namespace
}  // namespace candela
