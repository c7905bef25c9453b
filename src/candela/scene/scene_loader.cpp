#include "candela/scene/scene_loader.h"

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "candela/scene/enum_names.h"
#include "candela/scene/json_cursor.h"
#include "candela/scene/memory_budget.h"
#include "candela/scene/scene_sections.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 8> kSections = {"integrator", "sampler",   "camera", "film",
                                                       "textures",   "materials", "shapes", "lights"};
constexpr std::array<std::string_view, 1> kCameraTypes = {"perspective"};
constexpr int kMaxResolution = 32768;
constexpr int kMaxSpp = 1 << 24;
// |sin| of the angle between up and the view direction below which the camera frame is undefined.
constexpr double kParallelSine = 1e-6;

std::string format_vec(const Vec3f& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

void read_integrator(JsonCursor c, IntegratorSettings& integrator) {
    if (auto type = c.get("type"))
        integrator.type =
            *parse_integrator_type(type->choice("integrator type", integrator_type_names()));
    if (auto v = c.get("max_depth")) integrator.max_depth = v->integer(Bounds::at_least(1));
    if (auto v = c.get("rr_depth")) integrator.rr_depth = v->integer(Bounds::at_least(0));
    if (auto v = c.get("max_distance")) integrator.max_distance = v->number_f(Bounds::above(0));
    if (auto v = c.get("mis")) integrator.mis = v->boolean();
    if (auto v = c.get("rr")) integrator.rr_probability = v->number_f(Bounds{0.0, 1.0, true, false});
    if (auto v = c.get("light_selection"))
        integrator.light_selection =
            *parse_light_selection(v->choice("light selection", light_selection_names()));
    c.reject_unknown_keys();
}

void read_sampler(JsonCursor c, SamplerSettings& sampler) {
    if (auto v = c.get("type")) sampler.type = *parse_sampler_type(v->choice("sampler type", sampler_type_names()));
    if (auto v = c.get("spp")) sampler.spp = v->integer(Bounds::closed(1, kMaxSpp));
    if (auto v = c.get("seed")) sampler.seed = v->unsigned_integer();
    c.reject_unknown_keys();
}

// The film is the first large allocation a render makes, so it is charged first.
void check_film_memory(const CameraSettings& camera, const JsonCursor& at, MemoryBudget& budget) {
    if (auto refused = budget.charge(film_memory_bytes(camera.width, camera.height),
                                     fmt::format("a {}x{} film", camera.width, camera.height)))
        at.fail(*refused);
}

// The camera frame needs a view direction and an up vector not parallel to it. The error points at
// the key most likely to be wrong among those given (defaults cannot be wrong on their own).
void check_camera_frame(const CameraSettings& camera, const JsonCursor& c,
                        const std::optional<JsonCursor>& position,
                        const std::optional<JsonCursor>& look_at,
                        const std::optional<JsonCursor>& up) {
    Vec3f forward = camera.look_at - camera.position;
    if (!is_finite(forward)) {
        const JsonCursor& at = look_at ? *look_at : position ? *position : c;
        at.fail(fmt::format("look_at {} is too far from position {}: the view direction overflows "
                            "float range",
                            format_vec(camera.look_at), format_vec(camera.position)));
    }
    if (forward == Vec3f(0.0f)) {
        const JsonCursor& at = look_at ? *look_at : position ? *position : c;
        at.fail(fmt::format("look_at equals position {}; the camera has no view direction",
                            format_vec(camera.position)));
    }
    Vec3d f = normalize(Vec3d(forward));
    Vec3d u = normalize(Vec3d(camera.up));
    if (!(length(cross(f, u)) > kParallelSine)) {
        const JsonCursor& at = up ? *up : look_at ? *look_at : position ? *position : c;
        at.fail(
            fmt::format("up {} is parallel to the view direction {}; the camera cannot tell "
                        "which way is up",
                        format_vec(camera.up), format_vec(Vec3f(f))));
    }
}

void read_camera(JsonCursor c, CameraSettings& camera, MemoryBudget& budget) {
    if (auto type = c.get("type")) type->choice("camera type", kCameraTypes);
    auto position = c.get("position");
    auto look_at = c.get("look_at");
    auto up = c.get("up");
    if (position) camera.position = position->vec3f();
    if (look_at) camera.look_at = look_at->vec3f();
    if (up) {
        camera.up = up->vec3f();
        if (camera.up == Vec3f(0.0f)) up->fail_expected("a nonzero up vector");
    }
    if (auto v = c.get("fov")) camera.fov_degrees = v->number_f(Bounds::open(0, 180));
    if (auto v = c.get("resolution")) {
        auto wh = v->elements(2, "an array of 2 integers [width, height]");
        camera.width = wh[0].integer(Bounds::closed(1, kMaxResolution));
        camera.height = wh[1].integer(Bounds::closed(1, kMaxResolution));
        check_film_memory(camera, *v, budget);
    }
    if (auto v = c.get("near")) camera.near = v->number_f(Bounds::at_least(0));
    c.reject_unknown_keys();
    check_camera_frame(camera, c, position, look_at, up);
}

void read_film(JsonCursor c, FilmSettings& film) {
    if (auto v = c.get("filter"))
        film.filter = *parse_filter_type(v->choice("filter", filter_type_names()));
    if (auto v = c.get("tonemap"))
        film.tonemap = *parse_tonemap(v->choice("tone map", tonemap_names()));
    if (auto v = c.get("exposure")) film.exposure = v->number_f(Bounds::closed_open(0, 1));
    if (auto v = c.get("transfer"))
        film.transfer = *parse_transfer(v->choice("transfer", transfer_names()));
    if (auto v = c.get("gamma")) film.gamma = v->number_f(Bounds::above(0));
    c.reject_unknown_keys();
}

std::string read_text_file(const std::filesystem::path& file) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(file, ec);
    if (status.type() == std::filesystem::file_type::not_found)
        throw SceneError(SourceLocation{file.string(), 0, 0, ""}, "scene file not found");
    if (ec)  // a symbolic link loop, a folder we may not search
        throw SceneError(SourceLocation{file.string(), 0, 0, ""},
                         fmt::format("cannot access scene file: {}", ec.message()));
    // Other kinds than folders are allowed: a pipe, as in `candela render <(make_scene)`.
    if (status.type() == std::filesystem::file_type::directory)
        throw SceneError(SourceLocation{file.string(), 0, 0, ""}, "is a folder, not a scene file");
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw SceneError(SourceLocation{file.string(), 0, 0, ""},
                         fmt::format("cannot open scene file: {}", std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw SceneError(SourceLocation{file.string(), 0, 0, ""}, "cannot read scene file");
    return std::move(text).str();
}

// pbrt-v4 warns the same way: a black image after hours of rendering is a poor way to find out.
void warn_if_unlit(Scene& scene) {
    const IntegratorType t = scene.integrator.type;
    if (t != IntegratorType::kPath && t != IntegratorType::kBsdf && t != IntegratorType::kWhitted) return;
    if (scene.environment) return;
    for (const Shape& shape : scene.shapes)
        if (!shape.emission.is_black()) return;
    scene.warnings.push_back(
        SceneError(SourceLocation{scene.file.string(), 0, 0, ""},
                   fmt::format("the scene has no lights (no shape has an emission and there is no "
                               "environment); the {} integrator will render a black image",
                               integrator_type_name(t)))
            .formatted());
}

}  // namespace

std::filesystem::path referenced_file(const JsonCursor& file, const std::filesystem::path& folder,
                                      std::string_view what) {
    std::string name = file.string();
    if (name.empty()) file.fail_expected(fmt::format("the name of a {} file", what));
    // operator/ keeps an absolute name as it is.
    std::filesystem::path path = folder / std::filesystem::path(name);
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found)
        file.fail(fmt::format("{} file {} not found (looked for {})", what, json_quoted(name),
                              path.string()));
    if (ec)
        file.fail(fmt::format("cannot access {} file {}: {}", what, json_quoted(name), ec.message()));
    if (status.type() == std::filesystem::file_type::directory)
        file.fail(fmt::format("{} file {} is a folder, not a file", what, json_quoted(name)));
    if (status.type() != std::filesystem::file_type::regular)
        file.fail(fmt::format("{} file {} is not a regular file", what, json_quoted(name)));
    return path;
}

