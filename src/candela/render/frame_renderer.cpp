#include "candela/render/frame_renderer.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <type_traits>
#include <string>

#include "candela/camera/camera.h"
#include "candela/core/check.h"
#include "candela/core/error.h"
#include "candela/film/film.h"
#include "candela/film/pixel_filter.h"
#include "candela/geometry/accelerator.h"
#include "candela/lights/light_set.h"
#include "candela/integrators/aov_tracer.h"
#include "candela/render/adaptive_sampling.h"
#include "candela/integrators/integrator.h"
#include "candela/render/frame_setup.h"
#include "candela/sampling/sampler.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

// What every camera sample reads, shared by the render threads (the camera aside: see
// render_pixels).
struct SampleContext {
    const Integrator& integrator;
    int width;  // of the full image
    uint64_t seed;
    SamplerType sampler_type;
    const PixelFilter& filter;
    PixelBounds bounds;  // the film's pixels within the full image (the crop window)
    const AovTracer* aov_tracer;  // null when the film has no AOV layers
    std::optional<AdaptiveSettings> adaptive;
};

// Camera sample `s` of pixel (x, y) of the full image, added to the pixel's running sum (and its
// weight to the weight sum, for a Weighted filter), or dropped (counted) when it is NaN or Inf: a
// dropped sample's weight still counts, so it counts as zero as without weights. Its random
// numbers are a pure function of (pixel, s, seed), so the sum is the same whichever thread
// computes it and however the samples are split into passes. The filter's request comes first,
// then the camera's lens point if it has a lens (camera_model.h). WithAovs: the sample's AOV
// values (integrators/aov_tracer.h) are added, with the same filter weight, to pixel `film_pixel` of
// `to`, after the radiance has taken its random numbers; a sample whose radiance is dropped keeps
// its AOV values, which are always finite. Statistics: the value's square is also added to
// `squares` (a dropped sample counts as zero there too; the caller counts samples).
template <bool Weighted, bool WithAovs, bool Statistics, CameraModel CameraT>
void take_sample(const SampleContext& c, const CameraT& camera, int x, int y, uint32_t s,
                 const PixelSampler& pixel_sampler, PixelSum& sum, double& weight_sum, TileTally& tally, Film& to,
                 Vec2i film_pixel, PixelSum* squares = nullptr) {
    Sampler sampler = pixel_sampler.sample(s);
    const FilterSample f = c.filter.sample(s, sampler.next_vec2f());
    Vec2f film_pos = Vec2f(float(x), float(y)) + f.position;
    const Ray camera_ray = camera.generate_ray(film_pos, sampler);
    Rgb L = c.integrator.radiance(camera_ray, sampler, tally.rays);
    if constexpr (WithAovs)
        to.add_aov_sample(film_pixel.x, film_pixel.y, c.aov_tracer->trace(camera_ray, sampler, tally.rays),
                          Weighted ? f.weight : 1.0f);
    if constexpr (Weighted) weight_sum += double(f.weight);
    if (!L.is_finite()) {
        ++tally.dropped;
        return;
    }
    if constexpr (Weighted)
        add_weighted_to_sum(sum, L, f.weight);
    else
        add_to_sum(sum, L);
    if constexpr (Statistics) {
        if constexpr (Weighted)
            add_weighted_square_to_sum(*squares, L, f.weight);
        else
            add_square_to_sum(*squares, L);
    }
}

// The samples [begin, end) of the pixels of `block` (film pixels), for one kind of camera and
// filter, with or without AOVs and statistics: the caller dispatches on all four once per tile,
// so the sample loop has no camera, weight, AOV or statistics branch (a film without statistics
// or AOVs runs the loop it ran before they existed). The camera and the sampler see full-image
// pixels, so a cropped film's pixels get the rays and random numbers they have in the full
// image. Statistics: also the sums of squares, the counts, the prefix sums and the rays each
// pixel's samples trace (its work, which --target-error's allocation weighs); an inactive block
// (adaptive_sampling.h) takes no samples and is copied.
template <bool Weighted, bool WithAovs, bool Statistics, CameraModel CameraT>
void render_block(const SampleContext& c, const CameraT& camera, const PixelBounds& block, bool active,
                  uint32_t begin, uint32_t end, const Film& from, Film& to, TileTally& tally) {
    for (int y = block.y0; y < block.y1; ++y) {
        for (int x = block.x0; x < block.x1; ++x) {
            PixelSum sum = from.sum(x, y);
            double weight_sum = Weighted ? from.weight(x, y) : 0.0;
            PixelSum squares{};
            double count = 0.0, rays = 0.0;
            PrefixSums prefixes;
            if constexpr (Statistics) {
                squares = from.squares(x, y);
                count = from.count(x, y);
                rays = from.rays(x, y);
                prefixes = from.prefix_sums(x, y);
            }
            if constexpr (WithAovs)
                if (&from != &to) std::copy_n(from.aov_sums(x, y), from.aovs().value_count(), to.aov_sums(x, y));
            if (!Statistics || active) {
                uint64_t rays_before = 0;
                if constexpr (Statistics) rays_before = tally.rays.total();
                const int full_x = x + c.bounds.x0, full_y = y + c.bounds.y0;
                const PixelSampler pixel_sampler(c.sampler_type,
                                                 uint64_t(full_y) * uint64_t(c.width) + uint64_t(full_x), c.seed);
                for (uint32_t s = begin; s < end; ++s) {
                    take_sample<Weighted, WithAovs, Statistics>(c, camera, full_x, full_y, s, pixel_sampler, sum,
                                                                weight_sum, tally, to, Vec2i(x, y), &squares);
                    if constexpr (Statistics) prefixes.after_sample(s, sum, Weighted ? weight_sum : double(s + 1));
                }
                if constexpr (Statistics) {
                    count += double(end - begin);
                    rays += double(tally.rays.total() - rays_before);
                }
            }
            to.sum(x, y) = sum;
            if constexpr (Weighted) to.weight(x, y) = weight_sum;
            if constexpr (Statistics) {
                to.squares(x, y) = squares;
                to.count(x, y) = count;
                to.rays(x, y) = rays;
                to.prefix_sums(x, y) = prefixes;
            }
        }
    }
}

