#include "candela/render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "candela/core/error.h"
#include "candela/film/film.h"
#include "candela/film/pixel_statistics.h"
#include "candela/geometry/accelerator.h"
#include "candela/lights/light_set.h"
#include "candela/film/pixel_filter.h"
#include "candela/render/adaptive_sampling.h"
#include "candela/render/error_allocation.h"
#include "candela/render/frame_renderer.h"
#include "candela/render/pass_schedule.h"
#include "candela/render/progress.h"
#include "candela/sampling/sampler.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A pass's samples [begin, end) for every pixel: each pixel's sum is read from `from`, the pass's
// samples are added in index order, and the new sum is written to `to`. So `from` keeps the state
// before the pass until the whole pass is done, and a pass abandoned halfway leaves no trace.
struct Pass {
    uint32_t begin = 0, end = 0;
    const Film* from = nullptr;
    Film* to = nullptr;
};

// Throws RenderError when `start` cannot continue a render of `frame`: another size, or weight
// sums where the pixel filter has none or the other way round.
void check_start_state(const FrameRenderer& frame, const RenderState& start, bool statistics) {
    const int width = frame.width(), height = frame.height();
    if (start.film.width() != width || start.film.height() != height)
        throw RenderError("render: the start state is " + std::to_string(start.film.width()) + "x" +
                          std::to_string(start.film.height()) + ", the scene " + std::to_string(width) + "x" +
                          std::to_string(height));
    if (start.film.weighted() != frame.weighted())
        throw RenderError(std::string("render: the start state ") + (start.film.weighted() ? "has" : "lacks") +
                          " the weight sums that the pixel filter " + (frame.weighted() ? "needs" : "does not use"));
    if (!(start.film.aovs() == frame.aovs()))
        throw RenderError("render: the start state's AOV layers are not the ones the scene asks for");
    if (statistics && !start.film.has_statistics())
        throw RenderError("render: the start state lacks the per-pixel statistics (sums of squares, sample counts) "
                          "that adaptive sampling and a target error need");
}

// The tiles' pixels, as regions for the film's reductions.
std::vector<PixelBounds> tile_regions(const std::vector<Tile>& tiles) {
    std::vector<PixelBounds> regions;
    regions.reserve(tiles.size());
    for (const Tile& tile : tiles) regions.push_back(tile.bounds());
    return regions;
}

}  // namespace

AlphaCutouts alpha_cutouts(const Scene& scene) {
    AlphaCutouts cutouts;
    cutouts.textures = &scene.textures;
    bool any = false;
    for (const Shape& shape : scene.shapes) {
        const SurfaceParams& surface = scene.materials[shape.material].surface;
        cutouts.shape_alpha.push_back(surface.alpha);
        any = any || surface.cuts_out();
    }
    if (!any) cutouts.shape_alpha.clear();
    return cutouts;
}

LightSet build_light_set(const Scene& scene, const Accelerator& accel) {
    std::optional<EnvironmentLight> environment;
    if (const auto& env = scene.environment)
        environment.emplace(env->radiance, env->scale, env->to_world, env->sampling, env->mapping, env->filter);
    // The environment's and the directional lights' power need the scene's size: its bounding
    // sphere (pbrt-v4's Bounds3::BoundingSphere: centre and half diagonal).
    Bounds3f bounds = accel.bounds();
    float scene_radius = bounds.empty() ? 1.0f : std::max(0.5f * length(bounds.diagonal()), 1e-6f);
    std::vector<DeltaLight> delta_lights;
    std::vector<SpectralColor> delta_spectra;
    for (const DeltaLightSettings& settings : scene.delta_lights) {
        DeltaLight light = settings.light;
        float power_scale = 1.0f;
        if (auto* directional = get_if<DirectionalLight>(&light); directional && settings.directional_power) {
            power_scale = *settings.directional_power / DirectionalLight::power_per_irradiance(scene_radius);
            directional->irradiance *= power_scale;
        }
        delta_lights.push_back(light);
        if (settings.spectrum != kNoSpectrum)
            delta_spectra.push_back(
                SpectralColor{{}, &scene.textures.spectrum(settings.spectrum), settings.spectrum_scale * power_scale});
        else
            delta_spectra.push_back(SpectralColor{rgb_illuminant_spectrum(to_rgb(delta_light_color(light))), nullptr, 1.0f});
    }
    LightSet lights(scene.meshes, scene.spheres, scene.disks, scene.shapes, delta_lights,
                    scene.integrator.light_selection, std::move(environment), scene_radius);
    if (scene.integrator.spectral) {
        std::vector<SpectralColor> shape_spectra(scene.shapes.size());
        for (size_t i = 0; i < scene.shapes.size(); ++i) {
            const Shape& shape = scene.shapes[i];
            if (shape.emission_spectrum != kNoSpectrum)
                shape_spectra[i] = SpectralColor{{}, &scene.textures.spectrum(shape.emission_spectrum), 1.0f};
            else
                shape_spectra[i].rgb = rgb_illuminant_spectrum(shape.emission);
        }
        lights.set_spectra(shape_spectra, delta_spectra);
    }
    return lights;
}

