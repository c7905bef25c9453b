#include "candela/distributed/mpi_renderer.h"

#include <fmt/format.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "candela/core/error.h"
#include "candela/distributed/mpi_channel.h"
#include "candela/distributed/mpi_session.h"
#include "candela/distributed/tile_messages.h"
#include "candela/distributed/tile_scheduler.h"
#include "candela/film/film.h"
#include "candela/geometry/accelerator.h"
#include "candela/render/frame_renderer.h"
#include "candela/film/pixel_statistics.h"
#include "candela/render/adaptive_sampling.h"
#include "candela/render/error_allocation.h"
#include "candela/render/pass_schedule.h"
#include "candela/render/progress.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

using Clock = std::chrono::steady_clock;

// How long a communicating thread sleeps between looks at MPI when nothing wakes it. Each look
// costs ~15 us of a core that a render thread would use (a context switch and MPI's progress
// engine; polling every 0.2 ms cost 6% of the render on 2 cores), so they are rare, and latency
// is hidden instead by each rank asking for work well before it runs out (kQueuedSeconds).
// rank 0 looks every millisecond (a request waits at most that long); another rank every 2 ms
// while its threads have work, and every 0.1 ms while they wait for some.
constexpr auto kRootPollInterval = std::chrono::microseconds(1000);
constexpr auto kBusyPollInterval = std::chrono::microseconds(2000);
constexpr auto kStarvedPollInterval = std::chrono::microseconds(100);
// The work a rank keeps queued beyond one tile per thread, in seconds: several round trips of
// requests, short against a pass (the queue's tail is what a pass's end may wait for).
constexpr double kQueuedSeconds = 0.008;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

[[noreturn]] void protocol_error(const std::string& what) {
    throw std::runtime_error("MPI render: malformed message: " + what);
}

int threads_for(const MpiSession& session, const RenderOptions& options) {
    return options.threads > 0 ? options.threads : default_threads_per_rank(session.local_size());
}

// Rank 0: the scheduler, its own render threads, and the thread that answers the other ranks.
class RootRender {
  public:
    RootRender(const MpiSession& session, const FrameRenderer& frame, const Scene& scene,
               const MpiRenderOptions& options, RenderState start)
        : session_(session), frame_(frame), options_(options), spp_(uint32_t(scene.sampler.spp)),
          adaptive_(scene.sampler.adaptive),
          target_(options.render.target_error > 0.0),
          first_decision_(first_decision_point(adaptive_)),
          tiles_(render_tiles(frame.width(), frame.height(), options.render, adaptive_ || target_)),
          scheduler_(int(tiles_.size()), session.size(), start.samples_done == 0) {
        state_ = std::move(start);
        if (target_) target_scale_ = std::numeric_limits<double>::infinity();
        start_samples_ = state_.samples_done;
        start_dropped_ = state_.dropped_samples;
        for (const Tile& tile : tiles_) {
            pixels_ += uint64_t(tile.pixels());
            regions_.push_back(tile.bounds());
        }
        if (state_.film.has_statistics()) samples_before_ = spp_summary(state_.film, regions_).total;
    }

