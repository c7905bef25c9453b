#pragma once
// An orthonormal frame: the local shading space of BSDFs, where z is the normal.
#include <cmath>

#include "candela/math/vec.h"

namespace candela {

struct Frame {
    Vec3f s, t, n;  // tangent, bitangent, normal: right-handed (cross(s, t) = n)

    // A frame around unit normal n, continuous except at n.z = -1 (Duff et al. 2017,
    // "Building an Orthonormal Basis, Revisited", JCGT 6(1)).
    CANDELA_HD static Frame from_normal(const Vec3f& n) {
        float sign = std::copysign(1.0f, n.z);
        float a = -1.0f / (sign + n.z);
        float b = n.x * n.y * a;
        return {Vec3f(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x),
                Vec3f(b, sign + n.y * n.y * a, -n.y), n};
    }
    // A frame around unit normal n whose s is `tangent` made perpendicular to n (Gram-Schmidt),
    // so that anisotropic lobes' x axis follows the surface's dpdu; from_normal(n) when the
    // tangent is (nearly) parallel to n or not finite.
    CANDELA_HD static Frame from_normal_and_tangent(const Vec3f& n, const Vec3f& tangent) {
        Vec3f s = tangent - n * dot(tangent, n);
        const float len2 = length_squared(s);
        if (!(len2 > 1e-12f * length_squared(tangent))) return from_normal(n);
        s = s * (1.0f / std::sqrt(len2));
        return {s, cross(n, s), n};
    }
    CANDELA_HD Vec3f to_local(const Vec3f& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    CANDELA_HD Vec3f to_world(const Vec3f& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace candela
