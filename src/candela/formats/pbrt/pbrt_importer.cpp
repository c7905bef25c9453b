#include "candela/formats/pbrt/pbrt_importer.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_import_context.h"
#include "candela/formats/pbrt/pbrt_parser.h"
#include "candela/math/animated_transform.h"
#include "candela/math/constants.h"

namespace candela::pbrt {

// ---------------------------------------------------------------------------------------------
// ImportContext

void ImportContext::warn(const Location& at, const std::string& message) {
    if (warning_counts_[message]++ == 0) first_warnings_.emplace_back(message, describe(at) + ": " + message);
}

void ImportContext::finish_warnings() {
    for (const auto& [message, line] : first_warnings_) {
        const size_t n = warning_counts_[message];
        out_.warnings.push_back(n > 1 ? fmt::format("{} (and {} more like it)", line, n - 1) : line);
    }
}

std::string ImportContext::define_texture_name(const std::string& pbrt_name, bool is_float) {
    std::string name = pbrt_name;
    // pbrt-v4 lets a float and a spectrum texture share a name; the JSON cannot.
    if (texture_names_.count(name)) name = pbrt_name + (is_float ? " (float)" : " (spectrum)");
    for (int i = 2; texture_names_.count(name); ++i) name = fmt::format("{} ({})", pbrt_name, i);
    texture_names_.insert(name);
    (is_float ? float_textures_ : spectrum_textures_)[pbrt_name] = name;
    return name;
}

std::optional<std::string> ImportContext::texture_name(const std::string& pbrt_name, bool want_float) const {
    const auto& table = want_float ? float_textures_ : spectrum_textures_;
    if (auto it = table.find(pbrt_name); it != table.end()) return it->second;
    return std::nullopt;
}

std::string ImportContext::texture_reference(const Parameter& p, bool want_float) const {
    const std::string& name = p.strings.at(0);
    if (auto found = texture_name(name, want_float)) return *found;
    if (texture_name(name, !want_float))
        fail(p.location, fmt::format("\"{}\" is a {} texture; parameter \"{}\" needs a {} texture", name,
                                     want_float ? "spectrum" : "float", p.name, want_float ? "float" : "spectrum"));
    fail(p.location, fmt::format("texture \"{}\" is not defined", name));
}

std::string ImportContext::new_material_name(const std::string& wanted) {
    std::string name = wanted;
    for (int i = 2; materials_.count(name); ++i) name = fmt::format("{}-{}", wanted, i);
    materials_.insert(name);
    return name;
}

std::string ImportContext::new_mesh_name(const std::string& kind) {
    return fmt::format("meshes/{}-{}.ply", kind, ++mesh_count_);
}

std::string pointer_token(const std::string& name) {
    std::string out;
    for (char c : name) out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
    return out;
}

bool ImportContext::is_interface(const std::string& material) {
    const Json& materials = doc()["materials"];
    auto it = materials.find(material);
    return it != materials.end() && it->value("type", "") == "interface";
}

Transform pbrt_directions(const Transform& t, const Vec3d& camera_position) {
    return t.is_affine() ? t : Transform::translate(-camera_position) * t;
}

Json transform_json(const Transform& t) {
    if (t.is_identity()) return Json::array();
    Json m = Json::array();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m.push_back(t.matrix()[r][c]);
    return Json::array({Json{{"matrix", m}}});
}

namespace {

// pbrt's 16 numbers are the matrix's columns (m[12..14] translate), as Transform [...] writes.
Transform from_pbrt_matrix(const std::array<double, 16>& m) {
    Transform::Matrix rows{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) rows[r][c] = m[c * 4 + r];
    return Transform(rows);
}

// pbrt-v4's LookAt: the camera-from-world transform of an eye looking at `look` with `up`
// (camera space: +z forward, +y up, +x = cross(up, forward), left-handed).
std::optional<Transform> look_at_transform(const Vec3d& eye, const Vec3d& look, const Vec3d& up) {
    const Vec3d dir = look - eye;
    if (!(length(dir) > 0)) return std::nullopt;
    const Vec3d d = normalize(dir);
    const Vec3d r0 = cross(normalize(up), d);
    if (!(length(r0) > 0)) return std::nullopt;
    const Vec3d right = normalize(r0);
    const Vec3d new_up = cross(d, right);
    Transform::Matrix world_from_camera{{{right.x, new_up.x, d.x, eye.x},
                                         {right.y, new_up.y, d.y, eye.y},
                                         {right.z, new_up.z, d.z, eye.z},
                                         {0, 0, 0, 1}}};
    return Transform(world_from_camera).inverse();
}

// An object definition (its shapes are in the document's "objects").
struct ObjectDefinition {
    Location at;
    bool empty = false;  // no shape candela renders: its instances are left out
};

constexpr size_t kMaxAttributeDepth = 100000;

class Importer final : public Target {
  public:
    Importer(ImportedScene& out, const std::filesystem::path& file) : ctx_(out, file.parent_path()) {
        Json& d = ctx_.doc();
        d["integrator"] = Json::object();
        d["sampler"] = Json::object();
        d["media"] = Json::object();
        d["camera"] = Json::object();
        d["film"] = Json::object();
        d["textures"] = Json::object();
        d["materials"] = Json::object();
        d["shapes"] = Json::array();
        d["lights"] = Json::array();
        // Every section exists from the start: the document is an ordered map (a vector), so a
        // key added later would move the others while the parts hold references into them.
        d["objects"] = Json::object();
    }