    MpiRenderResult run() {
        const int threads = threads_for(session_, options_.render);
        const Clock::time_point render_start = Clock::now();
        {
            ProgressBar progress(pixels_ * (spp_ - std::min(spp_, start_samples_)), options_.render.progress);
            progress_ = &progress;
            std::vector<TileTally> tallies(static_cast<size_t>(threads));
            std::vector<std::thread> workers;
            for (int i = 0; i < threads; ++i) workers.emplace_back([this, &tally = tallies[size_t(i)]] { render_locally(tally); });
            if (adaptive_ || target_) {
                std::lock_guard lock(mutex_);
                update_active();  // a resumed render's blocks may have stopped
            }
            serve();
            {
                std::lock_guard lock(mutex_);
                shutdown_ = true;
            }
            work_.notify_all();
            for (std::thread& t : workers) t.join();
            for (const TileTally& t : tallies) rays_ += t.rays;
            if (end_ != RenderEnd::kComplete && options_.on_stop && state_.samples_done > start_samples_)
                options_.on_stop(state_);
            end_workers();
            progress_ = nullptr;
        }
        MpiRenderResult out;
        RenderResult& r = out.result;
        r.end = end_;
        r.stats.build_seconds = frame_.build_seconds();
        r.stats.render_seconds = seconds_since(render_start);
        r.stats.rays = rays_;
        r.stats.threads = threads;
        r.stats.passes = passes_;
        r.stats.samples = state_.film.has_statistics()
                              ? uint64_t(spp_summary(state_.film, regions_).total - samples_before_)
                              : pixels_ * (state_.samples_done - start_samples_);
        r.stats.relmse_estimate = relmse_estimate_;
        r.stats.converged = converged_;
        r.stats.dropped_samples = state_.dropped_samples - start_dropped_;
        r.image = state_.film.resolve(state_.samples_done);
        r.aov_layers = state_.film.resolve_aovs(state_.samples_done);
        r.state = std::move(state_);
        out.stop_signal = stop_signal_;
        out.exit_code = exit_code();
        out.ranks = session_.size();
        out.bytes_sent = channel_.bytes_sent();
        out.bytes_received = channel_.bytes_received();
        return out;
    }

  private:
    int exit_code() const { return end_ == RenderEnd::kStopped ? 128 + stop_signal_ : 0; }

    // A render thread of rank 0: takes tiles of the pass in flight until told to stop.
    void render_locally(TileTally& tally) {
        enable_flush_denormals();
        std::unique_lock lock(mutex_);
        while (true) {
            work_.wait(lock, [&] { return shutdown_ || (pass_active_ && scheduler_.pending() > 0); });
            if (shutdown_) return;
            const int tile_index = scheduler_.take(0, 1).front().tile;
            const Tile tile = tiles_[size_t(tile_index)];
            const uint32_t begin = pass_begin_, end = pass_end_;
            const std::optional<double> target_scale = target_scale_;
            lock.unlock();
            const uint64_t rays_before = tally.rays.total(), dropped_before = tally.dropped;
            frame_.render_tile(tile, begin, end, state_.film, next_, tally, target_scale);
            progress_->advance(sampled_pixels(size_t(tile_index)) * (end - begin), tally.rays.total() - rays_before);
            lock.lock();
            pass_dropped_ += tally.dropped - dropped_before;
            scheduler_.done(tile_index, 0);
            if (scheduler_.pass_complete()) main_.notify_one();  // else the poll will do: wakes cost
        }
    }

    // The answering thread's loop, until the render is complete, stopped or out of time.
    void serve() {
        {
            std::lock_guard lock(mutex_);
            if (!start_pass()) return;
        }
        while (true) {
            while (std::optional<ReceivedMessage> m = channel_.try_receive(kTagToRoot)) handle(*m);
            if (end_ == RenderEnd::kComplete) check_stop();
            if (end_ != RenderEnd::kComplete) return;
            std::unique_lock lock(mutex_);
            if (pass_active_ && scheduler_.pass_complete()) {
                finish_pass();
                if (!start_pass()) return;
            }
            channel_.progress();
            main_.wait_for(lock, kRootPollInterval);
        }
    }

    void check_stop() {
        if (options_.render.stop && options_.render.stop()) {
            stop_signal_ = options_.stop_signal();
            end_ = RenderEnd::kStopped;
        } else if (options_.render.deadline && Clock::now() >= *options_.render.deadline) {
            end_ = RenderEnd::kDeadline;
        }
    }

