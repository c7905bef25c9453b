#include "candela/render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>

#include "candela/camera/perspective_camera.h"
#include "candela/film/film.h"
#include "candela/film/filter.h"
#include "candela/geometry/accelerator.h"
#include "candela/lights/light_set.h"
#include "candela/render/integrator.h"
#include "candela/render/progress.h"
#include "candela/sampling/rng.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Tile {
    int x0, y0, x1, y1;
};

std::vector<Tile> make_tiles(int width, int height, int size) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += size)
        for (int x = 0; x < width; x += size)
            tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
    return tiles;
}

// What each thread counts on its own; summed once at the end.
struct ThreadTally {
    RayCounters rays;
    uint64_t dropped = 0;
};

}  // namespace

LightSet build_light_set(const Scene& scene, const Accelerator& accel) {
    std::optional<EnvironmentLight> environment;
    if (const auto& env = scene.environment)
        environment.emplace(env->radiance, env->scale, env->to_world, env->sampling);
    // The environment's power estimate needs the scene's size: its bounding sphere.
    Bounds3f bounds = accel.bounds();
    float scene_radius = bounds.empty() ? 1.0f : std::max(0.5f * length(bounds.diagonal()), 1e-6f);
    return LightSet(scene.meshes, scene.spheres, scene.shapes, scene.integrator.light_selection,
                    std::move(environment), scene_radius);
}

RenderResult render(const Scene& scene, const RenderOptions& options) {
    RenderResult result;
    Clock::time_point build_start = Clock::now();
    Accelerator accel(scene.meshes, scene.spheres, scene.shapes);

    LightSet lights = build_light_set(scene, accel);
    result.stats.build_seconds = seconds_since(build_start);

    PerspectiveCamera camera(scene.camera);
    std::unique_ptr<Integrator> integrator = make_integrator(scene, accel, lights);
    const int width = camera.width(), height = camera.height();
    const auto spp = uint32_t(scene.sampler.spp);
    const uint64_t seed = scene.sampler.seed;
    const FilterType filter = scene.film.filter;

    Film film(width, height);
    std::vector<Tile> tiles = make_tiles(width, height, std::max(1, options.tile_size));
    int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
    result.stats.threads = threads;
    tbb::enumerable_thread_specific<ThreadTally> tallies;

    Clock::time_point render_start = Clock::now();
    {
        ProgressBar progress(uint64_t(width) * uint64_t(height) * spp, options.progress);
        tbb::task_arena arena(threads);
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
                enable_flush_denormals();
                ThreadTally& tally = tallies.local();
                for (size_t t = r.begin(); t != r.end(); ++t) {
                    const Tile& tile = tiles[t];
                    uint64_t rays_before = tally.rays.total();
                    for (int y = tile.y0; y < tile.y1; ++y) {
                        for (int x = tile.x0; x < tile.x1; ++x) {
                            uint64_t pixel = uint64_t(y) * uint64_t(width) + uint64_t(x);
                            // Samples in index order, each from its own stream: the pixel's sum is
                            // the same whichever thread computes it.
                            for (uint32_t s = 0; s < spp; ++s) {
                                Rng rng = Rng::for_sample(pixel, s, seed);
                                Vec2f film_pos = Vec2f(float(x), float(y)) + sample_filter(filter, s, rng.next_vec2f());
                                Rgb L = integrator->radiance(camera.generate_ray(film_pos), rng, tally.rays);
                                if (!L.is_finite()) {
                                    ++tally.dropped;
                                    continue;
                                }
                                film.add_sample(x, y, L);
                            }
                        }
                    }
                    uint64_t pixels = uint64_t(tile.x1 - tile.x0) * uint64_t(tile.y1 - tile.y0);
                    progress.advance(pixels * spp, tally.rays.total() - rays_before);
                }
            });
        });
    }
    result.stats.render_seconds = seconds_since(render_start);
    for (const ThreadTally& t : tallies) {
        result.stats.rays += t.rays;
        result.stats.dropped_samples += t.dropped;
    }
    result.stats.samples = uint64_t(width) * uint64_t(height) * spp;
    result.image = film.resolve(spp);
    return result;
}

}  // namespace candela
