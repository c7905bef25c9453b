#include "candela/formats/json/scene_loader.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <system_error>

#include "candela/camera/camera_frame.h"
#include "candela/scene/enum_names.h"
#include "candela/formats/json/json_cursor.h"
#include "candela/scene/media_warning.h"
#include "candela/scene/memory_budget.h"
#include "candela/formats/json/scene_sections.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 10> kSections = {"integrator", "sampler", "media",   "camera", "film",
                                                        "textures",   "materials", "objects", "shapes", "lights"};
// In the order of CameraType and FovAxis (camera_settings.h).
constexpr std::array<std::string_view, 2> kCameraTypes = {"perspective", "orthographic"};
constexpr std::array<std::string_view, 5> kFovAxes = {"x", "y", "diagonal", "smaller", "larger"};
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
    if (auto v = c.get("spectral")) integrator.spectral = v->boolean();
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
    if (auto a = c.get("adaptive")) {
        a->expect_object();
        AdaptiveSettings adaptive;
        // A threshold of 1 or more would stop every block at its first decision.
        if (auto v = a->get("threshold")) adaptive.threshold = v->number_f(Bounds{0.0, 1.0, true, true});
        // Two samples are the fewest a sample variance needs.
        if (auto v = a->get("min_spp")) adaptive.min_spp = v->integer(Bounds::closed(2, kMaxSpp));
        a->reject_unknown_keys();
        sampler.adaptive = adaptive;
    }
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

template <class E, size_t N>
E enum_of(std::string_view name, const std::array<std::string_view, N>& names) {
    return E(std::find(names.begin(), names.end(), name) - names.begin());
}

// `key` belongs to the other camera type: say which, rather than calling it unknown.
[[noreturn]] void fail_other_type_key(const JsonCursor& c, std::string_view key, CameraType type) {
    const bool perspective = type == CameraType::kPerspective;
    c.document().fail_at_key(
        c.pointer(), key,
        fmt::format("{} is a key of the {} camera; {} camera takes {}", json_quoted(key),
                    perspective ? "orthographic" : "perspective",
                    perspective ? "a perspective" : "an orthographic",
                    perspective ? "\"fov\" (degrees)" : "\"height\" (the image's height in scene units)"));
}

// screen_window: [xmin, xmax, ymin, ymax], finite, each minimum below its maximum.
std::array<float, 4> read_screen_window(const JsonCursor& v) {
    std::vector<JsonCursor> e = v.elements(4, "an array of 4 numbers [xmin, xmax, ymin, ymax]");
    std::array<float, 4> w{};
    for (size_t i = 0; i < 4; ++i) w[i] = e[i].number_f();
    for (size_t axis = 0; axis < 2; ++axis)
        if (!(w[2 * axis] < w[2 * axis + 1]))
            e[2 * axis + 1].fail(fmt::format("expected a number > {} ({}min), got {}", w[2 * axis], axis == 0 ? "x" : "y",
                                             e[2 * axis + 1].describe()));
    if (!std::isfinite(w[1] - w[0]) || !std::isfinite(w[3] - w[2]))
        v.fail("the screen window's extent overflows float range");
    return w;
}

// The projection: fov and fov_axis for perspective, height for orthographic, or screen_window for
// either (with fov for perspective, instead of fov_axis or height).
void read_projection(JsonCursor& c, CameraSettings& camera) {
    if (auto v = c.get("screen_window")) camera.screen_window = read_screen_window(*v);
    if (camera.type == CameraType::kPerspective) {
        if (c.has("height")) fail_other_type_key(c, "height", camera.type);
        if (auto v = c.get("fov")) camera.fov_degrees = v->number_f(Bounds::open(0, 180));
        if (auto v = c.get("fov_axis")) {
            if (camera.screen_window)
                v->fail("fov_axis chooses the default screen window; with \"screen_window\", fov spans its "
                        "coordinates -1 to 1 (pbrt-v4's screenwindow)");
            camera.fov_axis = enum_of<FovAxis>(v->choice("fov axis", kFovAxes), kFovAxes);
        }
        return;
    }
    for (std::string_view key : {"fov", "fov_axis"})
        if (c.has(key)) fail_other_type_key(c, key, camera.type);
    if (camera.screen_window) {
        if (auto v = c.get("height"))
            v->fail("an orthographic camera takes \"height\" or \"screen_window\" (in scene units), not both");
        return;
    }
    camera.ortho_height = c.require("height").number_f(Bounds::above(0));
}