    // Starts the next pass (mutex_ held); false when there is none: all samples are done, or not
    // one more sample per pixel fits before the deadline.
    bool start_pass() {
        const bool converged_now = converged();  // also the estimate after the last pass
        if (state_.samples_done >= spp_ || converged_now) return false;
        std::optional<double> seconds_left;
        if (options_.render.deadline)
            seconds_left = std::chrono::duration<double>(*options_.render.deadline - Clock::now()).count();
        // Passes end at the decision points of adaptive sampling and of a target error, as in
        // render(): the decisions are made from the state there, so they are the same.
        uint32_t remaining = spp_ - state_.samples_done;
        if (adaptive_ || target_)
            remaining = std::min(remaining, next_decision_point(state_.samples_done, first_decision_) - state_.samples_done);
        const uint32_t n = next_pass_spp(previous_, remaining, options_.render.pass_seconds, seconds_left,
                                         options_.render.pass_spp);
        if (n == 0) {
            end_ = RenderEnd::kDeadline;
            return false;
        }
        if (next_.width() != frame_.width() || next_.height() != frame_.height())
            next_ = Film(frame_.width(), frame_.height(), frame_.weighted(), frame_.aovs(), state_.film.has_statistics());
        pass_begin_ = state_.samples_done;
        pass_end_ = state_.samples_done + n;
        ++pass_id_;
        pass_dropped_ = 0;
        pass_start_ = Clock::now();
        scheduler_.start_pass();
        pass_active_ = true;
        work_.notify_all();
        std::vector<std::pair<int, int>> waiting;
        waiting.swap(waiting_requests_);
        for (auto [rank, want] : waiting) assign(rank, want);
        return true;
    }

    // At a pass boundary, for a film with statistics (mutex_ held): whether the render is done
    // because every pixel stopped or the estimated relMSE met the target, as render() decides it,
    // else the target's allocation scale for the passes to the next decision point; also the
    // estimate, for the progress bar and the summary.
    bool converged() {
        if (!state_.film.has_statistics() || state_.samples_done == 0) return false;
        relmse_estimate_ = estimated_relmse(state_.film, regions_);
        progress_->set_note(fmt::format("relMSE ~{:.3g}", *relmse_estimate_));
        if (!is_decision_point(state_.samples_done, first_decision_)) return false;
        if (target_ && *relmse_estimate_ <= options_.render.target_error) {
            converged_ = true;
            return converged_;
        }
        if (target_)
            target_scale_ =
                target_allocation_scale(state_.film, tiles_, state_.samples_done, options_.render.target_error);
        if ((adaptive_ || target_) && update_active() == 0) converged_ = true;
        return converged_;
    }

    // Adaptive sampling or a target, at a decision point (or the start): each tile's pixels that take samples
    // until the next one, for the progress bar, which then counts them only (as render() does).
    uint64_t update_active() {
        tile_active_ = active_pixels_per_tile(state_.film, tiles_, state_.samples_done, adaptive_, target_scale_);
        uint64_t active = 0;
        for (uint64_t pixels : tile_active_) active += pixels;
        progress_->set_remaining(active * (spp_ - std::min(spp_, state_.samples_done)));
        return active;
    }

    // The pixels of tile `t` that take this pass's samples.
    uint64_t sampled_pixels(size_t t) const {
        return tile_active_.empty() ? uint64_t(tiles_[t].pixels()) : tile_active_[t];
    }

    // Every tile of the pass is home (mutex_ held): `next_` is the new state.
    void finish_pass() {
        pass_active_ = false;
        std::swap(state_.film, next_);
        state_.samples_done = pass_end_;
        state_.dropped_samples += pass_dropped_;
        ++passes_;
        previous_ = {pass_end_ - pass_begin_, seconds_since(pass_start_)};
        if (options_.render.on_pass) options_.render.on_pass(state_);
    }

