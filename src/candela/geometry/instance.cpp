#include "candela/geometry/instance.h"

#include <algorithm>
#include <cmath>

#include "candela/geometry/ray_offset.h"

namespace candela {

Instance make_instance(uint32_t object, const Transform& to_world) {
    Instance instance;
    instance.object = object;
    const Transform inverse = to_world.inverse();
    const Transform::Matrix &m = to_world.matrix(), &inv = inverse.matrix();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) {
            instance.to_world.m[r][c] = float(m[r][c]);
            instance.to_object.m[r][c] = float(inv[r][c]);
        }
    }
    return instance;
}

void hit_to_world(const Instance& instance, SurfaceHit& hit) {
    const auto& m = instance.to_world.m;
    const Vec3d p(hit.p), e(hit.p_error);
    // Per row: |M| e carries the object-space error box; |M| |p| + |t| bounds the terms whose
    // roundings (in double, then to float) the transformed point suffers (pbrt-v4's
    // Transform::operator()(Point3fi), with the gamma of float arithmetic to stay conservative).
    double carried = 0.0, magnitude = 0.0;
    for (int r = 0; r < 3; ++r) {
        const double er = std::abs(double(m[r][0])) * e.x + std::abs(double(m[r][1])) * e.y + std::abs(double(m[r][2])) * e.z;
        const double pr =
            std::abs(double(m[r][0]) * p.x) + std::abs(double(m[r][1]) * p.y) + std::abs(double(m[r][2]) * p.z) +
            std::abs(double(m[r][3]));
        carried = std::max(carried, er);
        magnitude = std::max(magnitude, pr);
    }
    hit.p = Vec3f(instance.to_world.apply_point(p));
    // Isotropic, as the accelerator's own bounds (docs/decisions/0002-error-bounded-ray-offsets.md).
    hit.p_error = Vec3f(float(carried * (1.0 + double(rounding_gamma(3))) + magnitude * double(rounding_gamma(3))));
    // Normals by the inverse transpose; the geometric one then agrees with the shading one again,
    // as a directly placed mesh's does (pbrt's rule), should a shear have moved them apart.
    const Vec3f ns = normalize(Vec3f(instance.to_object.apply_transposed(Vec3d(hit.ns))));
    hit.ng = face_forward(normalize(Vec3f(instance.to_object.apply_transposed(Vec3d(hit.ng)))), ns);
    hit.ns = ns;
}

ShadingGeometry shading_to_world(const Instance& instance, const ShadingGeometry& g, const Vec3f& ns) {
    ShadingGeometry w;
    w.uv = g.uv;
    w.dpdu = Vec3f(instance.to_world.apply_vector(Vec3d(g.dpdu)));
    w.dpdv = Vec3f(instance.to_world.apply_vector(Vec3d(g.dpdv)));
    const Vec3d m = instance.to_object.apply_transposed(Vec3d(ns));
    const double len = length(m);
    const Vec3d n = m / len;
    auto derivative = [&](const Vec3f& dn) {
        const Vec3d d = instance.to_object.apply_transposed(Vec3d(dn));
        return Vec3f((d - n * dot(n, d)) / len);
    };
    w.dndu = derivative(g.dndu);
    w.dndv = derivative(g.dndv);
    return w;
}

}  // namespace candela
