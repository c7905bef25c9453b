// The rendering options of a pbrt-v4 scene (Camera, Film, PixelFilter, Sampler, Integrator) as
// candela's camera, film, sampler and integrator, with pbrt-v4's defaults
// (https://pbrt.org/fileformat-v4): a 1280x720 film, a gaussian filter of radius 1.5, 16 samples
// per pixel, the path integrator to depth 5, spectral transport.
#include <fmt/format.h>

#include <cmath>

#include "candela/formats/pbrt/pbrt_import_context.h"
#include "candela/scene/enum_names.h"

namespace candela::pbrt {
namespace {

// The type a directive names: "perspective" of `Camera "perspective"`.
std::string directive_type(const Params& p) {
    const std::string& d = p.directive();
    const size_t open = d.find('"'), close = d.rfind('"');
    return open == std::string::npos || close <= open ? std::string() : d.substr(open + 1, close - open - 1);
}

// pbrt's camera space looks along +z with +y up and +x to the image's right; candela's look_at
// camera puts cross(forward, up) on the right. Where the two agree (the camera transform mirrors
// space, as most exporters' do) the camera is written as position / look_at / up, which people
// can read; otherwise as its matrix (`transform`), which keeps pbrt's orientation.
// A projective camera transform (pbrt-v4 takes any matrix) becomes the affine one that makes the
// same rays: the origin where it takes the camera's (divided by w), the directions by the upper
// 3x3 of its render-space transform (pbrt_directions), as pbrt-v4's pinhole camera makes them.
// as_matrix: write the matrix even where the look_at form would do (a moving camera's two frames
// take the same form). Returns whether the look_at form was written.
bool write_camera_frame(const Transform& camera_from_world, Json& camera, bool as_matrix = false) {
    Transform world_from_camera = camera_from_world.inverse();
    if (!world_from_camera.is_affine()) {
        const Vec3d origin = world_from_camera.apply_point(Vec3d(0, 0, 0));
        Transform::Matrix m = pbrt_directions(world_from_camera, origin).matrix();
        for (int i = 0; i < 3; ++i) m[size_t(i)][3] = origin[i];
        m[3] = {0, 0, 0, 1};
        world_from_camera = Transform(m);
    }
    const Vec3d position = world_from_camera.apply_point(Vec3d(0, 0, 0));
    const Vec3d forward = normalize(world_from_camera.apply_vector(Vec3d(0, 0, 1)));
    const Vec3d up = normalize(world_from_camera.apply_vector(Vec3d(0, 1, 0)));
    const Vec3d right = world_from_camera.apply_vector(Vec3d(1, 0, 0));
    if (!as_matrix && dot(cross(forward, up), right) > 0) {
        camera["position"] = vec_json(position);
        camera["look_at"] = vec_json(position + forward);
        camera["up"] = vec_json(up);
        return true;
    }
    camera["transform"] = transform_json(world_from_camera);
    return false;
}

// A camera transform that differs at the end time (ActiveTransform EndTime before Camera): the
// end frame becomes camera.motion, in the form of the start frame, with the transform times.
void write_camera_motion(const RenderOptions& o, Json& camera) {
    const Location at = o.camera ? o.camera->location() : Location{};
    if (o.camera_from_world.swaps_handedness() != o.camera_from_world_end.swaps_handedness())
        fail(at, "Camera: the camera transforms at the start and end times differ in handedness (one mirrors "
                 "space); a moving camera cannot turn one into the other");
    Json motion = Json::object();
    const bool look_at = camera.contains("look_at");
    if (write_camera_frame(o.camera_from_world_end, motion, !look_at) != look_at) {
        // The end frame needs the matrix form: write both so.
        for (const char* key : {"position", "look_at", "up"}) camera.erase(key);
        motion = Json::object();
        write_camera_frame(o.camera_from_world, camera, true);
        write_camera_frame(o.camera_from_world_end, motion, true);
    }
    if (o.camera_start_time != 0.0 || o.camera_end_time != 1.0)
        motion["times"] = Json::array({o.camera_start_time, o.camera_end_time});
    camera["motion"] = std::move(motion);
}

void translate_camera(const RenderOptions& o, int width, int height, Json& camera, Json& film, ImportContext& ctx) {
    std::string type = "perspective";
    if (o.camera) {
        const Params& p = *o.camera;
        const std::string& d = p.directive();
        type = directive_type(p);
        if (type != "perspective" && type != "orthographic") {
            ctx.warn(p.location(), fmt::format("Camera \"{}\" is not supported; rendered with a perspective camera "
                                               "of the same fov",
                                               type));
            type = "perspective";
        }
        // The shutter interval is the sensor's exposure time (pbrt-v4's CameraBase).
        const double open = p.float_or("shutteropen", 0.0), close = p.float_or("shutterclose", 1.0);
        if (!(close > open)) p.fail(p.find("shutterclose"), "shutterclose must be after shutteropen");
        if (close - open != 1.0) film["exposure_time"] = close - open;
        if (open != 0.0 || close != 1.0) camera["shutter"] = Json::array({open, close});
        if (const Parameter* s = p.find("screenwindow")) {
            std::vector<double> w = p.numbers("screenwindow");
            if (w.size() != 4) p.fail(s, "screenwindow takes 4 numbers: xmin xmax ymin ymax");
            camera["screen_window"] = w;
        }
        if (p.has("frameaspectratio"))
            ctx.warn(p.find("frameaspectratio")->location,
                     "frameaspectratio is not supported: the image's aspect ratio is its resolution's");
        const double lens = p.float_or("lensradius", 0.0);
        const double focus = p.float_or("focaldistance", 1e6);
        if (lens < 0) p.fail(p.find("lensradius"), "lensradius must be >= 0");
        if (!(focus > 0)) p.fail(p.find("focaldistance"), "focaldistance must be > 0");
        if (lens > 0) {
            camera["aperture_radius"] = lens;
            camera["focus_distance"] = focus;
        }
        if (type == "perspective") {
            const double fov = p.float_or("fov", 90.0);
            if (!(fov > 0 && fov < 180)) p.fail(p.find("fov"), "fov must be in (0, 180) degrees");
            camera["fov"] = fov;
        }
        for (const char* unused : {"lensfile", "aperturediameter", "focusdistance", "mapping"})
            if (p.has(unused))
                ctx.warn(p.find(unused)->location, fmt::format("{}: parameter \"{}\" is not supported", d, unused));
    } else {
        camera["fov"] = 90.0;
    }
    camera["type"] = type;
    if (type == "perspective") {
        // pbrt's fov spans the shorter image axis; with a screen window, the window says which
        // part of the plane at tan(fov / 2) the image is.
        if (!camera.contains("screen_window")) camera["fov_axis"] = "smaller";
    } else if (!camera.contains("screen_window")) {
        // pbrt's default screen window spans [-1, 1] on the shorter axis, in camera-space units.
        camera["height"] = width >= height ? 2.0 : 2.0 * double(height) / double(width);
    }
    write_camera_frame(o.camera_from_world, camera);
    if (o.camera_from_world.matrix() != o.camera_from_world_end.matrix()) write_camera_motion(o, camera);
    // pbrt-v4 looks the camera's medium up as the world begins.
    if (!o.camera_medium.empty()) {
        if (!ctx.has_medium(o.camera_medium))
            fail(o.camera ? o.camera->location() : Location{},
                 fmt::format("Camera: medium \"{}\" is not defined (MakeNamedMedium must come before WorldBegin)",
                             o.camera_medium));
        camera["medium"] = o.camera_medium;
    }
    camera["resolution"] = Json::array({width, height});
}

// pbrt-v4's GBufferFilm: the rgb film's image plus, in the same EXR, the first visible surface's
// albedo, position and shading normal (in camera space by default, or world space) and the
// pixel's variance: candela's AOV layers of the same meaning, under pbrt-v4's channel names where
// it has the quantity (film/aov_layers.h; docs/PBRT.md lists the channels candela does not write).
void translate_gbuffer(const Params& p, Json& film) {
    film["aovs"] = Json::array({"albedo", "normal", "position", "variance"});
    film["aov_names"] = "pbrt";
    const std::string space = p.get_string("coordinatesystem").value_or("camera");
    if (space != "camera" && space != "world")
        p.fail(p.find("coordinatesystem"),
               fmt::format("unknown coordinate system \"{}\" for the gbuffer film; expected \"camera\" or \"world\"",
                           space));
    film["aov_space"] = space;
    // pbrt-v4 writes a gbuffer only as OpenEXR (its default file name is pbrt.exr).
    if (auto name = p.get_string("filename"); name && !name->ends_with(".exr") && !name->ends_with(".EXR"))
        p.fail(p.find("filename"), fmt::format("\"{}\": EXR is the only format the gbuffer film writes", *name));
}

void translate_film(const RenderOptions& o, int& width, int& height, Json& film, ImportContext& ctx) {
    width = 1280;
    height = 720;
    if (!o.film) return;
    const Params& p = *o.film;
    const std::string& d = p.directive();
    if (d == "Film \"gbuffer\"") {
        translate_gbuffer(p, film);
    } else if (d != "Film \"rgb\"") {
        ctx.warn(p.location(), fmt::format("{}: rendered as an \"rgb\" film (linear sRGB image)", d));
    }
    const long long w = p.int_or("xresolution", 1280), h = p.int_or("yresolution", 720);
    if (w < 1 || w > 32768) p.fail(p.find("xresolution"), "xresolution must be in 1 .. 32768");
    if (h < 1 || h > 32768) p.fail(p.find("yresolution"), "yresolution must be in 1 .. 32768");
    width = int(w);
    height = int(h);
    if (const Parameter* c = p.find("cropwindow")) {
        std::vector<double> crop = p.numbers("cropwindow");
        if (crop.size() != 4) p.fail(c, "cropwindow takes 4 numbers: x0 x1 y0 y1");
        film["crop_window"] = crop;
    }
    if (p.has("pixelbounds"))
        ctx.warn(p.find("pixelbounds")->location, "pixelbounds is not supported (use cropwindow); the whole image is rendered");
    if (auto name = p.get_string("filename")) film["filename"] = *name;
    if (auto iso = p.get_float("iso")) film["iso"] = *iso;
    if (auto wb = p.get_float("whitebalance")) film["white_balance"] = *wb;
    // pbrt-v4's PixelSensor::Create: "cie1931" or a camera it has the responses of.
    if (auto sensor = p.get_string("sensor")) {
        if (!parse_sensor(*sensor))
            p.fail(p.find("sensor"),
                   fmt::format("unknown sensor \"{}\"; expected one of: {}", *sensor, names_list(sensor_names())));
        if (*sensor != "cie1931") film["sensor"] = *sensor;
    }
    // pbrt-v4's RGBFilm clamps each sample's sensor values to maxcomponentvalue (infinity: none).
    if (auto m = p.get_float("maxcomponentvalue")) {
        if (!(*m > 0)) p.fail(p.find("maxcomponentvalue"), "maxcomponentvalue must be > 0");
        if (std::isfinite(*m)) film["max_component_value"] = *m;
    }
    p.bool_or("savefp16", true);  // a matter of the output file only
    p.float_or("diagonal", 35.0);  // only the realistic camera reads it
}

void translate_filter(const RenderOptions& o, Json& film, ImportContext& ctx) {
    std::string type = "gaussian";
    const Params* p = o.filter ? &*o.filter : nullptr;
    if (p) {
        type = directive_type(*p);
    }
    double radius = 1.5;
    Json filter = Json::object();
    if (type == "box") {
        radius = 0.5;
    } else if (type == "triangle") {
        radius = 2.0;
    } else if (type == "gaussian") {
        filter["sigma"] = p ? p->float_or("sigma", 0.5) : 0.5;
    } else if (type == "mitchell") {
        radius = 2.0;
        filter["B"] = p->float_or("B", 1.0 / 3.0);
        filter["C"] = p->float_or("C", 1.0 / 3.0);
    } else if (type == "sinc" || type == "lanczos") {
        type = "lanczos";
        radius = 4.0;
        filter["tau"] = p->float_or("tau", 3.0);
    } else {
        ctx.warn(p->location(), fmt::format("PixelFilter \"{}\" is not supported; pbrt-v4's default gaussian is used", type));
        type = "gaussian";
        filter["sigma"] = 0.5;
    }
    const double xr = p ? p->float_or("xradius", radius) : radius;
    const double yr = p ? p->float_or("yradius", radius) : radius;
    if (!(xr > 0) || !(yr > 0)) p->fail(p->find(xr > 0 ? "yradius" : "xradius"), "the filter radius must be > 0");
    Json out = Json{{"type", type}, {"radius", Json::array({xr, yr})}};
    for (auto& [k, v] : filter.items()) out[k] = v;
    film["filter"] = out;
}

void translate_sampler(const RenderOptions& o, Json& sampler, ImportContext& ctx) {
    long long spp = 16;
    std::string type = "sobol";
    if (o.sampler) {
        const Params& p = *o.sampler;
        const std::string& d = p.directive();
        const std::string pbrt_type = directive_type(p);
        if (pbrt_type == "stratified") {
            const long long x = p.int_or("xsamples", 4), y = p.int_or("ysamples", 4);
            p.bool_or("jitter", true);
            spp = x * y;
        } else {
            spp = p.int_or("pixelsamples", 16);
        }
        if (spp < 1 || spp > (1 << 24)) p.fail(p.find("pixelsamples"), "pixelsamples must be in 1 .. 16777216");
        if (pbrt_type == "independent") {
            type = "independent";
        } else if (pbrt_type != "sobol" && pbrt_type != "zsobol" && pbrt_type != "paddedsobol") {
            ctx.warn(p.location(), fmt::format("{}: rendered with candela's Owen-scrambled Sobol sampler (the same "
                                               "image, different noise)",
                                               d));
        }
        p.string_or("randomization", "");
        if (auto seed = p.get_int("seed")) sampler["seed"] = *seed;
    }
    sampler["type"] = type;
    sampler["spp"] = spp;
    if (o.seed && !sampler.contains("seed")) sampler["seed"] = *o.seed;
}

// Returns whether the type follows the media (volpath if the scene has any).
bool translate_integrator(const RenderOptions& o, Json& integrator, ImportContext& ctx) {
    long long max_depth = 5;
    std::string type = "path";
    bool follows_media = true;  // pbrt-v4's default integrator is volpath
    // pbrt-v4's path and volpath integrators choose lights with its BVH light sampler unless
    // "lightsampler" says otherwise; so does an import without an Integrator directive.
    std::string light_selection = "bvh";
    if (o.integrator) {
        const Params& p = *o.integrator;
        const std::string& d = p.directive();
        const std::string pbrt_type = directive_type(p);
        follows_media = false;
        if (pbrt_type == "volpath") {
            type = "volpath";
        } else if (pbrt_type == "simplevolpath") {
            type = "volpath";
            ctx.warn(p.location(), fmt::format("{}: rendered with candela's volpath (NEE + MIS through media), which "
                                               "converges to the same image",
                                               d));
        } else if (pbrt_type != "path") {
            // bdpt and mlt render media as volpath does; the others as path.
            follows_media = pbrt_type == "bdpt" || pbrt_type == "mlt";
            ctx.warn(p.location(), fmt::format("{}: rendered with candela's {}, which converges to the same image", d,
                                               follows_media ? "path tracer (volpath where the scene has media)"
                                                             : "path tracer (NEE + MIS)"));
        }
        max_depth = p.int_or("maxdepth", 5);
        if (max_depth < 0) p.fail(p.find("maxdepth"), "maxdepth must be >= 0");
        if (p.bool_or("regularize", false))
            ctx.warn(p.find("regularize")->location, "regularize is not supported; paths are not regularized");
        // pbrt-v4's light samplers; "lightsampler" is the path and volpath integrators' parameter.
        const std::string sampler = p.string_or("lightsampler", "");
        if (sampler == "bvh" || sampler == "power" || sampler == "uniform") {
            light_selection = sampler;
        } else if (sampler == "exhaustive") {
            ctx.warn(p.find("lightsampler")->location,
                     "lightsampler \"exhaustive\" is rendered with \"bvh\" (the same image, other noise)");
            light_selection = "bvh";
        } else if (!sampler.empty()) {
            p.fail(p.find("lightsampler"), fmt::format("unknown lightsampler \"{}\"; expected one of: bvh, exhaustive, "
                                                       "power, uniform",
                                                       sampler));
        } else if (pbrt_type != "path" && pbrt_type != "volpath") {
            // bdpt, mlt and sppm choose lights by power in pbrt-v4 (their own samplers, no parameter).
            light_selection = "power";
        }
    }
    integrator["light_selection"] = light_selection;
    integrator["type"] = type;
    // pbrt-v4's maxdepth 0 renders emitters seen directly only; candela's max_depth counts the
    // same bounces but must be >= 1.
    if (max_depth == 0)
        ctx.warn(o.integrator->location(), "maxdepth 0 is rendered as maxdepth 1 (direct light included)");
    integrator["max_depth"] = std::max<long long>(1, max_depth);
    integrator["rr_depth"] = 1;  // pbrt-v4's PathIntegrator and VolPathIntegrator: Russian roulette once depth > 1
    integrator["spectral"] = true;
    return follows_media;
}

}  // namespace

bool translate_options(const RenderOptions& o, ImportContext& ctx) {
    Json& d = ctx.doc();
    int width = 1280, height = 720;
    translate_film(o, width, height, d["film"], ctx);
    translate_filter(o, d["film"], ctx);
    translate_camera(o, width, height, d["camera"], d["film"], ctx);
    translate_sampler(o, d["sampler"], ctx);
    const bool follows_media = translate_integrator(o, d["integrator"], ctx);
    for (const std::optional<Params>* p : {&o.camera, &o.film, &o.filter, &o.sampler, &o.integrator})
        if (*p) (*p)->report_unused([&](const Location& at, const std::string& m) { ctx.warn(at, m); });
    if (o.camera) ctx.origin("/camera", o.camera->location());
    if (o.film) ctx.origin("/film", o.film->location());
    if (o.sampler) ctx.origin("/sampler", o.sampler->location());
    if (o.integrator) ctx.origin("/integrator", o.integrator->location());
    return follows_media;
}

}  // namespace candela::pbrt