void add_warning(Scene& scene, const JsonCursor& at, const std::string& message) {
    scene.warnings.push_back(SceneError(at.document().locate(at.pointer()), message).formatted());
}

Scene load_scene(const std::filesystem::path& file, const LoadOptions& options) {
    return load_scene_from_string(read_text_file(file), file, options);
}

Scene load_scene_from_string(std::string_view json, const std::filesystem::path& file,
                             const LoadOptions& options) {
    JsonDocument document{std::string(json), file.string()};
    JsonCursor root = document.root();
    // Unknown sections first: a misspelt "materials" would otherwise surface as an undefined
    // material in `shapes`, far from the typo.
    for (std::string_view section : kSections) root.has(section);
    root.reject_unknown_keys();

    Scene scene;
    scene.file = file;
    const std::filesystem::path folder = file.parent_path();
    MemoryBudget budget(options.memory_limit ? *options.memory_limit : MemoryLimit::of_this_process());
    if (auto c = root.get("integrator")) read_integrator(*c, scene.integrator);
    if (auto c = root.get("sampler")) read_sampler(*c, scene.sampler);
    std::optional<JsonCursor> camera = root.get("camera");
    if (camera) read_camera(*camera, scene.camera, budget);
    if (budget.used() == 0) check_film_memory(scene.camera, camera ? *camera : root, budget);
    if (auto c = root.get("film")) read_film(*c, scene.film);
    if (auto c = root.get("textures")) read_textures(*c, scene);
    if (auto c = root.get("materials")) read_materials(*c, scene);
    if (auto c = root.get("shapes")) read_shapes(*c, folder, scene, budget);
    if (auto c = root.get("lights")) read_lights(*c, folder, scene, budget);
    load_texture_images(scene, document, budget);
    warn_if_unlit(scene);
    return scene;
}

}  // namespace candela
