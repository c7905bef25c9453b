#pragma once
// What the importer's parts share while they translate a pbrt-v4 scene (internal to
// formats/pbrt/): the document being built, where its pieces came from, the warnings, the
// textures' and materials' names, and the graphics state that shapes and lights read.
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/formats/pbrt/pbrt_params.h"
#include "candela/math/transform.h"

namespace candela::pbrt {

// An AreaLightSource, applied to the shapes that follow it in its attribute block.
struct AreaLight {
    ParameterList params;
    Location at;
};

struct GraphicsState {
    Transform ctm;  // object (or light, camera) space to world, at the start time
    // pbrt-v4's second CTM, at the end time (motion blur), and which of the two the transform
    // directives change (ActiveTransform); TransformTimes' start and end.
    Transform ctm_end;
    bool start_active = true, end_active = true;
    double start_time = 0.0, end_time = 1.0;
    bool moving() const { return ctm.matrix() != ctm_end.matrix(); }
    bool reverse_orientation = false;
    std::string material;  // the JSON name of the current material
    std::optional<AreaLight> area_light;
    // MediumInterface "inside" "outside": the media on the two sides of the shapes that follow;
    // the outside one is also the camera's (at Camera) and a light's. "" is no medium.
    std::string inside_medium, outside_medium;
    // Attribute "shape" | "light" | "material" | "medium" | "texture": default parameters.
    std::map<std::string, ParameterList> attributes;
};

// The last `curves` shape the importer added, which the next curve joins when it is in the same
// graphics state and no other shape came between (pbrt_curves.cpp).
struct CurveRun {
    const Json* shapes = nullptr;  // the shape list it is in
    size_t index = 0;              // its index there
    std::string key;               // the state it was made in: material, kind, media, ...
    Transform ctm;                 // ... and transform
    std::string file;              // its curve store entry
};

class ImportContext {
  public:
    ImportContext(ImportedScene& out, std::filesystem::path folder) : out_(out), folder_(std::move(folder)) {}

    // The main scene file's folder: pbrt-v4 resolves every file name against it.
    const std::filesystem::path& folder() const { return folder_; }

    Json& doc() { return out_.document; }
    MeshStore& meshes() { return out_.meshes; }
    CurveStore& curves() { return out_.curves; }
    CurveRun& curve_run() { return curve_run_; }
    // Remembers that the element at `pointer` comes from `at`.
    void origin(const std::string& pointer, const Location& at) { out_.origins.emplace_back(pointer, at); }
    // A warning at `at`. The same message (without its location) is reported once, with a count
    // of the repeats at the end.
    void warn(const Location& at, const std::string& message);
    void finish_warnings();

    // Texture names: pbrt-v4 keeps float and spectrum textures apart, candela's JSON has one set.
    std::string define_texture_name(const std::string& pbrt_name, bool is_float);
    std::optional<std::string> texture_name(const std::string& pbrt_name, bool want_float) const;
    // For Params::colour / number_or_texture: the JSON name of a texture parameter's texture.
    std::string texture_reference(const Parameter& p, bool want_float) const;

    // Material names: named ones keep their name (made unique against anonymous ones).
    std::string new_material_name(const std::string& wanted);
    bool has_material(const std::string& name) const { return materials_.count(name) > 0; }
    std::map<std::string, std::string>& named_materials() { return named_; }

    // A fresh mesh file name for the store ("meshes/NAME-N.ply").
    std::string new_mesh_name(const std::string& kind);
    // A fresh curves file name for the store ("curves/curve-N.curves").
    std::string new_curves_name() { return "curves/curve-" + std::to_string(++curves_count_) + ".curves"; }

    // Media defined so far (MakeNamedMedium), and where.
    std::map<std::string, Location>& media() { return media_; }
    bool has_medium(const std::string& name) const { return media_.count(name) > 0; }
    // Whether a material of the document is pbrt-v4's "interface" (no surface, a boundary only).
    // A material named before its definition counts as a surface; end_of_files checks that.
    bool is_interface(const std::string& material);

    // NamedMaterial before its MakeNamedMaterial: pbrt-v4 looks names up once the file is read.
    // Shapes meanwhile get a placeholder material, replaced at the end of the files.
    static std::string later_material(const std::string& pbrt_name) { return "\x1f" + pbrt_name; }
    static bool is_later_material(const std::string& material) { return material.starts_with('\x1f'); }
    std::map<std::string, Location>& later_materials() { return later_; }