// A thin lens: aperture_radius (0: none) and focus_distance (default: the distance to look_at).
void read_lens(JsonCursor& c, CameraSettings& camera) {
    if (auto v = c.get("aperture_radius")) camera.aperture_radius = v->number_f(Bounds::at_least(0));
    if (auto v = c.get("focus_distance")) camera.focus_distance = v->number_f(Bounds::above(0));
}

// Camera rays within float range: the orthographic film's width, and a thin lens's rays towards
// the corners of the focus plane (whose length normalize() squares).
void check_camera_extent(const CameraSettings& camera, JsonCursor& c) {
    const bool orthographic = camera.type == CameraType::kOrthographic;
    auto reach = [](const ScreenWindow& w) {
        return Vec2f(std::abs(w.centre.x) + w.half.x, std::abs(w.centre.y) + w.half.y);
    };
    if (orthographic) {
        const Vec2f r = reach(orthographic_screen_window(camera));
        if (!std::isfinite(r.x + r.y + camera.aperture_radius)) {
            if (camera.screen_window)
                c.require("screen_window").fail("the screen window plus the aperture overflows float range");
            c.require("height").fail(fmt::format(
                "the film's width ({} times the aspect ratio, plus the aperture) overflows float range",
                camera.ortho_height));
        }
    }
    if (!orthographic && camera.screen_window) {
        // The pinhole's direction to the window's corner, whose length normalize() squares.
        const Vec2f r = reach(perspective_screen_window(camera));
        if (!std::isfinite(r.x * r.x + r.y * r.y + 1.0f))
            c.require("screen_window").fail("the screen window times tan(fov / 2) gives rays beyond float range");
    }
    if (camera.aperture_radius == 0.0f) return;
    const Vec2f half = orthographic ? Vec2f(0.0f, 0.0f) : reach(perspective_screen_window(camera));
    const float f = resolved_focus_distance(camera), r = camera.aperture_radius;
    const Vec3f corner(f * half.x + r, f * half.y + r, f);
    if (!std::isfinite(dot(corner, corner))) {
        const std::optional<JsonCursor> focus = c.get("focus_distance");
        (focus ? *focus : c.require("aperture_radius"))
            .fail(fmt::format("a thin lens of aperture_radius {} focused at {} gives rays beyond float range", r, f));
    }
}

// The camera `transform`: camera space (at the origin, looking along +z, +y up, image right along
// +x: pbrt-v4's camera space) to the world. The axes are normalized; their handedness is kept.
CameraBasis read_camera_basis(const JsonCursor& v) {
    const Transform t = read_transform(v);
    const Vec3d position = t.apply_point(Vec3d(0.0));
    const Vec3d right = t.apply_vector(Vec3d(1, 0, 0)), up = t.apply_vector(Vec3d(0, 1, 0)),
                forward = t.apply_vector(Vec3d(0, 0, 1));
    const CameraBasis basis{Vec3f(position), Vec3f(normalize(right)), Vec3f(normalize(up)), Vec3f(normalize(forward))};
    if (!is_finite(basis.position) || !is_finite(basis.right) || !is_finite(basis.up) || !is_finite(basis.forward))
        v.fail("the camera transform places the camera beyond float range or flattens an axis");
    return basis;
}