    // --- transforms -----------------------------------------------------------------------
    void identity(const Location&) override { set_active(Transform()); }
    void translate(double dx, double dy, double dz, const Location& at) override {
        apply(Transform::translate({dx, dy, dz}), at);
    }
    void scale(double sx, double sy, double sz, const Location& at) override {
        apply(Transform::scale({sx, sy, sz}), at);
    }
    void rotate(double angle, double ax, double ay, double az, const Location& at) override {
        const Vec3d axis(ax, ay, az);
        if (!(length(axis) > 0)) fail(at, "Rotate: the axis is zero");
        apply(Transform::rotate(axis, angle * kPiD / 180.0), at);
    }
    void look_at(double ex, double ey, double ez, double lx, double ly, double lz, double ux, double uy, double uz,
                 const Location& at) override {
        std::optional<Transform> t = look_at_transform({ex, ey, ez}, {lx, ly, lz}, {ux, uy, uz});
        if (!t) fail(at, "LookAt: the eye equals the point looked at, or up is parallel to the view direction");
        apply(*t, at);
    }
    void concat_transform(const std::array<double, 16>& m, const Location& at) override {
        apply(from_pbrt_matrix(m), at);
    }
    void transform(const std::array<double, 16>& m, const Location& at) override {
        set_active(Transform());
        apply(from_pbrt_matrix(m), at);
    }
    void coordinate_system(const std::string& name, const Location&) override {
        named_frames_[name] = {state_.ctm, state_.ctm_end};
    }
    void coord_sys_transform(const std::string& name, const Location& at) override {
        auto it = named_frames_.find(name);
        if (it == named_frames_.end()) {
            ctx_.warn(at, fmt::format("CoordSysTransform: no coordinate system named \"{}\"; ignored", name));
            return;
        }
        // Both CTMs, whatever ActiveTransform says (pbrt-v4's CoordSysTransform).
        state_.ctm = it->second.first;
        state_.ctm_end = it->second.second;
    }
    void active_transform(const std::string& which, const Location&) override {
        state_.start_active = which != "EndTime";
        state_.end_active = which != "StartTime";
    }
    void transform_times(double start, double end, const Location& at) override {
        if (!(end > start)) fail(at, fmt::format("TransformTimes: the end time ({}) must be after the start ({})", end, start));
        state_.start_time = start;
        state_.end_time = end;
    }
    void reverse_orientation(const Location&) override { state_.reverse_orientation = !state_.reverse_orientation; }
    void attribute_begin(const Location& at) override {
        // Each level keeps a copy of the graphics state (a few hundred bytes): a bound keeps a
        // file of a million AttributeBegins from taking gigabytes.
        if (stack_.size() >= kMaxAttributeDepth)
            fail(at, fmt::format("AttributeBegin nested deeper than {} levels", kMaxAttributeDepth));
        stack_.push_back({state_, at});
    }
    void attribute_end(const Location& at) override {
        if (stack_.empty()) fail(at, "AttributeEnd without a matching AttributeBegin");
        state_ = std::move(stack_.back().first);
        stack_.pop_back();
    }
    void attribute(const std::string& target, ParameterList params, const Location& at) override {
        static const std::set<std::string> kTargets = {"shape", "light", "material", "medium", "texture"};
        if (!kTargets.count(target))
            fail(at, fmt::format("Attribute: unknown target \"{}\"; expected shape, light, material, medium or "
                                 "texture",
                                 target));
        ParameterList& defaults = state_.attributes[target];
        for (Parameter& p : params) {
            std::erase_if(defaults, [&](const Parameter& d) { return d.name == p.name; });
            defaults.push_back(std::move(p));
        }
    }