  private:
    ImportedScene& out_;
    std::filesystem::path folder_;
    std::map<std::string, size_t> warning_counts_;  // message -> times seen
    std::vector<std::pair<std::string, std::string>> first_warnings_;  // (message, located line)
    std::map<std::string, std::string> float_textures_, spectrum_textures_;  // pbrt name -> JSON name
    std::set<std::string> texture_names_;
    std::set<std::string> materials_;
    std::map<std::string, std::string> named_;  // pbrt name -> JSON name
    size_t mesh_count_ = 0;
    size_t curves_count_ = 0;
    CurveRun curve_run_;
    std::map<std::string, Location> media_;
    std::map<std::string, Location> later_;  // pbrt name -> first NamedMaterial asking for it
};

// The parts of the translation, each in its own file.
// pbrt_options.cpp: Camera, Film, PixelFilter, Sampler, Integrator (into the document's camera,
// film, sampler, integrator) once WorldBegin shows they are complete.
struct RenderOptions {
    std::optional<Params> camera, film, filter, sampler, integrator;
    Transform camera_from_world;
    // At the end of the camera's transform times (the same as camera_from_world when it does not move).
    Transform camera_from_world_end;
    double camera_start_time = 0.0, camera_end_time = 1.0;
    std::string camera_medium;  // the outside medium at Camera (pbrt-v4's CameraMedium)
    std::optional<unsigned long long> seed;  // Option "seed"
};
// Returns whether the integrator is to be volpath if the scene has media (pbrt-v4's default, and
// those that render media the same); the importer decides once the file is read.
bool translate_options(const RenderOptions& options, ImportContext& ctx);

// pbrt_materials.cpp: a Texture directive into the document's textures; a Material or
// MakeNamedMaterial into its materials (returns the JSON name).
void translate_texture(const std::string& name, const std::string& value_type, const std::string& type,
                       const Params& params, const Transform& to_world, ImportContext& ctx);
std::string translate_material(const std::string& wanted_name, const std::string& type, const Params& params,
                               ImportContext& ctx);
// A copy of material `name` with pbrt's shape `alpha` (a number or {"texture": ...}).
std::string material_with_alpha(const std::string& name, const Json& alpha, ImportContext& ctx);

// A point or vector as the JSON scene document writes it, [x, y, z].
inline Json vec_json(const Vec3d& v) { return Json::array({v.x, v.y, v.z}); }

// pbrt_shapes.cpp: a Shape into JSON shapes appended to `shapes` (usually the document's).
void translate_shape(const std::string& type, const Params& params, const GraphicsState& state, Json& shapes,
                     const std::string& shapes_pointer, ImportContext& ctx);

// pbrt_curves.cpp: a Shape "curve", added to the last curves shape of `shapes` when it is in the
// same state, else as a new one.
void translate_curve(const Params& params, const GraphicsState& state, Json& shapes, const std::string& shapes_pointer,
                     ImportContext& ctx);
// pbrt_shapes.cpp: the MediumInterface of `state` on a shape.
void add_media(const GraphicsState& state, Json& shape);
// pbrt_shapes.cpp: a moving `state`'s motion (ActiveTransform EndTime) on a shape or instance placed
// by its CTM times `frame` (applied first): the end CTM times `frame`, with TransformTimes.
void add_motion(const GraphicsState& state, Json& shape, const Transform& frame = Transform());

// pbrt_media.cpp: a MakeNamedMedium into the document's media; `to_world` is the transformation
// current at the directive.
void translate_medium(const std::string& name, const Params& params, const Transform& to_world, ImportContext& ctx);

// pbrt_lights.cpp: a LightSource into the document's lights. `camera_position` (world space) is
// the origin of pbrt-v4's render space (pbrt_directions).
void translate_light(const std::string& type, const Params& params, const Transform& light_to_world,
                     const Vec3d& camera_position, ImportContext& ctx);

// A JSON pointer's reference token for `name` (RFC 6901: ~ and / escaped).
std::string pointer_token(const std::string& name);

// pbrt-v4 renders in "camera-world" space by default: the world translated to put the camera at
// the origin (render = Translate(-camera) x world). A projective transform t (last row not 0 0 0 1)
// moves points the same there (the divide comes first), but directions by the upper 3x3 of
// Translate(-camera) x t, which is not t's. Returns that transform, whose directions (and inverse
// directions) are pbrt-v4's; t itself when t is affine.
Transform pbrt_directions(const Transform& t, const Vec3d& camera_position);

// A transform in candela's JSON syntax: [{"matrix": [16 numbers row by row]}], or [] for identity.
Json transform_json(const Transform& t);

}  // namespace candela::pbrt