// The camera's `motion`: its frame at the end of `times` (default [0, 1]), given as the camera's
// own frame is (position / look_at / up, or transform), so that both have the same handedness.
CameraMotion read_camera_motion(JsonCursor m, const CameraSettings& start) {
    CameraMotion motion;
    if (auto v = m.get("times")) {
        const std::array<double, 2> t = read_time_interval(*v, "start", "end");
        motion.start_time = t[0];
        motion.end_time = t[1];
    }
    if (start.basis) {
        for (std::string_view key : {"position", "look_at", "up"})
            if (m.has(key))
                m.document().fail_at_key(m.pointer(), key,
                                         "the camera is placed by \"transform\"; its end frame takes \"transform\" too");
        motion.end = read_camera_basis(m.require("transform"));
    } else {
        if (m.has("transform"))
            m.document().fail_at_key(m.pointer(), "transform",
                                     "the camera is placed by position / look_at / up; its end frame takes those too");
        CameraSettings end = start;
        auto position = m.get("position");
        auto look_at = m.get("look_at");
        auto up = m.get("up");
        if (!position && !look_at && !up) m.fail("the end frame needs position, look_at or up (the others default to the start frame's)");
        if (position) end.position = position->vec3f();
        if (look_at) end.look_at = look_at->vec3f();
        if (up) {
            end.up = up->vec3f();
            if (end.up == Vec3f(0.0f)) up->fail_expected("a nonzero up vector");
        }
        check_camera_frame(end, m, position, look_at, up);
        const CameraFrame f(end);
        motion.end = CameraBasis{f.position, f.right, f.up, f.forward};
    }
    m.reject_unknown_keys();
    return motion;
}

void read_camera(JsonCursor c, CameraSettings& camera, MemoryBudget* budget) {
    c.has("medium");  // the medium it sits in: read by load_scene once the media are
    if (auto type = c.get("type"))
        camera.type = enum_of<CameraType>(type->choice("camera type", kCameraTypes), kCameraTypes);
    if (auto transform = c.get("transform")) {
        for (std::string_view key : {"position", "look_at", "up"})
            if (c.has(key))
                c.document().fail_at_key(c.pointer(), key,
                                         fmt::format("{} and \"transform\" both place the camera; give one of them",
                                                     json_quoted(key)));
        camera.basis = read_camera_basis(*transform);
    }
    auto position = c.get("position");
    auto look_at = c.get("look_at");
    auto up = c.get("up");
    if (position) camera.position = position->vec3f();
    if (look_at) camera.look_at = look_at->vec3f();
    if (up) {
        camera.up = up->vec3f();
        if (camera.up == Vec3f(0.0f)) up->fail_expected("a nonzero up vector");
    }
    read_projection(c, camera);
    if (auto v = c.get("resolution")) {
        auto wh = v->elements(2, "an array of 2 integers [width, height]");
        camera.width = wh[0].integer(Bounds::closed(1, kMaxResolution));
        camera.height = wh[1].integer(Bounds::closed(1, kMaxResolution));
        if (budget) check_film_memory(camera, *v, *budget);
    }
    if (auto v = c.get("near")) camera.near = v->number_f(Bounds::at_least(0));
    read_lens(c, camera);
    if (auto v = c.get("shutter")) camera.shutter = read_time_interval(*v, "open", "close");
    std::optional<JsonCursor> motion = c.get("motion");
    c.reject_unknown_keys();
    if (!camera.basis) check_camera_frame(camera, c, position, look_at, up);
    check_camera_extent(camera, c);
    if (motion) camera.motion = read_camera_motion(*motion, camera);
}

