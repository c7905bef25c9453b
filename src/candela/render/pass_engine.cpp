#include "candela/render/pass_engine.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>
#include <utility>

#include "candela/core/error.h"
#include "candela/core/seconds_since.h"
#include "candela/film/film.h"
#include "candela/film/pixel_statistics.h"
#include "candela/render/adaptive_sampling.h"
#include "candela/render/error_allocation.h"
#include "candela/render/frame_renderer.h"
#include "candela/render/pass_schedule.h"
#include "candela/render/progress.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

using Clock = std::chrono::steady_clock;

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

}  // namespace

bool needs_statistics(const Scene& scene, const RenderOptions& options) {
    return scene.sampler.adaptive.has_value() || options.target_error > 0.0 || options.statistics ||
           film_needs_statistics(scene.film.aovs);
}

bool makes_decisions(const Scene& scene, const RenderOptions& options) {
    return scene.sampler.adaptive.has_value() || options.target_error > 0.0;
}

std::vector<Tile> render_tiles(int width, int height, const RenderOptions& options, bool adaptive) {
    static_assert(kShardTileSize % kAdaptiveBlockSize == 0, "shard tiles must hold whole adaptive blocks");
    if (options.shard.count > 1) return shard_tiles(width, height, options.shard);
    const int size = std::max(1, options.tile_size);
    return make_tiles(width, height, adaptive ? adaptive_tile_size(size) : size);
}

PassEngine::PassEngine(const FrameRenderer& frame, const Scene& scene, const RenderOptions& options, RenderState start)
    : frame_(frame), options_(options), spp_(uint32_t(scene.sampler.spp)), aov_names_(scene.film.aov_names),
      adaptive_(scene.sampler.adaptive), target_(options.target_error > 0.0),
      decisions_(makes_decisions(scene, options)), first_decision_(first_decision_point(adaptive_)),
      tiles_(render_tiles(frame.width(), frame.height(), options, decisions_)), state_(std::move(start)) {
    check_start_state(frame, state_, needs_statistics(scene, options));
    for (const Tile& tile : tiles_) pixels_ += uint64_t(tile.pixels());
    if (state_.film.has_statistics())
        for (const Tile& tile : tiles_) regions_.push_back(tile.bounds());
    // Until the first decision point, the target's allocation keeps every block.
    if (target_) target_scale_ = std::numeric_limits<double>::infinity();
}

PassEngine::~PassEngine() = default;

bool PassEngine::should_stop() {
    if (end_.load(std::memory_order_relaxed) != RenderEnd::kComplete) return true;
    const RenderEnd why = options_.stop && options_.stop()                          ? RenderEnd::kStopped
                          : options_.deadline && Clock::now() >= *options_.deadline ? RenderEnd::kDeadline
                                                                                    : RenderEnd::kComplete;
    if (why == RenderEnd::kComplete) return false;
    abandon(why);
    return true;
}

void PassEngine::abandon(RenderEnd why) {
    RenderEnd none = RenderEnd::kComplete;
    end_.compare_exchange_strong(none, why);  // the first reason stays
}

void PassEngine::tile_done(size_t t, const PassWork& pass, uint64_t rays) {
    const uint64_t sampled = tile_active_.empty() ? uint64_t(tiles_[t].pixels()) : tile_active_[t];
    progress_->advance(sampled * (pass.end - pass.begin), rays);
}

// With decisions, at a decision point (or the start): each tile's pixels that take samples
// until the next one, which the progress bar then counts instead of every pixel.
uint64_t PassEngine::update_active() {
    tile_active_ = active_pixels_per_tile(state_.film, tiles_, state_.samples_done, adaptive_, target_scale_);
    uint64_t active = 0;
    for (uint64_t tile_pixels : tile_active_) active += tile_pixels;
    progress_->set_remaining(active * (spp_ - std::min(spp_, state_.samples_done)));
    return active;
}

// The image's estimated relMSE at the film's count, shown on the progress bar.
void PassEngine::update_estimate() {
    relmse_estimate_ = estimated_relmse(state_.film, regions_);
    estimate_samples_ = state_.samples_done;
    progress_->set_note(fmt::format("relMSE ~{:.3g}", *relmse_estimate_));
}