PixelBounds render_pixel_bounds(const Scene& scene) {
    return crop_pixel_bounds(scene.camera.width, scene.camera.height, scene.film.crop_window);
}

Film make_film(const Scene& scene, bool statistics) {
    const PixelBounds bounds = render_pixel_bounds(scene);
    return Film(bounds.width(), bounds.height(), is_tabulated(scene.film.filter.type), scene.film.aovs,
                statistics || scene.sampler.adaptive.has_value() || film_needs_statistics(scene.film.aovs));
}

bool needs_statistics(const Scene& scene, const RenderOptions& options) {
    return scene.sampler.adaptive.has_value() || options.target_error > 0.0 || options.statistics ||
           film_needs_statistics(scene.film.aovs);
}

std::vector<Tile> render_tiles(int width, int height, const RenderOptions& options, bool adaptive) {
    static_assert(kShardTileSize % kAdaptiveBlockSize == 0, "shard tiles must hold whole adaptive blocks");
    if (options.shard.count > 1) return shard_tiles(width, height, options.shard);
    const int size = std::max(1, options.tile_size);
    return make_tiles(width, height, adaptive ? adaptive_tile_size(size) : size);
}

RenderResult render(const Scene& scene, const RenderOptions& options) {
    return render(scene, options, RenderState{make_film(scene, needs_statistics(scene, options))});
}