// The sensor's keys (film/sensor.h): sensor names its responses (cie1931 or a camera); iso and exposure_time give the imaging ratio, which must
// stay a positive float; white_balance is 0 or a temperature; max_component_value > 0.
void read_sensor(JsonCursor& c, FilmSettings& film) {
    if (auto v = c.get("sensor")) film.camera_sensor = *parse_sensor(v->choice("sensor", sensor_names()));
    std::optional<JsonCursor> last;  // where an imaging ratio out of float range is reported
    if (auto v = c.get("iso")) {
        film.iso = v->number_f(Bounds::above(0));
        last = v;
    }
    if (auto v = c.get("exposure_time")) {
        film.exposure_time = v->number_f(Bounds::above(0));
        last = v;
    }
    const float ratio = imaging_ratio(film);
    if (last && !(ratio > 0.0f && std::isfinite(ratio)))
        last->fail(fmt::format("the imaging ratio exposure_time * iso / 100 = {:g} * {:g} / 100 is {}", film.exposure_time,
                               film.iso, ratio > 0.0f ? "beyond float range" : "below float range (0)"));
    if (auto v = c.get("white_balance")) {
        film.white_balance = v->number_f(Bounds::at_least(0));
        if (film.white_balance != 0.0f && film.white_balance < kMinWhiteBalanceKelvin)
            v->fail_expected(fmt::format("0 (no white balance) or a temperature >= {} (kelvin)", kMinWhiteBalanceKelvin));
    }
    // pbrt-v4's maxcomponentvalue; a number beyond float range is no clamp at all.
    if (auto v = c.get("max_component_value")) {
        const double m = v->number(Bounds::above(0));
        film.max_component_value = m < double(std::numeric_limits<float>::max())
                                       ? float(m)
                                       : std::numeric_limits<float>::infinity();
    }
}

void read_film(JsonCursor c, FilmSettings& film, const CameraSettings& camera, std::string& output_file) {
    if (auto v = c.get("filename")) {
        output_file = v->string();
        if (output_file.empty()) v->fail_expected("an image file name");
    }
    if (auto v = c.get("filter")) film.filter = read_filter(*v);
    if (auto v = c.get("crop_window")) film.crop_window = read_crop_window(*v, camera);
    if (auto v = c.get("aovs")) film.aovs = read_aov_layers(*v);
    if (auto v = c.get("aov_names")) {
        static constexpr std::array<std::string_view, 2> names = {"candela", "pbrt"};
        film.aov_names = v->choice("AOV channel naming", names) == "pbrt" ? AovNames::kPbrt : AovNames::kCandela;
    }
    if (auto v = c.get("aov_space")) {
        static constexpr std::array<std::string_view, 2> spaces = {"world", "camera"};
        film.aov_space = v->choice("AOV space", spaces) == "camera" ? AovSpace::kCamera : AovSpace::kWorld;
    }
    if (auto v = c.get("tonemap"))
        film.tonemap = *parse_tonemap(v->choice("tone map", tonemap_names()));
    if (auto v = c.get("exposure")) film.exposure = v->number_f(Bounds::closed_open(0, 1));
    if (auto v = c.get("transfer"))
        film.transfer = *parse_transfer(v->choice("transfer", transfer_names()));
    if (auto v = c.get("gamma")) film.gamma = v->number_f(Bounds::above(0));
    read_sensor(c, film);
    c.reject_unknown_keys();
}

// pbrt-v4 warns the same way: a black image after hours of rendering is a poor way to find out.
void warn_if_unlit(Scene& scene) {
    const IntegratorType t = scene.integrator.type;
    if (t != IntegratorType::kPath && t != IntegratorType::kBsdf && t != IntegratorType::kWhitted && t != IntegratorType::kVolPath) return;
    if (scene.environment || !scene.delta_lights.empty()) return;
    for (const Shape& shape : scene.shapes)
        if (!shape.emission.is_black()) return;
    // An emitting medium lights the scene for volpath (pbrt-v4 counts it as a light too).
    if (t == IntegratorType::kVolPath)
        for (const Medium& m : scene.media)
            if (medium_emissive(m)) return;
    scene.warnings.push_back(
        SceneError(SourceLocation{scene.file.string(), 0, 0, ""},
                   fmt::format("the scene has no lights (no shape has an emission and there is no "
                               "environment, point, spot or directional light); the {} integrator "
                               "will render a black image",
                               integrator_type_name(t)))
            .formatted());
}