    // --- options --------------------------------------------------------------------------
    void option(const std::string& name, const Parameter& value, const Location& at) override {
        if (name == "seed" && value.numbers.size() == 1 && value.numbers[0] >= 0) {
            options_.seed = static_cast<unsigned long long>(value.numbers[0]);
            return;
        }
        ctx_.warn(at, fmt::format("Option \"{}\" is not supported; ignored", name));
    }
    void color_space(const std::string& name, const Location& at) override {
        if (name != "srgb")
            ctx_.warn(at, fmt::format("ColorSpace \"{}\": candela knows only srgb; colours are read as sRGB", name));
    }
    void camera(const std::string& type, ParameterList params, const Location& at) override {
        before_world("Camera", at);
        options_.camera.emplace(std::move(params), fmt::format("Camera \"{}\"", type), at);
        options_.camera_from_world = state_.ctm;
        options_.camera_from_world_end = state_.ctm_end;
        options_.camera_start_time = state_.start_time;
        options_.camera_end_time = state_.end_time;
        options_.camera_medium = state_.outside_medium;
        named_frames_["camera"] = {state_.ctm.inverse(), state_.ctm_end.inverse()};
    }
    void film(const std::string& type, ParameterList params, const Location& at) override {
        before_world("Film", at);
        options_.film.emplace(std::move(params), fmt::format("Film \"{}\"", type), at);
    }
    void pixel_filter(const std::string& type, ParameterList params, const Location& at) override {
        before_world("PixelFilter", at);
        options_.filter.emplace(std::move(params), fmt::format("PixelFilter \"{}\"", type), at);
    }
    void sampler(const std::string& type, ParameterList params, const Location& at) override {
        before_world("Sampler", at);
        options_.sampler.emplace(std::move(params), fmt::format("Sampler \"{}\"", type), at);
    }
    void integrator(const std::string& type, ParameterList params, const Location& at) override {
        before_world("Integrator", at);
        options_.integrator.emplace(std::move(params), fmt::format("Integrator \"{}\"", type), at);
    }
    void accelerator(const std::string&, ParameterList, const Location& at) override {
        ctx_.warn(at, "Accelerator: candela always uses Embree's BVH; ignored");
    }
    // pbrt-v4 allows both before and after WorldBegin; the medium lives in the space current here.
    void make_named_medium(const std::string& name, ParameterList params, const Location& at) override {
        if (name.empty()) fail(at, "MakeNamedMedium: the name \"\" is taken: it means no medium");
        if (auto it = ctx_.media().find(name); it != ctx_.media().end())
            fail(at, fmt::format("MakeNamedMedium: medium \"{}\" is defined twice (first at {})", name,
                                 describe(it->second)));
        merge_defaults(params, state_.attributes["medium"]);
        Params p(std::move(params), fmt::format("MakeNamedMedium \"{}\"", name), at);
        translate_medium(name, p, state_.ctm, ctx_);
        ctx_.media().emplace(name, at);
        finish(p);
    }
    // One name means the same medium on both sides (the parser passes it twice).
    void medium_interface(const std::string& inside, const std::string& outside, const Location&) override {
        state_.inside_medium = inside;
        state_.outside_medium = outside;
    }
    void world_begin(const Location& at) override {
        if (in_world_) fail(at, "WorldBegin appears twice");
        in_world_ = true;
        options_translated_ = true;
        integrator_follows_media_ = translate_options(options_, ctx_);
        state_.ctm = state_.ctm_end = Transform();
        named_frames_["world"] = {Transform(), Transform()};
    }

