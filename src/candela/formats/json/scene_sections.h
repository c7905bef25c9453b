#pragma once
// The readers for the parts of a scene file, shared by the scene loader's source files (internal to
// scene/). Each takes a cursor on its part, fills the Scene, and rejects keys it did not read.
#include <array>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "candela/core/error.h"
#include "candela/math/constants.h"
#include "candela/math/animated_transform.h"
#include "candela/math/transform.h"
#include "candela/formats/curves/curve_file.h"
#include "candela/formats/json/json_cursor.h"
#include "candela/formats/mesh/mesh_store.h"
#include "candela/scene/memory_budget.h"
#include "candela/scene/scene.h"

namespace candela {

// `transform`: an array of one-key steps (translate, scale, rotate, matrix), the first listed
// applied first. A matrix's last row must be [0, 0, 0, 1] unless `rows` allows a projective one
// (meshes and environment lights, which pbrt-v4's scenes give such matrices: points are divided by
// w, directions take the upper 3x3, as in pbrt-v4).
enum class MatrixRows { kAffine, kProjective };
Transform read_transform(const JsonCursor& steps, MatrixRows rows = MatrixRows::kAffine);

// `film.filter`: a name (box, tent, gaussian, smallpt) or an object {"type": ..., parameters}.
FilterSettings read_filter(JsonCursor filter);

// `film.crop_window`: [x0, x1, y0, y1], fractions of the camera's resolution; it must cover at least
// one pixel of it.
std::array<float, 4> read_crop_window(const JsonCursor& crop, const CameraSettings& camera);

// `film.aovs`: an array of distinct AOV layer names (film/aov_layers.h).
AovLayers read_aov_layers(const JsonCursor& aovs);

// `textures`: name -> texture, read before the materials that name them. A texture may name
// textures defined after it (but not itself, through any chain). The image files are read later,
// by load_texture_images.
void read_textures(JsonCursor textures, Scene& scene);

// Reads the image files scene.texture_files lists (each once) into scene.textures, charging
// each to `budget` before its texels are allocated. Errors are located at the `file` key that
// first names the file.
void load_texture_images(Scene& scene, const JsonDocument& document, MemoryBudget& budget);

// `media`: name -> participating medium (media/medium.h), in file order; grids are charged to
// `budget` before they are allocated.
void read_media(JsonCursor media, Scene& scene, MemoryBudget& budget);
// A medium of pbrt-v4's bounded kinds (scene_media_grids.cpp): `type` uniformgrid, rgbgrid or
// cloud, placed by `to_world` (its `transform`); grids charged to `budget` before they are read.
Medium read_bounded_medium(std::string_view type, JsonCursor& medium, const Scene& scene, const Transform& to_world,
                           MemoryBudget& budget);
// `nanovdb` (a .nvdb file, pbrt-v4's) and `openvdb` (a .vdb file): a grid medium of the file's
// density grid and, when the file has one, its temperature grid (scene_media_vdb.cpp).
Medium read_vdb_medium(std::string_view type, JsonCursor& medium, const Scene& scene, const Transform& to_world,
                       MemoryBudget& budget);
// The medium a camera or shape names: its index, or kNoMedium for "" (pbrt-v4's "no medium").
uint32_t medium_index(const JsonCursor& c, const Scene& scene);
// What every medium type reads alike (scene_media.cpp): a coefficient (a number, [r, g, b] or a
// spectrum, >= 0; an RGB value's spectrum is pbrt-v4's RGBUnboundedSpectrum), `scale` (default
// 1), `g` (default 0), and the emission `Le` times a number `Le_scale` (nullopt without `Le` or
// when black; a spectrum normalized to luminance 1, an RGB value's illuminant uplift, as area
// lights' emission). A grid's `Le_scale` array is the grid reader's to read. An RGB value's
// spectra: medium_coefficient and medium_emission (media/medium_spectrum.h).
MediumSpectrum read_medium_coefficient(const JsonCursor& c, const Scene& scene);
float read_medium_scale(JsonCursor& medium);
// `sigma_a` and `sigma_s` (default 1 each, as pbrt-v4's), both times `scale` when `scalable` (a
// cloud takes no scale).
void read_medium_coefficients(JsonCursor& medium, const Scene& scene, MediumSpectrum& sigma_a, MediumSpectrum& sigma_s,
                              bool scalable = true);
// A temperature grid's mapping to kelvin: `temperature_offset` (default `temperature_cutoff`, then 0,
// as pbrt-v4's) and `temperature_scale` (default 1).
void read_temperature_mapping(JsonCursor& medium, float& offset, float& scale);
float read_medium_g(JsonCursor& medium);
std::optional<MediumSpectrum> read_medium_emission(JsonCursor& medium, const Scene& scene);

// `materials`: name -> material, in file order.
void read_materials(JsonCursor materials, Scene& scene);
// A material's `roughness`: one alpha for both directions, or [alpha_u, alpha_v]; each a number
// or a texture.
RoughnessParams read_roughness(const JsonCursor& c, Scene& scene);
// A `subsurface` material (scene_subsurface.cpp) named `material_name`: its interior joins
// Scene::subsurfaces, and for the random walk its medium joins Scene::media.
Material read_subsurface(JsonCursor& c, Scene& scene, const std::string& material_name);

// A colour parameter of a material: a constant (one number or [r, g, b], each within `bounds`),
// `{"texture": NAME}` naming one of the `textures`, or a texture object written in place. A
// texture's value is clamped to `bounds` where it is looked up (texture_param.h).
ColorParam read_color_param(const JsonCursor& c, Scene& scene, const Bounds& bounds);
// A number parameter of a material: a constant within `bounds`, or a texture as above, read as
// a number (textures/texture_kinds.h).
FloatParam read_float_param(const JsonCursor& c, Scene& scene, const Bounds& bounds);

// A material's `normal_map`: a file name (an image texture of it, read linearly, repeating), or
// a colour parameter in [0, 1] as read_color_param reads it.
ColorParam read_normal_map_param(const JsonCursor& c, Scene& scene);

// The world-space box around an object's shapes (in object space), as they are read: an instance
// checks that its transform keeps them within float range.
struct ObjectBounds {
    Vec3d lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

