#pragma once
// Ray intersection with the clipped quadrics (quadric.h), pbrt-v4's rules in double: the ray is
// taken into object space; of the two roots, the nearer one inside (tmin, tmax) is the hit unless
// it lies outside the z or phi range (or the disk's radii), in which case the farther one is tried.
// Then the surface's (u, v), normal and derivatives at an object-space point, pbrt-v4's
// parameterisation (Sphere, Cylinder and Disk::InteractionFromIntersection) moved to the world.
#include <algorithm>
#include <cmath>
#include <optional>

#include "candela/core/platform.h"
#include "candela/geometry/quadric.h"
#include "candela/geometry/shading_geometry.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

// A hit in object space: the ray parameter, the point moved onto the surface, its phi.
struct QuadricHit {
    double t = 0.0;
    Vec3d p;
    double phi = 0.0;
};

// phi = atan2(y, x) in [0, 2pi).
CANDELA_HD inline double quadric_phi(const Vec3d& p) {
    const double phi = std::atan2(p.y, p.x);
    return phi < 0.0 ? phi + 2.0 * kPiD : phi;
}

// The root t's point on the surface (pbrt-v4's refinement: reprojected onto the sphere or the
// cylinder, moved onto the disk's plane) and whether it lies on the clipped surface.
CANDELA_HD inline bool quadric_candidate(const Quadric& q, const Vec3d& o, const Vec3d& d, double t, QuadricHit& hit) {
    Vec3d p = o + d * t;
    switch (q.kind) {
        case QuadricKind::kSphere: {
            p = p * (q.radius / length(p));
            if (p.x == 0.0 && p.y == 0.0) p.x = 1e-5 * q.radius;  // phi is undefined on the pole
            hit.phi = quadric_phi(p);
            if ((q.clips_z_min() && p.z < q.z_min) || (q.clips_z_max() && p.z > q.z_max) || hit.phi > q.phi_max)
                return false;
            break;
        }
        case QuadricKind::kCylinder: {
            const double scale = q.radius / std::sqrt(p.x * p.x + p.y * p.y);
            p.x *= scale;
            p.y *= scale;
            hit.phi = quadric_phi(p);
            if (p.z < q.z_min || p.z > q.z_max || hit.phi > q.phi_max) return false;
            break;
        }
        case QuadricKind::kDisk: {
            const double r2 = p.x * p.x + p.y * p.y;
            if (r2 > q.radius * q.radius || r2 < q.inner_radius * q.inner_radius) return false;
            hit.phi = quadric_phi(p);
            if (hit.phi > q.phi_max) return false;
            p.z = q.height;
            break;
        }
    }
    hit.t = t;
    hit.p = p;
    return true;
}

// The nearest hit of the world ray o + t d with tmin < t < tmax, if any. d need not be unit.
CANDELA_HD inline std::optional<QuadricHit> intersect_quadric(const Quadric& q, const Vec3d& o_world,
                                                              const Vec3d& d_world, double tmin, double tmax) {
    std::optional<QuadricHit> result;
    const Vec3d o = q.to_object.apply_point(o_world), d = q.to_object.apply_vector(d_world);
    if (q.kind == QuadricKind::kDisk) {
        // A ray in the disk's plane misses it (pbrt-v4's Disk::BasicIntersect).
        if (d.z == 0.0) return result;
        const double t = (q.height - o.z) / d.z;
        QuadricHit hit;
        if (t > tmin && t < tmax && quadric_candidate(q, o, d, t, hit)) result = hit;
        return result;
    }
    // Roots of a t^2 + 2 b t + c = 0 over the coordinates the quadric constrains (all three for
    // the sphere, x and y for the cylinder), in the precise form of sphere_intersection.h.
    const bool sphere = q.kind == QuadricKind::kSphere;
    const Vec3d o2 = sphere ? o : Vec3d(o.x, o.y, 0.0), d2 = sphere ? d : Vec3d(d.x, d.y, 0.0);
    const double a = dot(d2, d2);
    if (!(a > 0.0)) return result;  // a ray along the cylinder's axis
    const double b = dot(o2, d2);
    const double c = dot(o2, o2) - q.radius * q.radius;
    const Vec3d l = o2 - d2 * (b / a);
    const double disc = a * (q.radius * q.radius - dot(l, l));
    if (disc < 0.0) return result;
    const double qq = -(b + std::copysign(std::sqrt(disc), b));
    double t0 = c / qq, t1 = qq / a;
    if (qq == 0.0) t0 = t1 = 0.0;
    if (t0 > t1) std::swap(t0, t1);
    QuadricHit hit;
    if (t0 > tmin && t0 < tmax && quadric_candidate(q, o, d, t0, hit)) return result = hit;
    if (t1 > tmin && t1 < tmax && quadric_candidate(q, o, d, t1, hit)) result = hit;
    return result;
}

// The unit normal of the front side at object-space point p, in the world: the outward normal
// moved by the inverse transpose (so the side is kept under a mirror), flipped when reversed.
CANDELA_HD inline Vec3d quadric_normal(const Quadric& q, const Vec3d& p) {
    const Vec3d n_object = q.kind == QuadricKind::kSphere     ? p
                           : q.kind == QuadricKind::kCylinder ? Vec3d(p.x, p.y, 0.0)
                                                              : Vec3d(0.0, 0.0, 1.0);
    const Vec3d n = normalize(q.to_world.apply_normal(n_object));
    return q.reverse_orientation ? -n : n;
}

