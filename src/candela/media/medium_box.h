#pragma once
// Where a bounded medium sits: its box p0..p1 in medium space and the map from world space into
// medium space (pbrt-v4's bounds and renderFromMedium, the CTM when the medium was named). The
// grid and cloud media look points up through it and clip rays to it.
//
// Rays keep their parameter: a world ray o + t d becomes the medium-space ray M o + t (M d),
// whose direction is not unit length under a scale, so distances t found in medium space (box
// entry and exit, grid crossings) are distances along the world ray (pbrt-v4's
// Transform::ApplyInverse(Ray, &tMax), without its nudge of the origin by the rounding error of
// the transform).
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/bounds.h"
#include "candela/math/ray.h"
#include "candela/math/transform.h"
#include "candela/math/vec.h"

namespace candela {

// An affine map y = A x + b of points (and y = A x of vectors) in float: a row-major 3x4 matrix.
struct AffineMap3f {
    float m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

    CANDELA_HD Vec3f apply_vector(const Vec3f& v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    CANDELA_HD Vec3f apply_point(const Vec3f& p) const {
        return apply_vector(p) + Vec3f(m[0][3], m[1][3], m[2][3]);
    }
    // The map that applies `first`, then this one.
    CANDELA_HD AffineMap3f after(const AffineMap3f& first) const {
        AffineMap3f r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) {
                float s = j == 3 ? m[i][3] : 0.0f;
                for (int k = 0; k < 3; ++k) s += m[i][k] * first.m[k][j];
                r.m[i][j] = s;
            }
        return r;
    }
    // The map x -> scale * x + offset, per axis.
    CANDELA_HD static AffineMap3f scale_offset(const Vec3f& scale, const Vec3f& offset) {
        AffineMap3f r;
        for (int i = 0; i < 3; ++i) {
            r.m[i][i] = scale[i];
            r.m[i][3] = offset[i];
        }
        return r;
    }
};

// A Transform (affine, double) in float: its upper three rows.
AffineMap3f affine_map_3f(const Transform& t);

struct MediumBox {
    AffineMap3f medium_from_world;  // the inverse of the medium's CTM
    Bounds3f bounds{Vec3f(0.0f), Vec3f(1.0f)};  // p0..p1 in medium space

    CANDELA_HD Vec3f to_medium(const Vec3f& p_world) const { return medium_from_world.apply_point(p_world); }

    // A medium-space point as a fraction of the box, (0, 0, 0) at p0 and (1, 1, 1) at p1 (pbrt-v4's
    // Bounds3::Offset: an axis where the box is flat is not divided).
    CANDELA_HD Vec3f unit(const Vec3f& p) const {
        Vec3f o = p - bounds.lo;
        for (int i = 0; i < 3; ++i)
            if (bounds.hi[i] > bounds.lo[i]) o[i] = o[i] / (bounds.hi[i] - bounds.lo[i]);
        return o;
    }

    // The world ray (any direction) in medium space and the stretch [*t0, *t1] of [0, t_max] it
    // spends in the box, t in the world ray's parameter; false when it misses the box (pbrt-v4's
    // Bounds3::IntersectP, whose exit is pushed out by 2 gamma(3) against rounding).
    CANDELA_HD bool clip(const Ray& world, float t_max, Ray* medium, float* t0, float* t1) const {
        medium->o = medium_from_world.apply_point(world.o);
        medium->d = medium_from_world.apply_vector(world.d);
        constexpr float kEpsilon = 0x1p-24f;
        constexpr float kGamma3 = 3 * kEpsilon / (1 - 3 * kEpsilon);
        float t_near = 0.0f, t_far = t_max;
        for (int i = 0; i < 3; ++i) {
            const float inv = 1.0f / medium->d[i];
            float a = (bounds.lo[i] - medium->o[i]) * inv;
            float b = (bounds.hi[i] - medium->o[i]) * inv;
            if (a > b) {
                const float s = a;
                a = b;
                b = s;
            }
            b *= 1 + 2 * kGamma3;
            // A NaN (origin on a face the ray runs parallel to) leaves the interval as it is.
            t_near = a > t_near ? a : t_near;
            t_far = b < t_far ? b : t_far;
            if (t_near > t_far) return false;
        }
        *t0 = t_near;
        *t1 = t_far;
        return true;
    }
};

}  // namespace candela
