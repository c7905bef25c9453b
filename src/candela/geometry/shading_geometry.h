#pragma once
// The surface's parametrization at a hit: (u, v) and the partial derivatives of the point and of
// the shading normal along u and v. Tangent frames (anisotropic roughness runs along dpdu), normal
// maps and bump maps need them; most hits never do, so Accelerator::shading computes them on
// request from the hit's shape and barycentrics, and nothing of this is done on the hot path.
//
// Conventions (docs/SCENE_FORMAT.md): a mesh's uvs are its vertex uvs interpolated; a quad's are
// (s, t) along (edge1, edge2); a sphere's are pbrt's (phi / 2pi, theta) turned to candela's +y up
// (below). Where a triangle has no uvs, or they are degenerate, dpdu and dpdv are the frame
// pbrt's CoordinateSystem builds from the geometric normal (Duff et al. 2017, math/frame.h).
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/constants.h"
#include "candela/math/frame.h"
#include "candela/math/vec.h"

namespace candela {

struct ShadingGeometry {
    Vec2f uv;          // the surface coordinates, as Accelerator::uv
    Vec3f dpdu, dpdv;  // world-space derivatives of the point; cross(dpdu, dpdv) is never 0
    Vec3f dndu, dndv;  // of the shading normal (0 on flat triangles without vertex normals)
};

// dpdu, dpdv of a surface with no usable parametrization: a unit tangent frame around unit `n`
// (pbrt-v4's CoordinateSystem, which is Frame::from_normal), so cross(dpdu, dpdv) = n.
CANDELA_HD inline void fallback_tangents(const Vec3f& n, Vec3f& dpdu, Vec3f& dpdv) {
    const Frame f = Frame::from_normal(n);
    dpdu = f.s;
    dpdv = f.t;
}

// Solves for the derivatives of a quantity q, given at the corners of a triangle whose corner uvs
// are uv0..uv2, along u and v: (dq02, dq12) = (duv02, duv12) (dqdu, dqdv) inverted (pbrt-v4,
// 6.5.3). Returns false when the uvs are degenerate (|determinant| < 1e-9, pbrt's threshold).
template <class Q>
CANDELA_HD bool triangle_derivatives(const Q& q0, const Q& q1, const Q& q2, const Vec2f& uv0, const Vec2f& uv1,
                                     const Vec2f& uv2, Q& dqdu, Q& dqdv) {
    const Vec2f duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    const Q dq02 = q0 - q2, dq12 = q1 - q2;
    const float det = duv02.x * duv12.y - duv02.y * duv12.x;
    if (!(std::abs(det) >= 1e-9f)) return false;
    const float inv = 1.0f / det;
    dqdu = (dq02 * duv12.y - dq12 * duv02.y) * inv;
    dqdv = (dq12 * duv02.x - dq02 * duv12.x) * inv;
    return true;
}

// A triangle's shading geometry at barycentrics (b1, b2). `uvs` and `normals` point at the three
// corners' values, or are null when the mesh has none (uv is then (b1, b2), as Accelerator::uv);
// `ng` is the hit's unit geometric normal.
CANDELA_HD inline ShadingGeometry triangle_shading_geometry(const Vec3f p[3], const Vec2f* uvs, const Vec3f* normals,
                                                            const Vec2f& b, const Vec3f& ng) {
    ShadingGeometry g;
    const float b0 = 1.0f - b.x - b.y;
    bool parametrized = false;
    if (uvs) {
        g.uv = uvs[0] * b0 + uvs[1] * b.x + uvs[2] * b.y;
        parametrized = triangle_derivatives(p[0], p[1], p[2], uvs[0], uvs[1], uvs[2], g.dpdu, g.dpdv) &&
                       length_squared(cross(g.dpdu, g.dpdv)) > 0.0f;
        if (parametrized && normals)
            triangle_derivatives(normals[0], normals[1], normals[2], uvs[0], uvs[1], uvs[2], g.dndu, g.dndv);
    } else {
        g.uv = b;
    }
    if (!parametrized) {
        fallback_tangents(ng, g.dpdu, g.dpdv);
        g.dndu = g.dndv = Vec3f(0.0f);
    }
    return g;
}

// A sphere's (u, v) and shading geometry at `n`, the unit outward direction of the point from
// the centre, of radius `r`; `reversed` when its front is the inside (the shading normal is -n).
//
// pbrt's sphere (z up, phi = atan2(y, x), u = phi / 2pi, v growing from the bottom pole to the top)
// with pbrt's z as candela's +y and pbrt's y as -z (a rotation, so the orientation is kept):
// phi = atan2(-z, x), u = phi / 2pi in [0, 1), v = 1 - theta / pi with theta = acos(y). Then
// dpdu = 2pi (z, 0, -x) and dpdv = pi (-y x / rho, rho, -y z / rho) r (rho = sqrt(x^2 + z^2))
// for the point r n, and cross(dpdu, dpdv) points outwards, as pbrt's. At the poles dpdu is 0,
// and the fallback frame stands in.
CANDELA_HD inline Vec2f sphere_uv(const Vec3d& n) {
    const double u = std::atan2(-n.z, n.x) / (2.0 * kPiD);
    const double y = n.y < -1.0 ? -1.0 : (n.y > 1.0 ? 1.0 : n.y);
    return Vec2f(float(u < 0.0 ? u + 1.0 : u), float(1.0 - std::acos(y) / kPiD));
}
CANDELA_HD inline ShadingGeometry sphere_shading_geometry(const Vec3d& n, double r, bool reversed) {
    ShadingGeometry g;
    g.uv = sphere_uv(n);
    const double rho = std::sqrt(n.x * n.x + n.z * n.z);
    if (rho > 0.0) {
        g.dpdu = Vec3f(Vec3d(n.z, 0.0, -n.x) * (2.0 * kPiD * r));
        g.dpdv = Vec3f(Vec3d(-n.y * n.x / rho, rho, -n.y * n.z / rho) * (kPiD * r));
    }
    if (!(rho > 0.0) || length_squared(cross(g.dpdu, g.dpdv)) == 0.0f) {
        fallback_tangents(Vec3f(n), g.dpdu, g.dpdv);
        g.dndu = g.dndv = Vec3f(0.0f);
        return g;
    }
    // The outward normal is (p - c) / r, so its derivatives are dpdu / r and dpdv / r; the shading
    // normal of a reversed sphere is its negation.
    const float s = float((reversed ? -1.0 : 1.0) / r);
    g.dndu = g.dpdu * s;
    g.dndv = g.dpdv * s;
    return g;
}

}  // namespace candela