// pbrt-v4's (u, v) at object-space point p with azimuth phi: u = phi / phi_max; v = (theta -
// theta_z_min) / (theta_z_max - theta_z_min) on the sphere, (z - z_min) / (z_max - z_min) on the
// cylinder, (radius - r) / (radius - inner_radius) on the disk.
CANDELA_HD inline Vec2f quadric_uv(const Quadric& q, const Vec3d& p, double phi) {
    const double u = phi / q.phi_max;
    double v = 0.0;
    switch (q.kind) {
        case QuadricKind::kSphere: {
            const double theta = std::acos(std::clamp(p.z / q.radius, -1.0, 1.0));
            v = (theta - q.theta_z_min) / (q.theta_z_max - q.theta_z_min);
            break;
        }
        case QuadricKind::kCylinder: v = (p.z - q.z_min) / (q.z_max - q.z_min); break;
        case QuadricKind::kDisk: v = (q.radius - std::sqrt(p.x * p.x + p.y * p.y)) / (q.radius - q.inner_radius); break;
    }
    return Vec2f(static_cast<float>(u), static_cast<float>(v));
}

// The shading geometry at object-space point p: pbrt-v4's dpdu, dpdv, and dndu, dndv from the
// Weingarten equations, in object space, then dpdu, dpdv moved as vectors and dndu, dndv as
// normals into the world (pbrt-v4's Transform of a SurfaceInteraction). Where dpdu vanishes (a
// sphere's pole, a disk's centre) the fallback frame around `ng` stands in.
CANDELA_HD inline ShadingGeometry quadric_shading_geometry(const Quadric& q, const Vec3d& p, const Vec3f& ng) {
    ShadingGeometry g;
    const double phi = quadric_phi(p);
    g.uv = quadric_uv(q, p, phi);
    const Vec3d dpdu(-q.phi_max * p.y, q.phi_max * p.x, 0.0);
    Vec3d dpdv, d2pduu, d2pduv, d2pdvv;
    switch (q.kind) {
        case QuadricKind::kSphere: {
            const double rho = std::sqrt(p.x * p.x + p.y * p.y);
            const double cos_phi = p.x / rho, sin_phi = p.y / rho;
            const double cos_theta = p.z / q.radius;
            const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
            const double dtheta = q.theta_z_max - q.theta_z_min;
            dpdv = Vec3d(p.z * cos_phi, p.z * sin_phi, -q.radius * sin_theta) * dtheta;
            d2pduu = Vec3d(p.x, p.y, 0.0) * (-q.phi_max * q.phi_max);
            d2pduv = Vec3d(-sin_phi, cos_phi, 0.0) * (dtheta * p.z * q.phi_max);
            d2pdvv = p * (-dtheta * dtheta);
            break;
        }
        case QuadricKind::kCylinder:
            dpdv = Vec3d(0.0, 0.0, q.z_max - q.z_min);
            d2pduu = Vec3d(p.x, p.y, 0.0) * (-q.phi_max * q.phi_max);
            break;
        case QuadricKind::kDisk: {
            const double r = std::sqrt(p.x * p.x + p.y * p.y);
            dpdv = Vec3d(p.x, p.y, 0.0) * ((q.inner_radius - q.radius) / r);
            break;
        }
    }
    Vec3d dndu(0.0), dndv(0.0);
    if (q.kind != QuadricKind::kDisk) {
        // Weingarten equations with the fundamental forms (pbrt-v4, 6.2.3).
        const double E = dot(dpdu, dpdu), F = dot(dpdu, dpdv), G = dot(dpdv, dpdv);
        const Vec3d n = normalize(cross(dpdu, dpdv));
        const double e = dot(n, d2pduu), f = dot(n, d2pduv), gg = dot(n, d2pdvv);
        const double egf2 = E * G - F * F;
        const double inv = egf2 == 0.0 ? 0.0 : 1.0 / egf2;
        dndu = dpdu * ((f * F - e * G) * inv) + dpdv * ((e * F - f * E) * inv);
        dndv = dpdu * ((gg * F - f * G) * inv) + dpdv * ((f * F - gg * E) * inv);
    }
    g.dpdu = Vec3f(q.to_world.apply_vector(dpdu));
    g.dpdv = Vec3f(q.to_world.apply_vector(dpdv));
    // The world's unit normal is normalize(M^-T n): its derivatives are (I - n n^T) M^-T dndu /
    // |M^-T n| (as shading_to_world moves an instance's; pbrt-v4 applies M^-T alone).
    const Vec3d n_object = q.kind == QuadricKind::kSphere     ? p / q.radius
                           : q.kind == QuadricKind::kCylinder ? Vec3d(p.x, p.y, 0.0) / q.radius
                                                              : Vec3d(0.0, 0.0, 1.0);
    const Vec3d m = q.to_world.apply_normal(n_object);
    const double len = length(m);
    const Vec3d n_world = m / len;
    auto to_world_derivative = [&](const Vec3d& dn) {
        const Vec3d v = q.to_world.apply_normal(dn);
        return Vec3f((v - n_world * dot(n_world, v)) / len);
    };
    g.dndu = to_world_derivative(dndu);
    g.dndv = to_world_derivative(dndv);
    if (!is_finite(g.dpdv) || length_squared(cross(g.dpdu, g.dpdv)) == 0.0f) {
        fallback_tangents(ng, g.dpdu, g.dpdv);
        g.dndu = g.dndv = Vec3f(0.0f);
    }
    return g;
}

}  // namespace candela