    bool empty() const { return lo.x > hi.x; }
    void add(const Vec3d& p);
    void add(const TriangleMesh& mesh);
    void add(const Sphere& sphere);
    void add(const Disk& disk);
    void add(const Quadric& quadric);
};

// Where a list of shapes is read: the scene's `shapes` (object empty), or an object's, whose shapes
// may neither emit nor be instances, and which collects their bounds.
struct ShapeSection {
    std::filesystem::path folder;            // mesh files are relative to it
    std::optional<std::string> object;       // the object's name; none for the scene's shapes
    ObjectBounds* bounds = nullptr;          // the object's, while it is read
    std::span<const ObjectBounds> objects;   // every object's, for instances
    const MeshStore* meshes = nullptr;       // meshes by file name, found before the disk (mesh_store.h)
    const CurveStore* curves = nullptr;      // curves by file name, likewise (curve_file.h)
};

// `shapes`: meshes (loaded relative to the section's folder, each charged to `budget` before it
// is built), quads, spheres, disks and instances of objects; needs the materials and objects.
void read_shapes(const JsonCursor& shapes, const ShapeSection& section, Scene& scene, MemoryBudget& budget);

// Whether shape `c` of `type` is a clipped quadric (scene_quadrics.cpp): a cylinder, or a sphere
// or disk with partial parameters. Marks the keys it looks at as read.
bool is_partial_quadric(JsonCursor& c, std::string_view type);
// Such a shape's geometry (all keys but the common ones, which the caller has read).
Quadric read_quadric(JsonCursor& c, std::string_view type, bool reverse_orientation);

// A `curves` shape (scene_curves.cpp): `shape` has its material and media, `c` the rest.
void read_curves(JsonCursor& c, const ShapeSection& section, Scene& scene, MemoryBudget& budget, Shape shape,
                 bool reverse_orientation);

// An interval [a, b] of times with b > a (the shutter: open, close; the motion's times: start,
// end), named `first` and `second` in the error (scene_motion.cpp).
std::array<double, 2> read_time_interval(const JsonCursor& v, std::string_view first, std::string_view second);
// The `motion` of a shape or instance whose transform is `start` (scene_motion.cpp): its transform
// at the end of `times` (default [0, 1]), of the same handedness as `start`.
AnimatedTransform read_motion(JsonCursor motion, const Transform& start);
// Checks that `instance`, placed by `to_world`, keeps `bounds` (its object's) within float range,
// and its matrices too; `blame` is the key that placed it, `what` names the object in the error.
void check_instance_range(const Instance& instance, const Transform& to_world, const ObjectBounds& bounds,
                          const JsonCursor& blame, std::string_view what);
// Makes the shape just read (the last of scene.shapes, placed at its start transform `start`) a
// moving one: a one-shape object and its instance, moved by `motion` (a shape's `motion` key).
void make_shape_move(const JsonCursor& motion, const Transform& start, Scene& scene);

// `objects`: name -> {"shapes": [...]}, each a run of shapes in object space that instances place
// (geometry/instance.h); read after the materials and before `shapes`. Returns each object's
// bounds, for the instances.
std::vector<ObjectBounds> read_objects(JsonCursor objects, const std::filesystem::path& folder, Scene& scene,
                                       MemoryBudget& budget, const MeshStore* meshes = nullptr,
                                       const CurveStore* curves = nullptr);

// An `instance` shape of `shapes`: `object` (a name) and `transform`.
void read_instance(JsonCursor& c, const ShapeSection& section, Scene& scene, MemoryBudget& budget);

// `lights`: at most one environment, charged to `budget`, and point, spot and directional lights;
// needs the integrator (bsdf cannot see delta lights).
void read_lights(const JsonCursor& lights, const std::filesystem::path& folder, Scene& scene,
                 MemoryBudget& budget);

// Adds "file:line:col: /pointer: message", located at `at`, to scene.warnings.
void add_warning(Scene& scene, const JsonCursor& at, const std::string& message);

// The path a `file` key names, relative to `folder` unless absolute. Fails at the key when there
// is no such regular file; `what` names the kind ("mesh", "environment image").
std::filesystem::path referenced_file(const JsonCursor& file, const std::filesystem::path& folder,
                                      std::string_view what);

// Runs `load` (load_mesh, read_image). A SceneError it throws keeps its own location (the mesh or
// image file, with line where known) and gains " (referenced by /pointer at scene:line:col)".
template <class Load>
auto load_referenced(const JsonDocument& document, const std::string& pointer, Load&& load) {
    try {
        return std::forward<Load>(load)();
    } catch (const SceneError& e) {
        SourceLocation at = document.locate(pointer);
        throw SceneError(e.where(), e.message() + " (referenced by " + at.json_pointer + " at " +
                                        at.file + ":" + std::to_string(at.line) + ":" +
                                        std::to_string(at.column) + ")");
    }
}
template <class Load>
auto load_referenced(const JsonCursor& file, Load&& load) {
    return load_referenced(file.document(), file.pointer(), std::forward<Load>(load));
}

}  // namespace candela
