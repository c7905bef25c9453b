#pragma once
// The expected image of a diffuse plane lit directly by lights whose irradiance has a closed form
// (render tests of analytic cases: DESIGN.md, "Correctness"). A diffuse plane of albedo rho under
// irradiance E leaves radiance rho E / pi; with max_depth = 1 (direct light only) every estimator
// renders exactly that, so each pixel's expectation is E / pi times rho, averaged over the pixel's
// footprint on the plane. Pixels are compared block by block with z-tests (render_moments.h).
#include <cmath>
#include <vector>

#include "candela/camera/perspective_camera.h"
#include "candela/math/vec.h"
#include "support/render_moments.h"

namespace candela::test {

// The receiver: the plane y = plane_y with unit normal (0, normal_y, 0), tested within
// max_distance of (center_x, y, center_z).
struct ReceiverPlane {
    float plane_y = 0.0f;
    float normal_y = 1.0f;
    double center_x = 0.0, center_z = 0.0;
    double max_distance = 1.0;
};

// Per pixel: whether its whole footprint sees the receiver within max_distance of its centre
// (where the test expects the lights to be found often enough for the sample variance to be a
// fair estimate), and if so the expected value E / pi for unit albedo, averaged over the
// footprint (16 x 16 midpoint rule on the film, the box filter's uniform density; E is smooth
// there, so the rule's error is far below the noise).
struct ExpectedImage {
    int width = 0;
    int height = 0;
    std::vector<bool> valid;
    std::vector<double> value;
};

// `irradiance(p)`: E at point p of the plane (double), for the plane's normal.
template <class Irradiance>
ExpectedImage expected_plane_image(const Scene& scene, const ReceiverPlane& plane, const Irradiance& irradiance) {
    PerspectiveCamera camera(scene.camera);
    ExpectedImage e;
    e.width = camera.width();
    e.height = camera.height();
    e.valid.assign(size_t(e.width) * size_t(e.height), false);
    e.value.assign(e.valid.size(), 0.0);
    auto on_plane = [&](const Ray& r) {
        Vec3d o(r.o), d(r.d);
        return o + d * ((double(plane.plane_y) - o.y) / d.y);
    };
    constexpr int kSub = 16;
    for (int y = 0; y < e.height; ++y) {
        for (int x = 0; x < e.width; ++x) {
            // The footprint's rays form a convex set, and so do those that reach the plane inside
            // the disk: testing the four corners tests the whole footprint.
            bool valid = true;
            for (int corner = 0; corner < 4; ++corner) {
                Ray r = camera.generate_ray({float(x + corner % 2), float(y + corner / 2)});
                Vec3d p = on_plane(r);
                const double dx = p.x - plane.center_x, dz = p.z - plane.center_z;
                valid = valid && (double(plane.plane_y) - double(r.o.y)) * double(r.d.y) > 0.0 &&
                        dx * dx + dz * dz < plane.max_distance * plane.max_distance;
            }
            const size_t i = size_t(y) * size_t(e.width) + size_t(x);
            e.valid[i] = valid;
            if (!valid) continue;
            double sum = 0.0;
            for (int sy = 0; sy < kSub; ++sy) {
                for (int sx = 0; sx < kSub; ++sx) {
                    Vec2f film(float(x) + (float(sx) + 0.5f) / kSub, float(y) + (float(sy) + 0.5f) / kSub);
                    sum += irradiance(on_plane(camera.generate_ray(film))) / kPiD;
                }
            }
            e.value[i] = sum / (kSub * kSub);
        }
    }
    return e;
}

// Whether every pixel of the block of `size` with top-left pixel (x0, y0) is valid.
inline bool valid_block(const ExpectedImage& e, int x0, int y0, int size) {
    for (int y = y0; y < y0 + size; ++y)
        for (int x = x0; x < x0 + size; ++x)
            if (!e.valid[size_t(y) * size_t(e.width) + size_t(x)]) return false;
    return true;
}

inline long valid_blocks(const ExpectedImage& e, int block) {
    long blocks = 0;
    for (int y = 0; y + block <= e.height; y += block)
        for (int x = 0; x + block <= e.width; x += block) blocks += valid_block(e, x, y, block) ? 1 : 0;
    return blocks;
}

// The z-tests test_plane_image makes where the expectation is not 0 (3 channels per block): a
// control that scales the expectation can only be rejected there.
inline long lit_block_tests(const ExpectedImage& e, int block) {
    long tests = 0;
    for (int y = 0; y + block <= e.height; y += block) {
        for (int x = 0; x + block <= e.width; x += block) {
            if (!valid_block(e, x, y, block)) continue;
            double sum = 0.0;
            for (int yy = y; yy < y + block; ++yy)
                for (int xx = x; xx < x + block; ++xx) sum += e.value[size_t(yy) * size_t(e.width) + size_t(xx)];
            tests += sum > 0.0 ? 3 : 0;
        }
    }
    return tests;
}

// z-tests of every block of valid pixels against `scale` times the expected image with albedo
// `albedo`, Sidak-corrected together. `rounding`: a relative error the renderer's float
// arithmetic may add to every pixel, for blocks whose samples barely vary (a light whose
// irradiance is nearly constant across a pixel): its square times the expectation's adds to each
// block's variance. 0 where the Monte Carlo noise dwarfs it.
inline ZTestFamily test_plane_image(const RenderMoments& m, const ExpectedImage& e, const Rgb& albedo, double scale,
                                    int block, double rounding = 0.0) {
    ZTestFamily family(sidak_critical_z(kRenderTestAlpha, 3 * valid_blocks(e, block)));
    for (int y = 0; y + block <= e.height; y += block) {
        for (int x = 0; x + block <= e.width; x += block) {
            if (!valid_block(e, x, y, block)) continue;
            double expected = 0.0;
            for (int yy = y; yy < y + block; ++yy)
                for (int xx = x; xx < x + block; ++xx) expected += e.value[size_t(yy) * size_t(e.width) + size_t(xx)];
            expected *= scale / (double(block) * double(block));
            for (int c = 0; c < 3; ++c) {
                BlockEstimate b = block_estimate(m, x, y, block, c);
                const double value = double(albedo[c]) * expected;
                family.add(b.mean - value, b.variance + (rounding * value) * (rounding * value), x, y, c);
            }
        }
    }
    return family;
}

}  // namespace candela::test