    // --- the world ------------------------------------------------------------------------
    void texture(const std::string& name, const std::string& value_type, const std::string& type,
                 ParameterList params, const Location& at) override {
        in_world("Texture", at);
        merge_defaults(params, state_.attributes["texture"]);
        Params p(std::move(params), fmt::format("Texture \"{}\"", name), at);
        translate_texture(name, value_type, type, p, state_.ctm, ctx_);
        finish(p);
    }
    void material(const std::string& type, ParameterList params, const Location& at) override {
        in_world("Material", at);
        merge_defaults(params, state_.attributes["material"]);
        Params p(std::move(params), fmt::format("Material \"{}\"", type), at);
        state_.material = translate_material("material", type, p, ctx_);
        finish(p);
    }
    void make_named_material(const std::string& name, ParameterList params, const Location& at) override {
        in_world("MakeNamedMaterial", at);
        if (ctx_.named_materials().count(name)) fail(at, fmt::format("MakeNamedMaterial: \"{}\" is defined twice", name));
        merge_defaults(params, state_.attributes["material"]);
        Params p(std::move(params), fmt::format("MakeNamedMaterial \"{}\"", name), at);
        const std::string type = p.string_or("type", "");
        if (type.empty()) p.fail(nullptr, fmt::format("MakeNamedMaterial \"{}\": \"string type\" is required", name));
        ctx_.named_materials()[name] = translate_material(name, type, p, ctx_);
        finish(p);
    }
    void named_material(const std::string& name, const Location& at) override {
        in_world("NamedMaterial", at);
        auto it = ctx_.named_materials().find(name);
        if (it == ctx_.named_materials().end()) {
            // pbrt-v4 keeps the name and looks it up once the file is read (contemporary-bathroom
            // names "light" before it includes materials.pbrt): resolved in end_of_files.
            ctx_.later_materials().try_emplace(name, at);
            state_.material = ImportContext::later_material(name);
            return;
        }
        state_.material = it->second;
    }
    void light_source(const std::string& type, ParameterList params, const Location& at) override {
        in_world("LightSource", at);
        merge_defaults(params, state_.attributes["light"]);
        Params p(std::move(params), fmt::format("LightSource \"{}\"", type), at);
        if (object_) {
            ctx_.warn(at, "LightSource inside ObjectBegin: pbrt-v4 does not instance lights; ignored");
            return;
        }
        // pbrt-v4 gives a light the outside medium and looks it up at once; the medium does not
        // change what the light sends (transmittance is the rays' business), so candela's lights
        // have none.
        if (!state_.outside_medium.empty() && !ctx_.has_medium(state_.outside_medium))
            fail(at, fmt::format("LightSource: medium \"{}\" is not defined (MakeNamedMedium must come first)",
                                 state_.outside_medium));
        if (state_.moving())
            ctx_.warn(at, "LightSource: animated lights are not supported (nor by pbrt-v4); the start transform is used");
        translate_light(type, p, state_.ctm, options_.camera_from_world.inverse().apply_point(Vec3d(0, 0, 0)), ctx_);
        finish(p);
    }
    void area_light_source(const std::string& type, ParameterList params, const Location& at) override {
        in_world("AreaLightSource", at);
        if (type != "diffuse") {
            ctx_.warn(at, fmt::format("AreaLightSource \"{}\": pbrt-v4 knows only \"diffuse\"; ignored", type));
            state_.area_light.reset();
            return;
        }
        merge_defaults(params, state_.attributes["light"]);
        state_.area_light = AreaLight{std::move(params), at};
    }
    void shape(const std::string& type, ParameterList params, const Location& at) override {
        in_world("Shape", at);
        merge_defaults(params, state_.attributes["shape"]);
        Params p(std::move(params), fmt::format("Shape \"{}\"", type), at);
        // pbrt-v4 refuses a moving emitter (Shape on an AreaLightSource); other moving shapes take
        // their end transform as a motion (add_motion), except in an object, which its instances move.
        if (state_.moving() && state_.area_light && !object_)
            fail(at, "Shape: animated area lights are not supported (as in pbrt-v4)");
        ensure_material();
        // pbrt-v4 looks the media up once the file is read: they may be defined after the shape.
        for (const std::string* m : {&state_.inside_medium, &state_.outside_medium})
            if (!m->empty()) medium_uses_.emplace_back(*m, at);
        if (object_) {
            GraphicsState s = state_;
            if (s.moving()) {
                ctx_.warn(at, "Shape: a moving shape inside ObjectBegin is not supported; rendered at the start "
                              "transform (its ObjectInstance may move)");
                s.ctm_end = s.ctm;
            }
            if (s.area_light) {
                ctx_.warn(at, "area lights inside ObjectBegin are not supported (as in pbrt-v4); the shape does not "
                              "emit");
                s.area_light.reset();
            }
            Json& shapes = ctx_.doc()["objects"][object_name_]["shapes"];
            translate_shape(type, p, s, shapes, "/objects/" + pointer_token(object_name_) + "/shapes", ctx_);
        } else {
            translate_shape(type, p, state_, ctx_.doc()["shapes"], "/shapes", ctx_);
        }
        finish(p);
    }
    // An object's shapes keep the transform each had when defined; an instance places them by the
    // transform at ObjectInstance (pbrt-v4: world = instance * definition), as an Embree instance
    // of the object.
    void object_begin(const std::string& name, const Location& at) override {
        in_world("ObjectBegin", at);
        if (object_) fail(at, fmt::format("ObjectBegin \"{}\" inside ObjectBegin \"{}\"", name, object_name_));
        if (objects_.count(name)) fail(at, fmt::format("ObjectBegin: object \"{}\" is defined twice", name));
        attribute_begin(at);
        object_name_ = name;
        object_ = &objects_[name];
        object_->at = at;
        Json& objects = ctx_.doc()["objects"];
        objects[name] = Json{{"shapes", Json::array()}};
        ctx_.origin("/objects/" + pointer_token(name), at);
    }
    void object_end(const Location& at) override {
        if (!object_) fail(at, "ObjectEnd without ObjectBegin");
        if (ctx_.doc()["objects"][object_name_]["shapes"].empty()) {
            ctx_.warn(object_->at, fmt::format("object \"{}\" has no shapes candela renders; its instances are empty",
                                               object_name_));
            ctx_.doc()["objects"].erase(object_name_);
            object_->empty = true;
        }
        object_ = nullptr;
        attribute_end(at);
    }
    void object_instance(const std::string& name, const Location& at) override {
        in_world("ObjectInstance", at);
        if (object_) fail(at, "ObjectInstance inside ObjectBegin: instances do not nest");
        auto it = objects_.find(name);
        if (it == objects_.end()) fail(at, fmt::format("ObjectInstance: no object named \"{}\"", name));
        if (it->second.empty) return;
        Json& shapes = ctx_.doc()["shapes"];
        Json instance{{"type", "instance"}, {"object", name}};
        if (!state_.ctm.is_identity() || state_.moving()) instance["transform"] = transform_json(state_.ctm);
        add_motion(state_, instance);
        if (state_.moving()) turning_objects_.insert(name);
        ctx_.origin(fmt::format("/shapes/{}", shapes.size()), at);
        shapes.push_back(std::move(instance));
    }

