// pbrt-v4's LightSource directives as candela's lights (docs/SCENE_FORMAT.md, "lights"): point,
// spot, distant (directional) and infinite (environment). Their `scale` and `power` keep pbrt-v4's
// meaning: candela's JSON divides a spectrum by its luminance and applies `power` as pbrt-v4 does.
#include <fmt/format.h>

#include <cmath>

#include "candela/formats/pbrt/pbrt_import_context.h"

namespace candela::pbrt {
namespace {

Json light_colour(const Params& p, const char* name) {
    Json c = p.colour(name, [&](const Parameter& t) -> std::string {
        fail(t.location, fmt::format("{}: \"{}\" cannot be a texture", p.directive(), name));
    });
    return c.is_null() ? Json(1.0) : c;
}

void scale_and_power(const Params& p, Json& light) {
    const double scale = p.float_or("scale", 1.0);
    if (scale < 0) p.fail(p.find("scale"), "scale must be >= 0");
    if (scale != 1) light["scale"] = scale;
    if (auto power = p.get_float("power"); power && *power > 0) light["power"] = *power;
}

}  // namespace

void translate_light(const std::string& type, const Params& p, const Transform& to_world,
                     const Vec3d& camera_position, ImportContext& ctx) {
    // Positions by to_world (with the divide by w of a projective one), directions as pbrt-v4
    // moves them in its render space.
    const Transform directions = pbrt_directions(to_world, camera_position);
    Json light;
    if (type == "point") {
        const Vec3d from = p.get_point3("from").value_or(Vec3d(0, 0, 0));
        light = Json{{"type", "point"}, {"position", vec_json(to_world.apply_point(from))}, {"intensity", light_colour(p, "I")}};
        scale_and_power(p, light);
    } else if (type == "spot") {
        const Vec3d from = p.get_point3("from").value_or(Vec3d(0, 0, 0));
        const Vec3d to = p.get_point3("to").value_or(Vec3d(0, 0, 1));
        if (!(length(to - from) > 0)) p.fail(p.find("to"), "spot: \"from\" and \"to\" are the same point");
        const double cone = p.float_or("coneangle", 30.0), delta = p.float_or("conedeltaangle", 5.0);
        if (!(cone > 0 && cone <= 180)) p.fail(p.find("coneangle"), "spot: coneangle must be in (0, 180]");
        if (!(delta >= 0)) p.fail(p.find("conedeltaangle"), "spot: conedeltaangle must be >= 0");
        light = Json{{"type", "spot"},
                     {"position", vec_json(to_world.apply_point(from))},
                     {"look_at", vec_json(to_world.is_affine() ? to_world.apply_point(to)
                                                               : to_world.apply_point(from) +
                                                                     directions.apply_vector(to - from))},
                     {"intensity", light_colour(p, "I")},
                     {"cone_angle", cone},
                     {"cone_delta", std::min(delta, cone)}};
        if (delta > cone)
            // (conedeltaangle may be the default 5 under a narrower coneangle: no parameter to point at)
            ctx.warn(p.has("conedeltaangle") ? p.find("conedeltaangle")->location : p.location(),
                     "spot: conedeltaangle > coneangle; the falloff spans the whole cone");
        scale_and_power(p, light);
    } else if (type == "distant") {
        const Vec3d from = p.get_point3("from").value_or(Vec3d(0, 0, 0));
        const Vec3d to = p.get_point3("to").value_or(Vec3d(0, 0, 1));
        const Vec3d dir = directions.apply_vector(to - from);
        if (!(length(dir) > 0)) p.fail(p.find("to"), "distant: \"from\" and \"to\" are the same point");
        light = Json{{"type", "directional"}, {"direction", vec_json(dir)}, {"irradiance", light_colour(p, "L")}};
        double scale = p.float_or("scale", 1.0);
        if (scale < 0) p.fail(p.find("scale"), "scale must be >= 0");
        // pbrt-v4's DistantLight: the illuminance (lux) of the light at luminance 1.
        if (auto e = p.get_float("illuminance"); e && *e > 0) scale *= *e;
        if (scale != 1) light["scale"] = scale;
    } else if (type == "infinite") {
        const Parameter* file = p.find("filename");
        const Parameter* L = p.find("L");
        if (file && L) p.fail(L, "infinite: give \"L\" or \"filename\", not both");
        // pbrt-v4's image infinite light reads the nearest texel (no interpolation) of an
        // equal-area square map, in the light's frame.
        double illuminance_factor = 1;
        if (file) {
            light = Json{{"type", "environment"},
                         {"file", p.string_or("filename", "")},
                         {"mapping", "equal_area"},
                         {"filter", "point"}};
            if (!directions.is_identity()) light["transform"] = transform_json(directions);
            // pbrt-v4 integrates a map's illuminance with a texel solid angle of 2 pi / (w h)
            // instead of 4 pi / (w h), so its maps deliver twice the illuminance asked for.
            illuminance_factor = 2;
        } else {
            Json colour = light_colour(p, "L");
            if (!colour.is_number() && !colour.is_array()) {
                ctx.warn(p.find("L")->location, "infinite: a spectrum L is not supported (candela's environment takes "
                                                "RGB); rendered white at the same scale");
                colour = 1.0;
            }
            // pbrt-v4 scales a uniform light by illuminance / pi without taking out the colour's
            // luminance, so the illuminance it delivers is the colour's luminance times that.
            illuminance_factor = colour.is_number() ? colour.get<double>()
                                               : 0.2126 * colour[0].get<double>() + 0.7152 * colour[1].get<double>() +
                                                     0.0722 * colour[2].get<double>();
            light = Json{{"type", "environment"}, {"color", colour}};
        }
        const double scale = p.float_or("scale", 1.0);
        if (scale < 0) p.fail(p.find("scale"), "scale must be >= 0");
        if (scale != 1) light["scale"] = scale;
        if (auto e = p.get_float("illuminance"); e && *e > 0 && illuminance_factor > 0)
            light["illuminance"] = *e * illuminance_factor;
        if (p.has("portal"))
            ctx.warn(p.find("portal")->location, "infinite: portals are not supported; the light is sampled without one");
        if (ctx.doc()["lights"].size() > 0)
            for (const Json& other : ctx.doc()["lights"])
                if (other["type"] == "environment")
                    p.fail(nullptr, "candela supports one infinite light per scene");
    } else {
        ctx.warn(p.location(), fmt::format("LightSource \"{}\" is not supported; skipped", type));
        p.mark_all_used();
        return;
    }
    ctx.origin(fmt::format("/lights/{}", ctx.doc()["lights"].size()), p.location());
    ctx.doc()["lights"].push_back(std::move(light));
}

}  // namespace candela::pbrt