    // Answers a request of `rank` for `want` tiles now, or when the next pass starts (mutex_ held).
    void assign(int rank, int want) {
        std::vector<TileScheduler::Assignment> tiles;
        if (pass_active_) tiles = scheduler_.take(rank, want);
        if (tiles.empty()) {
            waiting_requests_.emplace_back(rank, want);
            return;
        }
        MessageWriter w(TileMessageType::kAssign);
        w.u32(pass_id_);
        w.u32(pass_begin_);
        w.u32(pass_end_);
        w.u8(target_scale_ ? 1 : 0);
        w.f64(target_scale_.value_or(0.0));
        w.u32(uint32_t(tiles.size()));
        for (const TileScheduler::Assignment& a : tiles) {
            w.u32(uint32_t(a.tile));
            w.u8(a.send_values ? 1 : 0);
            if (!a.send_values) continue;
            const Tile& tile = tiles_[size_t(a.tile)];
            scratch_.resize(size_t(tile.pixels()) * size_t(state_.film.values_per_pixel()));
            state_.film.read_region(tile.bounds(), scratch_.data());
            w.doubles(scratch_.data(), scratch_.size());
        }
        channel_.send(rank, kTagToWorker, std::move(w.bytes()));
    }

    void handle(const ReceivedMessage& m) {
        MessageReader r(m.bytes);
        const std::optional<TileMessageType> type = r.type();
        if (!type) protocol_error("unknown type from rank " + std::to_string(m.source));
        std::lock_guard lock(mutex_);
        switch (*type) {
            case TileMessageType::kRequest: {
                const uint32_t want = r.u32();
                if (r.failed() || want == 0) protocol_error("request");
                assign(m.source, int(std::min<uint32_t>(want, uint32_t(tiles_.size()))));
                break;
            }
            case TileMessageType::kResult: {
                const uint32_t pass = r.u32(), tile_index = r.u32();
                const uint64_t dropped = r.u64();
                const RayCounters rays = r.rays();
                if (r.failed() || pass != pass_id_ || !pass_active_ || tile_index >= tiles_.size())
                    protocol_error("result from rank " + std::to_string(m.source));
                const Tile& tile = tiles_[tile_index];
                scratch_.resize(size_t(tile.pixels()) * size_t(next_.values_per_pixel()));
                if (!r.doubles(scratch_.data(), scratch_.size()) || !r.at_end()) protocol_error("result values");
                next_.write_region(tile.bounds(), scratch_.data());
                pass_dropped_ += dropped;
                scheduler_.done(int(tile_index), m.source);
                progress_->advance(sampled_pixels(tile_index) * (pass_end_ - pass_begin_), rays.total());
                break;
            }
            case TileMessageType::kStop: {
                const int signal = r.i32();
                if (end_ == RenderEnd::kComplete) {
                    stop_signal_ = signal;
                    end_ = RenderEnd::kStopped;
                }
                break;
            }
            default: protocol_error("unexpected message from rank " + std::to_string(m.source));
        }
    }

    // Tells every other rank to stop and waits for each one's goodbye with its ray count; what
    // they send before it (results of an abandoned pass, requests) is dropped.
    void end_workers() {
        for (int rank = 1; rank < session_.size(); ++rank) {
            MessageWriter w(TileMessageType::kEnd);
            w.i32(exit_code());
            channel_.send(rank, kTagToWorker, std::move(w.bytes()));
        }
        int goodbyes = 0;
        while (goodbyes < session_.size() - 1) {
            std::optional<ReceivedMessage> m = channel_.try_receive(kTagToRoot);
            if (!m) {
                channel_.progress();
                std::this_thread::sleep_for(kRootPollInterval);
                continue;
            }
            MessageReader r(m->bytes);
            if (r.type() == TileMessageType::kBye) {
                rays_ += r.rays();
                ++goodbyes;
            }
        }
        channel_.wait_all();
    }