    void end_of_files() override {
        // pbrt-v4 stops on these too: a block left open is likely a missing line.
        if (object_) fail(object_->at, "ObjectBegin without a matching ObjectEnd");
        if (!stack_.empty()) fail(stack_.back().second, "AttributeBegin without a matching AttributeEnd");
        if (!options_translated_) {
            // A file with no WorldBegin still has its options.
            integrator_follows_media_ = translate_options(options_, ctx_);
        }
        for (const auto& [name, at] : medium_uses_)
            if (!ctx_.has_medium(name)) fail(at, fmt::format("Shape: medium \"{}\" is not defined", name));
        resolve_later_materials();
        finish_integrator();
        for (const std::string& name : turning_objects_) pivot_about_render_origin(name);
        if (ctx_.doc()["objects"].empty()) ctx_.doc().erase("objects");
        if (ctx_.doc()["media"].empty()) ctx_.doc().erase("media");
        ctx_.finish_warnings();
    }
    void warn(const Location& at, const std::string& message) override { ctx_.warn(at, message); }

  private:
    // pbrt-v4 interpolates a moving ObjectInstance in its render space (scene.cpp: the instance's
    // transform is RenderFromObject(t) * WorldFromRender, its object's shapes already in render
    // space), whose origin is the camera's position at the middle of the camera's times (the
    // default "cameraworld"). A turning instance therefore turns about that point, not about its
    // object's origin. The same here: object `name`'s shapes move by -c and every instance of it
    // (moving or not, all share the object) by +c first, so that its path decomposes
    // instance * translate(c) at both ends; translate(-c) before the path commutes with the
    // interpolation, so the result is pbrt-v4's. Only objects with a moving instance change.
    void pivot_about_render_origin(const std::string& name) {
        const AnimatedTransform world_from_camera(options_.camera_from_world.inverse(), options_.camera_start_time,
                                                  options_.camera_from_world_end.inverse(), options_.camera_end_time);
        const Vec3d c = world_from_camera.at(0.5 * (options_.camera_start_time + options_.camera_end_time))
                            .apply_point(Vec3d(0, 0, 0));
        if (c.x == 0 && c.y == 0 && c.z == 0) return;
        Json& objects = ctx_.doc()["objects"];
        if (!objects.contains(name)) return;  // an empty object, left out
        // candela's transform lists apply their first step first: the shapes' shift comes last.
        for (Json& shape : objects[name]["shapes"]) {
            if (shape.contains("transform"))
                shape["transform"].push_back(Json{{"translate", {-c.x, -c.y, -c.z}}});
            else if (shape.value("type", "") == "sphere")  // a whole sphere: its centre
                for (int i = 0; i < 3; ++i) shape["center"][i] = shape["center"][i].get<double>() - c[i];
            else
                shape["transform"] = Json::array({Json{{"translate", {-c.x, -c.y, -c.z}}}});
        }
        const Json first_step{{"translate", {c.x, c.y, c.z}}};
        auto pivot = [&](Json& transform) { transform.insert(transform.begin(), first_step); };
        for (Json& shape : ctx_.doc()["shapes"]) {
            if (shape.value("type", "") != "instance" || shape.value("object", "") != name) continue;
            if (!shape.contains("transform")) shape["transform"] = Json::array();
            pivot(shape["transform"]);
            if (shape.contains("motion")) pivot(shape["motion"]["transform"]);
        }
    }

