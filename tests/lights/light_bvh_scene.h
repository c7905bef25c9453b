#pragma once
// Scenes of many lights for the BVH light sampler's tests (light_bvh_test.cpp,
// light_bvh_stat_test.cpp): random light bounds for LightBvh alone, and a LightSet of every kind
// of light (one-sided and two-sided quads, a sphere, a disk, a point, a spot, a directional light
// and the environment).
#include <cmath>
#include <utility>
#include <vector>

#include "candela/lights/light_bvh.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"
#include "lights/light_test_scene.h"

namespace candela::test {

inline Vec3f random_unit(Rng& rng) { return sample_uniform_sphere(rng.next_vec2f()); }

// `count` random bounds in [-5, 5]^3: small one-sided and two-sided patches facing random ways,
// isotropic points and narrow spots, of powers spread over two decades.
inline std::vector<std::pair<uint32_t, LightBounds>> random_light_bounds(uint32_t count, uint64_t seed) {
    Rng rng = Rng::for_sample(seed, 0, 0);
    std::vector<std::pair<uint32_t, LightBounds>> out;
    for (uint32_t i = 0; i < count; ++i) {
        LightBounds b;
        const Vec3f c = Vec3f(rng.next_float(), rng.next_float(), rng.next_float()) * 10.0f - Vec3f(5.0f, 5.0f, 5.0f);
        b.phi = std::pow(10.0f, 2.0f * rng.next_float());
        b.w = random_unit(rng);
        switch (i % 4) {
            case 0:
            case 1:  // a patch 0.5 wide
                b.bounds.extend(c - Vec3f(0.25f, 0.25f, 0.25f));
                b.bounds.extend(c + Vec3f(0.25f, 0.25f, 0.25f));
                b.cos_theta_o = 1.0f;
                b.cos_theta_e = 0.0f;
                b.two_sided = i % 4 == 1;
                break;
            case 2:  // a point
                b.bounds.extend(c);
                b.cos_theta_o = -1.0f;
                b.cos_theta_e = 0.0f;
                break;
            default:  // a spot of 20 degrees, falling off over 10 more
                b.bounds.extend(c);
                b.cos_theta_o = std::cos(20.0f * kPi / 180.0f);
                b.cos_theta_e = std::cos(10.0f * kPi / 180.0f);
                break;
        }
        out.emplace_back(i, b);
    }
    return out;
}

// Every kind of light: quads 0 (one-sided, facing +z, at z = -2) and 1 (two-sided, facing +x, at
// x = 3), sphere 2, disk 3 (facing -z, at z = 4); a point light at (-3, 0, 0), a spot light at
// (0, -3, 0) pointing +y with a 30 degree cone, a directional light, and a constant environment.
struct AllKindsOfLights {
    LightTestScene scene;
    Image sky{1, 1};
    static constexpr uint32_t kShapes = 4, kDeltas = 3;

    AllKindsOfLights() {
        scene.add_mesh(make_quad({-1.0f, -1.0f, -2.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}), Rgb(2.0f));
        scene.add_mesh(make_quad({3.0f, -0.5f, -0.5f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}), Rgb(1.0f, 3.0f, 2.0f),
                       true);
        scene.add_sphere(Sphere{Vec3d(1.5, 2.0, 1.0), 0.3, false}, Rgb(4.0f));
        scene.add_disk(make_round_disk(Vec3d(0.0, 1.0, 4.0), Vec3d(0.0, 0.0, -1.0), 0.5), Rgb(5.0f));
        scene.add_delta_light(PointLight{{-3.0f, 0.0f, 0.0f}, Color(2.0f)});
        scene.add_delta_light(SpotLight{{0.0f, -3.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, Color(6.0f),
                                        std::cos(20.0f * kPi / 180.0f), std::cos(30.0f * kPi / 180.0f)});
        scene.add_delta_light(DirectionalLight{normalize(Vec3f(1.0f, 1.0f, -1.0f)), Color(0.5f)});
        sky.at(0, 0) = Rgb(0.25f);
    }
    LightSet light_set(LightSelection selection) const {
        return scene.light_set(selection, EnvironmentLight(sky, 1.0f, Transform(), EnvironmentSampling::kUniform), 6.0f);
    }
};

}  // namespace candela::test
