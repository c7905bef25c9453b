#include "candela/lights/emitter_bounds.h"

#include <cmath>

namespace candela {

namespace {

Vec3f to_float(const Vec3d& v) { return {float(v.x), float(v.y), float(v.z)}; }

// The cone of a mesh's front normals: each triangle's winding normal, flipped towards the sum of
// its vertex normals when it has them (the side hits report as front, mesh_emitter.h; pbrt-v4's
// Triangle::NormalBounds), united over the triangles.
DirectionCone mesh_normal_cone(const TriangleMesh& m) {
    DirectionCone cone;
    for (size_t t = 0; t < m.triangle_count(); ++t) {
        const uint32_t i0 = m.indices[3 * t], i1 = m.indices[3 * t + 1], i2 = m.indices[3 * t + 2];
        Vec3f n = cross(m.positions[i1] - m.positions[i0], m.positions[i2] - m.positions[i0]);
        if (!(length_squared(n) > 0.0f)) continue;  // zero area: never sampled nor hit
        n = normalize(n);
        if (!m.normals.empty()) n = face_forward(n, m.normals[i0] + m.normals[i1] + m.normals[i2]);
        cone = union_of(cone, DirectionCone{n, 1.0f});
    }
    return cone;
}

}  // namespace

LightBounds area_light_bounds(const Shape& shape, std::span<const TriangleMesh> meshes,
                              std::span<const Sphere> spheres, std::span<const Disk> disks,
                              std::span<const Quadric> quadrics, float area) {
    LightBounds b;
    b.phi = shape.emission.max_component() * area * kPi;
    b.cos_theta_e = std::cos(kPi / 2.0f);
    b.two_sided = shape.two_sided;
    switch (shape.kind) {
        case ShapeKind::kMesh: {
            const TriangleMesh& m = meshes[shape.index];
            for (const Vec3f& p : m.positions) b.bounds.extend(p);
            DirectionCone cone = mesh_normal_cone(m);
            b.w = cone.w;
            b.cos_theta_o = cone.empty() ? 1.0f : cone.cos_theta;
            break;
        }
        case ShapeKind::kSphere: {
            const Sphere& s = spheres[shape.index];
            const Vec3f c = to_float(s.center), r{float(s.radius), float(s.radius), float(s.radius)};
            b.bounds.extend(c - r);
            b.bounds.extend(c + r);
            b.cos_theta_o = -1.0f;  // normals all around (pbrt-v4's Sphere::NormalBounds)
            break;
        }
        case ShapeKind::kDisk: {
            const Disk& d = disks[shape.index];
            const Vec3f c = to_float(d.center), u = to_float(d.axis_u), v = to_float(d.axis_v);
            for (float su : {-1.0f, 1.0f})
                for (float sv : {-1.0f, 1.0f}) b.bounds.extend(c + u * su + v * sv);
            b.w = normalize(to_float(d.normal));
            b.cos_theta_o = 1.0f;
            break;
        }
        case ShapeKind::kQuadric: {
            // Clipped spheres, cylinders and disks: their world box, and normals all around
            // (pbrt-v4 gives its cylinders and partial spheres the entire sphere of directions;
            // a disk's one normal would be tighter, and this bound is still a bound).
            Vec3d lo, hi;
            quadric_world_bounds(quadrics[shape.index], lo, hi);
            b.bounds.extend(to_float(lo));
            b.bounds.extend(to_float(hi));
            b.cos_theta_o = -1.0f;
            break;
        }
        case ShapeKind::kCurves: break;  // curves never emit (LightSet refuses them)
    }
    return b;
}

std::optional<LightBounds> delta_light_bounds(const DeltaLight& light) {
    std::optional<LightBounds> result;
    if (const PointLight* p = get_if<PointLight>(&light)) {
        LightBounds& b = result.emplace();
        b.bounds.extend(p->position);
        b.phi = 4.0f * kPi * to_rgb(p->intensity).max_component();
        b.cos_theta_o = std::cos(kPi);
        b.cos_theta_e = std::cos(kPi / 2.0f);
    } else if (const SpotLight* s = get_if<SpotLight>(&light)) {
        LightBounds& b = result.emplace();
        b.bounds.extend(s->position);
        b.w = s->axis;
        b.phi = 4.0f * kPi * to_rgb(s->intensity).max_component();
        b.cos_theta_o = s->cos_falloff_start;
        // Light leaves up to the falloff's width past the full-intensity cone; pbrt-v4's slop
        // keeps a thin falloff from rounding to nothing.
        b.cos_theta_e = std::cos(std::acos(s->cos_falloff_end) - std::acos(s->cos_falloff_start));
        if (b.cos_theta_e == 1.0f && s->cos_falloff_end != s->cos_falloff_start) b.cos_theta_e = 0.999f;
    }
    return result;
}

}  // namespace candela