RenderResult render(const Scene& scene, const RenderOptions& options, RenderState start) {
    RenderResult result;
    const FrameRenderer frame(scene);
    result.stats.build_seconds = frame.build_seconds();
    const int width = frame.width(), height = frame.height();
    const bool statistics = needs_statistics(scene, options);
    check_start_state(frame, start, statistics);
    const std::optional<AdaptiveSettings>& adaptive = scene.sampler.adaptive;
    // Passes end at decision points (adaptive_sampling.h) when blocks decide there: with adaptive
    // sampling, and with --target-error (its check and its allocation, error_allocation.h).
    const bool target = options.target_error > 0.0;
    const bool decisions = adaptive || target;
    const uint32_t first_decision = first_decision_point(adaptive);
    // --target-error's allocation scale at the last decision point.
    std::optional<double> target_scale;
    if (target) target_scale = std::numeric_limits<double>::infinity();
    const auto spp = uint32_t(scene.sampler.spp);
    RenderState& state = result.state;
    state = std::move(start);
    const uint32_t start_samples = state.samples_done;
    Film next;  // the second buffer of a pass (see Pass), allocated when there is one
    const std::vector<Tile> tiles = render_tiles(width, height, options, decisions);
    const std::vector<PixelBounds> regions = state.film.has_statistics() ? tile_regions(tiles) : std::vector<PixelBounds>{};
    uint64_t pixels = 0;  // that the tiles cover
    for (const Tile& tile : tiles) pixels += uint64_t(tile.pixels());
    int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
    result.stats.threads = threads;
    tbb::enumerable_thread_specific<TileTally> tallies;

    // Why the pass in flight was abandoned, set by the first tile that notices.
    std::atomic<RenderEnd> abandon{RenderEnd::kComplete};
    auto check_stop = [&] {
        if (abandon.load(std::memory_order_relaxed) != RenderEnd::kComplete) return true;
        RenderEnd why = options.stop && options.stop()                          ? RenderEnd::kStopped
                        : options.deadline && Clock::now() >= *options.deadline ? RenderEnd::kDeadline
                                                                                : RenderEnd::kComplete;
        if (why == RenderEnd::kComplete) return false;
        RenderEnd none = RenderEnd::kComplete;
        abandon.compare_exchange_strong(none, why);
        return true;
    };

    // One pass over all tiles, in parallel; a stop seen before a tile abandons the rest.
    // One task per tile (simple_partitioner): the default partitioner hands a thread runs of
    // tiles that it then renders alone, so at the end of a pass the other threads idle while it
    // finishes its run. With passes that end often, that cost 4% at 2 threads (bench/RESULTS.md);
    // a tile is milliseconds of work, far above a task's cost.
    // With adaptive sampling: each tile's pixels that take samples until the next decision point
    // (blocks stop only at decision points), counted there for the progress bar.
    std::vector<uint64_t> tile_active;
    auto update_active = [&](ProgressBar& progress) {
        tile_active = active_pixels_per_tile(state.film, tiles, state.samples_done, adaptive, target_scale);
        uint64_t active = 0;
        for (uint64_t tile_pixels : tile_active) active += tile_pixels;
        progress.set_remaining(active * (spp - std::min(spp, state.samples_done)));
        return active;
    };

    auto run_pass = [&](tbb::task_arena& arena, const Pass& pass, ProgressBar& progress) {
        const uint64_t n = pass.end - pass.begin;
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
                enable_flush_denormals();
                TileTally& tally = tallies.local();
                for (size_t t = r.begin(); t != r.end(); ++t) {
                    if (check_stop()) return;
                    const Tile& tile = tiles[t];
                    uint64_t rays_before = tally.rays.total();
                    frame.render_tile(tile, pass.begin, pass.end, *pass.from, *pass.to, tally, target_scale);
                    const uint64_t sampled = tile_active.empty() ? uint64_t(tile.pixels()) : tile_active[t];
                    progress.advance(sampled * n, tally.rays.total() - rays_before);
                }
            }, tbb::simple_partitioner());
        });
    };

    const double samples_before = state.film.has_statistics() ? spp_summary(state.film, regions).total : 0.0;
    // At a decision point: whether the render is done because every pixel stopped, or the
    // estimate met the target; else the target's allocation for the passes to the next one. Also
    // the estimate for the progress bar.
    auto converged = [&](ProgressBar& progress) {
        if (!state.film.has_statistics() || state.samples_done == 0) return false;
        const double estimate = estimated_relmse(state.film, regions);
        result.stats.relmse_estimate = estimate;
        progress.set_note(fmt::format("relMSE ~{:.3g}", estimate));
        if (!is_decision_point(state.samples_done, first_decision)) return false;
        if (target && estimate <= options.target_error) return true;
        if (target) target_scale = target_allocation_scale(state.film, tiles, state.samples_done, options.target_error);
        return decisions && update_active(progress) == 0;
    };

    Clock::time_point render_start = Clock::now();
    {
        ProgressBar progress(pixels * (spp - std::min(spp, start_samples)), options.progress);
        tbb::task_arena arena(threads);
        PassTiming previous;
        if (decisions) update_active(progress);  // a resumed render's blocks may have stopped
        result.stats.converged = converged(progress);
        while (state.samples_done < spp && !result.stats.converged) {
            if (check_stop()) break;
            std::optional<double> seconds_left;
            if (options.deadline)
                seconds_left = std::chrono::duration<double>(*options.deadline - Clock::now()).count();
            uint32_t remaining = spp - state.samples_done;
            if (decisions)
                remaining = std::min(remaining, next_decision_point(state.samples_done, first_decision) - state.samples_done);
            const uint32_t n =
                next_pass_spp(previous, remaining, options.pass_seconds, seconds_left, options.pass_spp);
            if (n == 0) {  // not one more sample per pixel fits before the deadline
                abandon = RenderEnd::kDeadline;
                break;
            }
            if (next.width() != width || next.height() != height)
                next = Film(width, height, frame.weighted(), frame.aovs(), state.film.has_statistics());
            const Pass pass{state.samples_done, state.samples_done + n, &state.film, &next};
            const Clock::time_point pass_start = Clock::now();
            run_pass(arena, pass, progress);
            uint64_t pass_dropped = 0;
            for (TileTally& t : tallies) pass_dropped += std::exchange(t.dropped, 0);
            if (abandon.load() != RenderEnd::kComplete) break;  // `next` is a mix of tiles: dropped

            std::swap(state.film, next);
            state.samples_done = pass.end;
            state.dropped_samples += pass_dropped;
            result.stats.dropped_samples += pass_dropped;
            ++result.stats.passes;
            previous = {n, seconds_since(pass_start)};
            if (options.on_pass) options.on_pass(state);
            result.stats.converged = converged(progress);
        }
    }
    result.end = abandon.load();
    result.stats.render_seconds = seconds_since(render_start);
    for (const TileTally& t : tallies) result.stats.rays += t.rays;
    result.stats.samples = state.film.has_statistics()
                               ? uint64_t(spp_summary(state.film, regions).total - samples_before)
                               : pixels * (state.samples_done - start_samples);
    result.image = state.film.resolve(state.samples_done);
    result.aov_layers = state.film.resolve_aovs(state.samples_done);
    return result;
}

}  // namespace candela