// After a pass (or at the start), for a film with statistics, at a decision point: the image's
// estimated relMSE, and whether the render is done because the estimate met the target or every
// block stopped, else the target's allocation scale for the passes to the next decision point.
bool PassEngine::decide() {
    if (!state_.film.has_statistics() || state_.samples_done == 0) return false;
    // The estimate reads every pixel's neighbourhood (film/pixel_statistics.h), which costs as much
    // as a few samples of a simple scene at a million pixels: it is made where it is needed, at the
    // decision points, and once at the end for the summary (run), not after every pass.
    if (!is_decision_point(state_.samples_done, first_decision_)) return false;
    update_estimate();
    if (target_ && *relmse_estimate_ <= options_.target_error) return true;
    if (target_)
        target_scale_ = target_allocation_scale(state_.film, tiles_, state_.samples_done, options_.target_error);
    return decisions_ && update_active() == 0;
}

RenderResult PassEngine::run(PassExecutor& executor) {
    RenderResult result;
    RenderStats& stats = result.stats;
    stats.build_seconds = frame_.build_seconds();
    stats.threads = executor.threads();
    const uint32_t start_samples = state_.samples_done;
    const uint64_t start_dropped = state_.dropped_samples;
    const double samples_before = state_.film.has_statistics() ? spp_summary(state_.film, regions_).total : 0.0;
    const Clock::time_point render_start = Clock::now();
    {
        ProgressBar progress(pixels_ * (spp_ - std::min(spp_, start_samples)), options_.progress);
        progress_ = &progress;
        if (decisions_) update_active();  // a resumed render's blocks may have stopped
        converged_ = decide();
        PassTiming previous;
        while (state_.samples_done < spp_ && !converged_ && !should_stop()) {
            std::optional<double> seconds_left;
            if (options_.deadline)
                seconds_left = std::chrono::duration<double>(*options_.deadline - Clock::now()).count();
            uint32_t remaining = spp_ - state_.samples_done;
            if (decisions_)  // decisions are made at fixed counts, so passes end there
                remaining = std::min(remaining, next_decision_point(state_.samples_done, first_decision_) -
                                                    state_.samples_done);
            const uint32_t n = next_pass_spp(previous, remaining, options_.pass_seconds, seconds_left, options_.pass_spp);
            if (n == 0) {  // not one more sample per pixel fits before the deadline
                abandon(RenderEnd::kDeadline);
                break;
            }
            if (next_.width() != frame_.width() || next_.height() != frame_.height())
                next_ = Film(frame_.width(), frame_.height(), frame_.weighted(), frame_.aovs(),
                             state_.film.has_statistics());
            const PassWork pass{uint32_t(stats.passes + 1), state_.samples_done, state_.samples_done + n, &state_.film,
                                &next_, target_scale_};
            const Clock::time_point pass_start = Clock::now();
            const uint64_t dropped = executor.run_pass(pass, *this);
            if (end_.load() != RenderEnd::kComplete) break;  // `next_` is a mix of tiles: dropped

            std::swap(state_.film, next_);
            state_.samples_done = pass.end;
            state_.dropped_samples += dropped;
            ++stats.passes;
            previous = {n, seconds_since(pass_start)};
            if (options_.on_pass) options_.on_pass(state_);
            converged_ = decide();
        }
        stats.rays = executor.finish(end_.load(), state_);
        if (state_.film.has_statistics() && state_.samples_done > 0 && estimate_samples_ != state_.samples_done)
            update_estimate();  // the summary's, where the render did not end at a decision point
        progress_ = nullptr;
    }
    result.end = end_.load();
    stats.render_seconds = seconds_since(render_start);
    stats.dropped_samples = state_.dropped_samples - start_dropped;
    stats.samples = state_.film.has_statistics()
                        ? uint64_t(spp_summary(state_.film, regions_).total - samples_before)
                        : pixels_ * (state_.samples_done - start_samples);
    stats.relmse_estimate = relmse_estimate_;
    stats.converged = converged_;
    result.image = state_.film.resolve(state_.samples_done);
    result.aov_layers = state_.film.resolve_aovs(state_.samples_done, aov_names_);
    result.state = std::move(state_);
    return result;
}

}  // namespace candela
