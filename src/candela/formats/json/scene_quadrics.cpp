// The clipped quadrics of a scene file (geometry/quadric.h): `cylinder`, and `sphere` or `disk`
// with partial parameters (z_min, z_max, phi_max; inner_radius, phi_max). docs/SCENE_FORMAT.md.
#include <fmt/format.h>

#include <cmath>

#include "candela/formats/json/scene_sections.h"

namespace candela {

namespace {

// phi_max in degrees, 360 when absent.
double read_phi_max(JsonCursor& c) {
    if (auto v = c.get("phi_max")) return v->number(Bounds{0.0, 360.0, true, false});
    return 360.0;
}

// z_min and z_max (defaults for a sphere: -radius and radius), z_min < z_max.
void read_z_range(JsonCursor& c, double default_min, double default_max, double& z_min, double& z_max) {
    std::optional<JsonCursor> lo = c.get("z_min"), hi = c.get("z_max");
    z_min = lo ? lo->number() : default_min;
    z_max = hi ? hi->number() : default_max;
    if (!(z_min < z_max)) {
        const JsonCursor& blame = hi ? *hi : *lo;
        blame.fail(fmt::format("expected z_min < z_max, got z_min {} and z_max {}", z_min, z_max));
    }
}

// The checks that must hold in float, where hits and light samples are: the bounds and the area.
void check_in_float(const Quadric& q, const JsonCursor& blame, bool transformed) {
    Vec3d lo, hi;
    quadric_world_bounds(q, lo, hi);
    if (!is_finite(Vec3f(lo)) || !is_finite(Vec3f(hi)))
        blame.fail(transformed ? "the transform moves the shape beyond float range" : "the shape reaches beyond float range");
    const double det = std::fabs(q.to_world.determinant());
    const auto area = static_cast<float>(q.object_area() * std::cbrt(det * det));
    if (!(area > 0.0f) || !std::isfinite(1.0f / area))
        blame.fail(transformed ? "the transform leaves the shape with no area in float precision"
                               : "the shape has no area in float precision");
}

}  // namespace

bool is_partial_quadric(JsonCursor& c, std::string_view type) {
    if (type == "cylinder") return true;
    if (type == "sphere") return c.has("z_min") || c.has("z_max") || c.has("phi_max");
    if (type == "disk") return c.has("inner_radius") || c.has("phi_max");
    return false;
}

Quadric read_quadric(JsonCursor& c, std::string_view type, bool reverse_orientation) {
    JsonCursor radius_key = c.require("radius");
    const double radius = radius_key.number(Bounds::above(0));
    std::optional<JsonCursor> transform = c.get("transform");
    Transform to_world;
    if (transform) to_world = read_transform(*transform);
    Quadric q;
    if (type == "cylinder") {
        double z_min = 0, z_max = 0;
        read_z_range(c, -1.0, 1.0, z_min, z_max);
        q = make_cylinder_quadric(radius, z_min, z_max, read_phi_max(c), to_world, reverse_orientation);
    } else if (type == "sphere") {
        // Centred at `center`; z_min and z_max are measured from it along z, and clamped to
        // [-radius, radius] as pbrt-v4 clamps them; the range must still cut the sphere.
        const Vec3d center = c.require("center").vec3();
        double z_min = 0, z_max = 0;
        read_z_range(c, -radius, radius, z_min, z_max);
        if (!(z_min < radius && z_max > -radius))
            c.require(z_min >= radius ? "z_min" : "z_max")
                .fail(fmt::format("the z range [{}, {}] misses the sphere of radius {}", z_min, z_max, radius));
        q = make_sphere_quadric(radius, z_min, z_max, read_phi_max(c), to_world * Transform::translate(center),
                                reverse_orientation);
    } else {
        // The disk's frame is the round disk's (disk.h): local x along the frame's first axis.
        JsonCursor normal = c.require("normal");
        const Vec3d n = normal.vec3();
        if (!is_finite(normalize(n))) normal.fail_expected("a nonzero normal");
        const Disk frame = make_round_disk(c.require("center").vec3(), n, 1.0);
        Transform::Matrix m{};
        for (int i = 0; i < 3; ++i) m[i] = {frame.axis_u[i], frame.axis_v[i], frame.normal[i], frame.center[i]};
        m[3] = {0, 0, 0, 1};
        double inner = 0;
        if (auto v = c.get("inner_radius")) {
            inner = v->number(Bounds::at_least(0));
            if (!(inner < radius))
                v->fail(fmt::format("expected inner_radius < radius ({}), got {}", radius, inner));
        }
        q = make_disk_quadric(0.0, radius, inner, read_phi_max(c), to_world * Transform(m), reverse_orientation);
    }
    c.reject_unknown_keys();
    check_in_float(q, transform ? *transform : radius_key, transform.has_value());
    return q;
}

}  // namespace candela