// pbrt-v4 warns the same way (cpu/render.cpp): only volpath (and bsdf, which is volpath without
// light sampling there) scatter in media; the others render the scene as if the media were vacuum.
void warn_if_media_ignored(Scene& scene) {
    const IntegratorType t = scene.integrator.type;
    if (t == IntegratorType::kVolPath || t == IntegratorType::kBsdf) return;
    if (!places_media(scene)) return;
    scene.warnings.push_back(
        SceneError(SourceLocation{scene.file.string(), 0, 0, ""},
                   fmt::format("{}{} integrator ignores them (it renders them as vacuum); use \"volpath\"",
                               kMediaIgnoredWarning, integrator_type_name(t)))
            .formatted());
}

// pbrt-v4 warns the same way (cpu/render.cpp): only volpath follows a path below a subsurface
// material's surface; pbrt-v4's path renders the dielectric boundary alone, and so does candela's.
void warn_if_subsurface_ignored(Scene& scene) {
    const IntegratorType t = scene.integrator.type;
    if (t == IntegratorType::kVolPath || t == IntegratorType::kBsdf) return;
    if (!has_tabulated_subsurface(scene)) return;
    scene.warnings.push_back(
        SceneError(SourceLocation{scene.file.string(), 0, 0, ""},
                   fmt::format("{}{} integrator renders only their dielectric boundary (as pbrt-v4's path does); "
                               "use \"volpath\"",
                               kSubsurfaceIgnoredWarning, integrator_type_name(t)))
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
    if (in.bad()) throw SceneError(SourceLocation{file.string(), 0, 0, ""}, "cannot read scene file");
    return std::move(text).str();
}

Scene load_scene(const std::filesystem::path& file, const LoadOptions& options) {
    return load_scene_from_string(read_text_file(file), file, options);
}

Scene load_scene_from_string(std::string_view json, const std::filesystem::path& file,
                             const LoadOptions& options) {
    JsonDocument document{std::string(json), file.string()};
    if (options.source_map) document.set_source_map(options.source_map);
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
    if (camera) read_camera(*camera, scene.camera, options.charge_film ? &budget : nullptr);
    if (options.charge_film && budget.used() == 0) check_film_memory(scene.camera, camera ? *camera : root, budget);
    if (options.charge_film && scene.sampler.adaptive)
        if (auto refused = budget.charge(film_statistics_memory_bytes(scene.camera.width, scene.camera.height),
                                         "the adaptive sampler's per-pixel statistics"))
            root.get("sampler")->get("adaptive")->fail(*refused);
    if (auto c = root.get("film")) read_film(*c, scene.film, scene.camera, scene.output_file);
    // The media, after the film (charged first), before the camera's medium and the shapes, which
    // name them.
    if (auto c = root.get("media")) read_media(*c, scene, budget);
    if (camera)
        if (auto v = camera->get("medium")) scene.camera_medium = medium_index(*v, scene);
    if (auto c = root.get("textures")) read_textures(*c, scene);
    if (auto c = root.get("materials")) read_materials(*c, scene);
    std::vector<ObjectBounds> objects;
    if (auto c = root.get("objects")) objects = read_objects(*c, folder, scene, budget, options.meshes, options.curves);
    if (auto c = root.get("shapes"))
        read_shapes(*c, ShapeSection{folder, std::nullopt, nullptr, objects, options.meshes, options.curves}, scene,
                    budget);
    if (auto c = root.get("lights")) read_lights(*c, folder, scene, budget);
    load_texture_images(scene, document, budget);
    warn_if_unlit(scene);
    warn_if_media_ignored(scene);
    warn_if_subsurface_ignored(scene);
    return scene;
}

}  // namespace candela