    const MpiSession& session_;
    const FrameRenderer& frame_;
    const MpiRenderOptions& options_;
    const uint32_t spp_;
    const std::optional<AdaptiveSettings> adaptive_;
    const bool target_;  // --target-error
    const uint32_t first_decision_;  // adaptive sampling's or a target's first decision point
    const std::vector<Tile> tiles_;
    uint64_t pixels_ = 0;                // that the tiles cover
    std::vector<PixelBounds> regions_;   // the tiles', for the film's reductions
    double samples_before_ = 0;          // films with statistics: the samples the start state had
    std::optional<double> relmse_estimate_;
    std::optional<double> target_scale_;  // --target-error's allocation scale, at the last decision point
    bool converged_ = false;
    std::vector<uint64_t> tile_active_;  // adaptive sampling: see update_active
    MpiChannel channel_;
    ProgressBar* progress_ = nullptr;

    // Shared with the render threads, under mutex_; the films' tiles are each written by one
    // thread (or the answering thread, for results) between a take and its done.
    std::mutex mutex_;
    std::condition_variable work_;  // wakes render threads: a pass started, or shutdown
    std::condition_variable main_;  // wakes the answering thread: a tile is done
    TileScheduler scheduler_;
    RenderState state_;
    Film next_;
    uint32_t start_samples_ = 0;
    uint64_t start_dropped_ = 0;
    bool pass_active_ = false;
    bool shutdown_ = false;
    uint32_t pass_id_ = 0, pass_begin_ = 0, pass_end_ = 0;
    uint64_t pass_dropped_ = 0;
    Clock::time_point pass_start_;
    PassTiming previous_;
    int passes_ = 0;
    std::vector<std::pair<int, int>> waiting_requests_;  // (rank, tiles wanted)
    std::vector<double> scratch_;

    // The answering thread's own.
    RenderEnd end_ = RenderEnd::kComplete;
    int stop_signal_ = 0;
    RayCounters rays_;
};

// Any other rank: render threads take tiles from a local queue that the communicating thread
// keeps filled by asking rank 0, rendering each tile in place in the rank's own film (which holds,
// for each tile, the values this rank last computed or was sent), and the communicating thread
// sends each result home.
class WorkerRender {
  public:
    WorkerRender(const MpiSession& session, const FrameRenderer& frame, const Scene& scene,
                 const MpiRenderOptions& options)
        : session_(session), frame_(frame), options_(options),
          tiles_(render_tiles(frame.width(), frame.height(), options.render,
                              scene.sampler.adaptive.has_value() || options.render.target_error > 0.0)),
          film_(frame.width(), frame.height(), frame.weighted(), frame.aovs(), needs_statistics(scene, options.render)),
          threads_(threads_for(session, options.render)) {}

    MpiRenderResult run() {
        const int threads = threads_;
        std::vector<TileTally> tallies(static_cast<size_t>(threads));
        std::vector<std::thread> workers;
        for (int i = 0; i < threads; ++i) workers.emplace_back([this, &tally = tallies[size_t(i)]] { render(tally); });
        std::optional<int> exit_code;
        bool request_outstanding = false, stop_reported = false;
        while (!exit_code) {
            while (std::optional<ReceivedMessage> m = channel_.try_receive(kTagToWorker)) {
                exit_code = handle(*m);
                if (exit_code) break;
                request_outstanding = false;
            }
            if (exit_code) break;
            send_results();
            if (!stop_reported && options_.stop_signal() != 0) {
                MessageWriter w(TileMessageType::kStop);
                w.i32(options_.stop_signal());
                channel_.send(0, kTagToRoot, std::move(w.bytes()));
                stop_reported = true;
            }
            int in_work = 0, depth = 0;
            {
                std::lock_guard lock(mutex_);
                in_work = int(queue_.size()) + running_;
                depth = queue_depth(threads);
            }
            if (!request_outstanding && !stop_reported && in_work < depth) {
                MessageWriter w(TileMessageType::kRequest);
                w.u32(uint32_t(depth - in_work));
                channel_.send(0, kTagToRoot, std::move(w.bytes()));
                request_outstanding = true;
            }
            channel_.progress();
            std::unique_lock lock(mutex_);
            main_.wait_for(lock, queue_.empty() ? kStarvedPollInterval : kBusyPollInterval);
        }
        {
            std::lock_guard lock(mutex_);
            shutdown_ = true;
        }
        work_.notify_all();
        for (std::thread& t : workers) t.join();
        RayCounters rays;
        for (const TileTally& t : tallies) rays += t.rays;
        MessageWriter w(TileMessageType::kBye);
        w.rays(rays);
        channel_.send(0, kTagToRoot, std::move(w.bytes()));
        channel_.wait_all();

        MpiRenderResult out;
        out.exit_code = *exit_code;
        out.result.end = *exit_code == 0 ? RenderEnd::kComplete : RenderEnd::kStopped;
        out.result.stats.rays = rays;
        out.result.stats.threads = threads;
        out.ranks = session_.size();
        out.bytes_sent = channel_.bytes_sent();
        out.bytes_received = channel_.bytes_received();
        return out;
    }

