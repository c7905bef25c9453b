// offset_ray_origin: the moved origin lies beyond the hit's error box, on the side of the normal,
// after its own float rounding, at any coordinate magnitude, with or without an error bound; and
// not much further than that.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/geometry/ray_offset.h"
#include "candela/math/vec.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

TEST(OffsetRayOrigin, LeavesTheErrorBoxOnTheNormalsSideAtEveryScale) {
    Rng rng(17, 3);
    for (int i = 0; i < 200000; ++i) {
        // Coordinates from 1e-4 to 1e6, either sign, some exactly 0; errors from none to large.
        Vec3f p;
        for (int axis = 0; axis < 3; ++axis) {
            float magnitude = std::pow(10.0f, -4.0f + 10.0f * rng.next_float());
            float u = rng.next_float();
            p[axis] = u < 0.1f ? 0.0f : (u < 0.55f ? magnitude : -magnitude);
        }
        float e = rng.next_float();
        Vec3f p_error = e < 0.2f ? Vec3f(0.0f, 0.0f, 0.0f)
                                 : Vec3f(max_component(abs(p)) * rounding_gamma(1 + int(e * 8.0f)));
        Vec3f n = sample_uniform_sphere(rng.next_vec2f());
        if (i % 7 == 0) n = Vec3f(0.0f, i % 2 ? 1.0f : -1.0f, 0.0f);  // axis-aligned: one coordinate moves
        if (max_component(abs(p)) == 0.0f && max_component(p_error) == 0.0f) continue;  // the one exception

        Vec3f po = offset_ray_origin(p, p_error, n);
        // In double, exactly: how far po is along n, against the box's extent along n.
        Vec3d nd(n), moved = Vec3d(po) - Vec3d(p);
        double box = dot(abs(nd), Vec3d(p_error));
        double along = dot(moved, nd) / length(nd);
        ASSERT_GT(along, box) << "p = (" << p.x << ", " << p.y << ", " << p.z << "), n = (" << n.x << ", " << n.y
                              << ", " << n.z << ")";
        // The price of skipping pbrt's per-coordinate step: a few float steps of p, no more.
        Vec3d abs_p = abs(Vec3d(p));
        double slack = 8.0 * std::ldexp(1.0, -24) * (abs_p.x + abs_p.y + abs_p.z);
        EXPECT_LT(along, box * (1.0 + 1e-6) + slack);
    }
}

}  // namespace
}  // namespace candela::test