    // Post-multiplies the active CTMs by t (ActiveTransform chooses which).
    void apply(const Transform& t, const Location& at) {
        if (!state_.start_active && !state_.end_active) return;
        if (!t.invertible()) fail(at, "the transform is not invertible (a zero scale?)");
        if (state_.start_active) state_.ctm = state_.ctm * t;
        if (state_.end_active) state_.ctm_end = state_.ctm_end * t;
    }
    void set_active(const Transform& t) {
        if (state_.start_active) state_.ctm = t;
        if (state_.end_active) state_.ctm_end = t;
    }
    void before_world(const char* directive, const Location& at) {
        if (in_world_) fail(at, fmt::format("{} must come before WorldBegin", directive));
    }
    void in_world(const char* directive, const Location& at) {
        if (!in_world_) fail(at, fmt::format("{} must come after WorldBegin", directive));
    }
    void finish(const Params& p) {
        p.report_unused([&](const Location& at, const std::string& m) { ctx_.warn(at, m); });
    }
    // NamedMaterial names given before their MakeNamedMaterial, now that the files are read: the
    // placeholders become the materials, or the first use of a name never defined is the error.
    // Shapes took such a material for a surface; one that is an "interface" would have been
    // translated differently, so that is an error too.
    void resolve_later_materials() {
        std::map<std::string, std::string> resolved;
        for (const auto& [name, at] : ctx_.later_materials()) {
            auto it = ctx_.named_materials().find(name);
            if (it == ctx_.named_materials().end()) fail(at, fmt::format("NamedMaterial: no material named \"{}\"", name));
            if (ctx_.is_interface(it->second))
                fail(at, fmt::format("NamedMaterial \"{}\": an \"interface\" material must be defined before the "
                                     "shapes that use it", name));
            resolved[ImportContext::later_material(name)] = it->second;
        }
        if (resolved.empty()) return;
        std::function<void(Json&)> replace = [&](Json& j) {
            if (j.is_string()) {
                auto it = resolved.find(j.get<std::string>());
                if (it != resolved.end()) j = it->second;
            } else if (j.is_structured()) {
                for (auto& child : j) replace(child);
            }
        };
        replace(ctx_.doc());
    }
    // pbrt-v4's default material: diffuse of reflectance 0.5.
    void ensure_material() {
        if (!state_.material.empty()) return;
        if (default_material_.empty()) {
            default_material_ = ctx_.new_material_name("default");
            ctx_.doc()["materials"][default_material_] = Json{{"type", "diffuse"}, {"albedo", 0.5}};
        }
        state_.material = default_material_;
    }
    // pbrt-v4's default integrator is volpath, which candela's path equals where there are no
    // media: volpath where the scene has media. (pbrt-v4's path ignores media and warns; the
    // loader gives that warning, for any integrator but volpath.)
    void finish_integrator() {
        if (integrator_follows_media_ && !ctx_.doc()["media"].empty()) ctx_.doc()["integrator"]["type"] = "volpath";
    }
    ImportContext ctx_;
    GraphicsState state_;
    std::vector<std::pair<GraphicsState, Location>> stack_;
    std::map<std::string, std::pair<Transform, Transform>> named_frames_;  // at the start and end times
    RenderOptions options_;
    bool in_world_ = false;
    bool options_translated_ = false;
    bool integrator_follows_media_ = false;
    std::vector<std::pair<std::string, Location>> medium_uses_;  // media shapes name, and where
    std::string default_material_;
    std::map<std::string, ObjectDefinition> objects_;
    std::set<std::string> turning_objects_;  // objects with a moving ObjectInstance
    ObjectDefinition* object_ = nullptr;
    std::string object_name_;
};

}  // namespace

ImportedScene import_pbrt_file(const std::filesystem::path& file) {
    ImportedScene out;
    Importer importer(out, file);
    parse_file(file, importer);
    return out;
}

ImportedScene import_pbrt_string(std::string_view text, const std::filesystem::path& name) {
    ImportedScene out;
    Importer importer(out, name);
    parse_string(text, name, importer);
    return out;
}

}  // namespace candela::pbrt