  private:
    struct Job {
        int tile;
        uint32_t pass, begin, end;
        std::optional<double> target_scale;
    };
    struct Done {
        Job job;
        uint64_t dropped;
        RayCounters rays;
    };

    void render(TileTally& tally) {
        enable_flush_denormals();
        std::unique_lock lock(mutex_);
        while (true) {
            work_.wait(lock, [&] { return shutdown_ || !queue_.empty(); });
            if (shutdown_) return;
            const Job job = queue_.front();
            queue_.pop_front();
            ++running_;
            lock.unlock();
            const TileTally before = tally;
            const Tile& tile = tiles_[size_t(job.tile)];
            const Clock::time_point start = Clock::now();
            frame_.render_tile(tile, job.begin, job.end, film_, film_, tally, job.target_scale);
            const double per_sample = seconds_since(start) / (double(tile.pixels()) * double(job.end - job.begin));
            RayCounters rays = tally.rays;
            rays.camera -= before.rays.camera;
            rays.bounce -= before.rays.bounce;
            rays.shadow -= before.rays.shadow;
            lock.lock();
            --running_;
            seconds_per_sample_ = seconds_per_sample_ > 0 ? 0.75 * seconds_per_sample_ + 0.25 * per_sample : per_sample;
            pass_spp_ = job.end - job.begin;
            done_.push_back({job, tally.dropped - before.dropped, rays});
            // Woken early only when the queue runs low (to ask for more, and to send the results
            // at a pass's end); the other results go at the next poll.
            if (2 * (int(queue_.size()) + running_) <= queue_depth(threads_)) main_.notify_one();
        }
    }

    // How many tiles to keep queued or in work (mutex_ held): one per thread, and kQueuedSeconds
    // more at the rate the last tiles took (2 per thread before there is a rate), so that a
    // request's answer arrives before the threads run out, whatever a tile costs.
    int queue_depth(int threads) const {
        if (seconds_per_sample_ <= 0) return 2 * threads + 1;
        const double tile_seconds =
            seconds_per_sample_ * double(kTypicalTilePixels) * double(std::max<uint32_t>(pass_spp_, 1));
        const double more = std::ceil(kQueuedSeconds * double(threads) / tile_seconds);
        return threads + int(std::clamp(more, 1.0, 64.0 * double(threads)));
    }