// A tile's samples [begin, end): with statistics block by block, since adaptive sampling and
// --target-error decide per block (tile_blocks) which blocks still take samples; without, the
// tile as one block.
template <bool Weighted, bool WithAovs, bool Statistics, CameraModel CameraT>
void render_pixels(const SampleContext& c, const CameraT& camera, const Tile& tile, uint32_t begin, uint32_t end,
                   const Film& from, Film& to, TileTally& tally, std::optional<double> target_scale) {
    if constexpr (Statistics) {
        for (const PixelBounds& block : tile_blocks(tile)) {
            const bool active =
                (!c.adaptive && !target_scale) || block_active(from, block, begin, c.adaptive, target_scale);
            render_block<Weighted, WithAovs, true>(c, camera, block, active, begin, end, from, to, tally);
        }
    } else {
        render_block<Weighted, WithAovs, false>(c, camera, tile.bounds(), true, begin, end, from, to, tally);
    }
}

}  // namespace

// Built in this order, each reading the ones before.
struct FrameRenderer::Parts {
    Accelerator accel;
    LightSet lights;
    Camera camera;
    std::unique_ptr<Integrator> integrator;
    PixelFilter filter;
    std::optional<AovTracer> aov_tracer;  // engaged when the film has AOV layers
    SampleContext context;

    Parts(const Scene& scene, PixelBounds bounds)
        : accel(scene.meshes, scene.spheres, scene.disks, scene.shapes, alpha_cutouts(scene),
                Instancing{scene.objects, scene.instances, scene.instance_motions, scene.camera.shutter},
                scene.curves, scene.quadrics),
          lights(build_light_set(scene, accel)),
          camera(make_camera(scene.camera, !scene.instance_motions.empty())),
          integrator(make_integrator(scene, accel, lights)),
          filter(scene.film.filter),
          aov_tracer(scene.film.aovs.empty() ? std::nullopt : std::make_optional<AovTracer>(scene, accel)),
          context{*integrator, scene.camera.width, scene.sampler.seed, scene.sampler.type, filter, bounds,
                  aov_tracer ? &*aov_tracer : nullptr, scene.sampler.adaptive},
          aovs(scene.film.aovs) {}
    AovLayers aovs;
};

FrameRenderer::FrameRenderer(const Scene& scene) : bounds_(render_pixel_bounds(scene)) {
    const auto start = std::chrono::steady_clock::now();
    parts_ = std::make_unique<Parts>(scene, bounds_);
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (width() < 1 || height() < 1)
        throw RenderError("render: the film's crop window covers no pixel of the " + std::to_string(scene.camera.width) +
                          "x" + std::to_string(scene.camera.height) + " image");
}

FrameRenderer::~FrameRenderer() = default;

bool FrameRenderer::weighted() const { return parts_->filter.weighted(); }

AovLayers FrameRenderer::aovs() const { return parts_->aovs; }

void FrameRenderer::render_tile(const Tile& tile, uint32_t begin, uint32_t end, const Film& from, Film& to,
                                TileTally& tally, std::optional<double> target_scale) const {
    const Parts& p = *parts_;
    const bool aovs = p.aov_tracer.has_value();
    const bool statistics = from.has_statistics();
    CANDELA_CHECK(to.has_statistics() == statistics && (statistics || (!p.context.adaptive && !target_scale)));
    auto run = [&](auto weighted, auto with_aovs) {
        visit([&](const auto& cam) {
            if (statistics)
                render_pixels<weighted(), with_aovs(), true>(p.context, cam, tile, begin, end, from, to, tally,
                                                             target_scale);
            else
                render_pixels<weighted(), with_aovs(), false>(p.context, cam, tile, begin, end, from, to, tally,
                                                              target_scale);
        }, p.camera);
    };
    if (p.filter.weighted())
        aovs ? run(std::true_type{}, std::true_type{}) : run(std::true_type{}, std::false_type{});
    else
        aovs ? run(std::false_type{}, std::true_type{}) : run(std::false_type{}, std::false_type{});
}

}  // namespace candela