    // An assignment: queues its tiles (after writing the start values sent with them). The end:
    // returns the job's exit code.
    std::optional<int> handle(const ReceivedMessage& m) {
        MessageReader r(m.bytes);
        const std::optional<TileMessageType> type = r.type();
        if (type == TileMessageType::kEnd) {
            const int code = r.i32();
            if (r.failed()) protocol_error("end");
            return code;
        }
        if (type != TileMessageType::kAssign) protocol_error("unexpected message from rank 0");
        const uint32_t pass = r.u32(), begin = r.u32(), end = r.u32();
        const bool has_scale = r.u8() != 0;
        const double scale = r.f64();
        const uint32_t count = r.u32();
        if (has_scale && !(scale >= 0.0)) protocol_error("assignment");
        const std::optional<double> target_scale = has_scale ? std::optional<double>(scale) : std::nullopt;
        std::vector<Job> jobs;
        for (uint32_t i = 0; i < count && !r.failed(); ++i) {
            const uint32_t tile_index = r.u32();
            const uint8_t has_values = r.u8();
            if (r.failed() || tile_index >= tiles_.size()) protocol_error("assignment");
            if (has_values) {
                const Tile& tile = tiles_[tile_index];
                scratch_.resize(size_t(tile.pixels()) * size_t(film_.values_per_pixel()));
                if (!r.doubles(scratch_.data(), scratch_.size())) protocol_error("assignment values");
                film_.write_region(tile.bounds(), scratch_.data());
            }
            jobs.push_back({int(tile_index), pass, begin, end, target_scale});
        }
        if (r.failed() || !r.at_end()) protocol_error("assignment");
        {
            std::lock_guard lock(mutex_);
            queue_.insert(queue_.end(), jobs.begin(), jobs.end());
        }
        work_.notify_all();
        return std::nullopt;
    }

    void send_results() {
        std::vector<Done> done;
        {
            std::lock_guard lock(mutex_);
            done.swap(done_);
        }
        for (const Done& d : done) {
            const Tile& tile = tiles_[size_t(d.job.tile)];
            MessageWriter w(TileMessageType::kResult);
            w.u32(d.job.pass);
            w.u32(uint32_t(d.job.tile));
            w.u64(d.dropped);
            w.rays(d.rays);
            scratch_.resize(size_t(tile.pixels()) * size_t(film_.values_per_pixel()));
            film_.read_region(tile.bounds(), scratch_.data());
            w.doubles(scratch_.data(), scratch_.size());
            channel_.send(0, kTagToRoot, std::move(w.bytes()));
        }
    }

    const MpiSession& session_;
    const FrameRenderer& frame_;
    const MpiRenderOptions& options_;
    const std::vector<Tile> tiles_;
    MpiChannel channel_;
    std::vector<double> scratch_;  // the communicating thread's

    std::mutex mutex_;
    std::condition_variable work_, main_;
    Film film_;  // each tile's region: written by the thread that renders it, or by an assignment
    std::deque<Job> queue_;
    std::vector<Done> done_;
    int running_ = 0;
    bool shutdown_ = false;
    const int threads_;
    double seconds_per_sample_ = 0;  // of a pixel sample, smoothed over the last tiles
    uint32_t pass_spp_ = 0;          // samples per pixel of the last tile's pass
    static constexpr int kTypicalTilePixels = 256;
};

}  // namespace

int default_threads_per_rank(int ranks_on_host) {
    cpu_set_t set;
    CPU_ZERO(&set);
    int cores = sched_getaffinity(0, sizeof(set), &set) == 0 ? CPU_COUNT(&set) : 0;
    if (cores < 1) cores = int(std::max(1u, std::thread::hardware_concurrency()));
    return std::max(1, cores / std::max(1, ranks_on_host));
}

MpiRenderResult render_mpi(const MpiSession& session, const Scene& scene, const MpiRenderOptions& options,
                           RenderState start) {
    const FrameRenderer frame(scene);
    if (session.rank() != 0) return WorkerRender(session, frame, scene, options).run();
    if (start.film.width() != frame.width() || start.film.height() != frame.height() ||
        start.film.weighted() != frame.weighted() || !(start.film.aovs() == frame.aovs()) ||
        start.film.has_statistics() != needs_statistics(scene, options.render))
        throw RenderError("render: the start state does not fit the scene's film");
    return RootRender(session, frame, scene, options, std::move(start)).run();
}

}  // namespace candela
