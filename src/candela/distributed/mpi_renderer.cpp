#include "candela/distributed/mpi_renderer.h"

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "candela/core/error.h"
#include "candela/core/seconds_since.h"
#include "candela/distributed/mpi_channel.h"
#include "candela/distributed/mpi_session.h"
#include "candela/distributed/tile_messages.h"
#include "candela/distributed/tile_scheduler.h"
#include "candela/film/film.h"
#include "candela/geometry/accelerator.h"
#include "candela/render/frame_renderer.h"
#include "candela/render/pass_engine.h"
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

[[noreturn]] void protocol_error(const std::string& what) {
    throw std::runtime_error("MPI render: malformed message: " + what);
}

int threads_for(const MpiSession& session, const RenderOptions& options) {
    return options.threads > 0 ? options.threads : default_threads_per_rank(session.local_size());
}

// Rank 0's pass executor: the tile scheduler, rank 0's own render threads, and the calling
// thread, which answers the other ranks while a pass runs. The pass policy is the engine's.
class RootExecutor final : public PassExecutor {
  public:
    RootExecutor(const MpiSession& session, const FrameRenderer& frame, const MpiRenderOptions& options,
                 const std::vector<Tile>& tiles, uint32_t start_samples)
        : session_(session), frame_(frame), options_(options), tiles_(tiles),
          threads_(threads_for(session, options.render)), start_samples_(start_samples),
          tallies_(size_t(threads_)), scheduler_(int(tiles.size()), session.size(), start_samples == 0) {
        for (int i = 0; i < threads_; ++i)
            workers_.emplace_back([this, &tally = tallies_[size_t(i)]] { render_locally(tally); });
    }

    ~RootExecutor() override { stop_threads(); }

    int threads() const override { return threads_; }
    int stop_signal() const { return stop_signal_; }
    int exit_code(RenderEnd end) const { return end == RenderEnd::kStopped ? 128 + stop_signal_ : 0; }
    const MpiChannel& channel() const { return channel_; }

    // Hands the pass's tiles out (to rank 0's threads and to requests, also those that came
    // while no pass ran) and answers the other ranks until every result is home or the engine
    // says stop.
    uint64_t run_pass(const PassWork& pass, PassEngine& engine) override {
        {
            std::lock_guard lock(mutex_);
            pass_ = pass;
            engine_ = &engine;
            pass_dropped_ = 0;
            scheduler_.start_pass();
            pass_active_ = true;
            std::vector<std::pair<int, int>> waiting;
            waiting.swap(waiting_requests_);
            for (auto [rank, want] : waiting) assign(rank, want);
        }
        work_.notify_all();
        while (true) {
            while (std::optional<ReceivedMessage> m = channel_.try_receive(kTagToRoot)) handle(*m, engine);
            if (engine.should_stop()) break;
            std::unique_lock lock(mutex_);
            if (scheduler_.pass_complete()) break;
            channel_.progress();
            main_.wait_for(lock, kRootPollInterval);
        }
        std::lock_guard lock(mutex_);
        pass_active_ = false;  // rank 0's threads finish the tile in hand and take no more
        return pass_dropped_;
    }

    // Stops rank 0's threads; if the job stopped early, saves its state (on_stop) and only then
    // tells the other ranks to stop (one of them may have died), and collects their ray counts.
    RayCounters finish(RenderEnd end, const RenderState& state) override {
        stop_threads();
        for (const TileTally& t : tallies_) rays_ += t.rays;
        if (end == RenderEnd::kStopped && stop_signal_ == 0) stop_signal_ = options_.stop_signal();
        if (end != RenderEnd::kComplete && options_.on_stop && state.samples_done > start_samples_)
            options_.on_stop(state);
        end_workers(end);
        return rays_;
    }

  private:
    void stop_threads() {
        {
            std::lock_guard lock(mutex_);
            if (shutdown_) return;
            shutdown_ = true;
        }
        work_.notify_all();
        for (std::thread& t : workers_) t.join();
    }

    // A render thread of rank 0: takes tiles of the pass in flight until told to stop.
    void render_locally(TileTally& tally) {
        enable_flush_denormals();
        std::unique_lock lock(mutex_);
        while (true) {
            work_.wait(lock, [&] { return shutdown_ || (pass_active_ && scheduler_.pending() > 0); });
            if (shutdown_) return;
            const int tile_index = scheduler_.take(0, 1).front().tile;
            const PassWork pass = pass_;
            PassEngine& engine = *engine_;
            lock.unlock();
            const uint64_t rays_before = tally.rays.total(), dropped_before = tally.dropped;
            frame_.render_tile(tiles_[size_t(tile_index)], pass.begin, pass.end, *pass.from, *pass.to, tally,
                               pass.target_scale);
            engine.tile_done(size_t(tile_index), pass, tally.rays.total() - rays_before);
            lock.lock();
            pass_dropped_ += tally.dropped - dropped_before;
            scheduler_.done(tile_index, 0);
            if (scheduler_.pass_complete()) main_.notify_one();  // else the poll will do: wakes cost
        }
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
        w.u32(pass_.id);
        w.u32(pass_.begin);
        w.u32(pass_.end);
        w.u8(pass_.target_scale ? 1 : 0);
        w.f64(pass_.target_scale.value_or(0.0));
        w.u32(uint32_t(tiles.size()));
        for (const TileScheduler::Assignment& a : tiles) {
            w.u32(uint32_t(a.tile));
            w.u8(a.send_values ? 1 : 0);
            if (!a.send_values) continue;
            const Tile& tile = tiles_[size_t(a.tile)];
            scratch_.resize(size_t(tile.pixels()) * size_t(pass_.from->values_per_pixel()));
            pass_.from->read_region(tile.bounds(), scratch_.data());
            w.doubles(scratch_.data(), scratch_.size());
        }
        channel_.send(rank, kTagToWorker, std::move(w.bytes()));
    }

    void handle(const ReceivedMessage& m, PassEngine& engine) {
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
                if (r.failed() || pass != pass_.id || !pass_active_ || tile_index >= tiles_.size())
                    protocol_error("result from rank " + std::to_string(m.source));
                const Tile& tile = tiles_[tile_index];
                scratch_.resize(size_t(tile.pixels()) * size_t(pass_.to->values_per_pixel()));
                if (!r.doubles(scratch_.data(), scratch_.size()) || !r.at_end()) protocol_error("result values");
                pass_.to->write_region(tile.bounds(), scratch_.data());
                pass_dropped_ += dropped;
                scheduler_.done(int(tile_index), m.source);
                engine.tile_done(tile_index, pass_, rays.total());
                break;
            }
            case TileMessageType::kStop: {
                const int signal = r.i32();
                if (stop_signal_ == 0) stop_signal_ = signal;
                engine.abandon(RenderEnd::kStopped);
                break;
            }
            default: protocol_error("unexpected message from rank " + std::to_string(m.source));
        }
    }

    // Tells every other rank to stop and waits for each one's goodbye with its ray count; what
    // they send before it (results of an abandoned pass, requests) is dropped.
    void end_workers(RenderEnd end) {
        for (int rank = 1; rank < session_.size(); ++rank) {
            MessageWriter w(TileMessageType::kEnd);
            w.i32(exit_code(end));
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
    const std::vector<Tile>& tiles_;
    const int threads_;
    const uint32_t start_samples_;
    std::vector<TileTally> tallies_;  // one per render thread
    std::vector<std::thread> workers_;
    MpiChannel channel_;
    std::vector<double> scratch_;
    RayCounters rays_;
    int stop_signal_ = 0;  // the signal that stopped the job, received by any rank

    // Shared with the render threads, under mutex_; the films' tiles are each written by one
    // thread (or the answering thread, for results) between a take and its done.
    std::mutex mutex_;
    std::condition_variable work_;  // wakes render threads: a pass started, or shutdown
    std::condition_variable main_;  // wakes the answering thread: a tile is done
    TileScheduler scheduler_;
    PassWork pass_;
    PassEngine* engine_ = nullptr;
    bool pass_active_ = false;
    bool shutdown_ = false;
    uint64_t pass_dropped_ = 0;
    std::vector<std::pair<int, int>> waiting_requests_;  // (rank, tiles wanted)
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
          tiles_(render_tiles(frame.width(), frame.height(), options.render, makes_decisions(scene, options.render))),
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
    // The other ranks' films are made for the scene (WorkerRender): rank 0's must carry as many
    // values per pixel, or the messages would not fit.
    if (start.film.has_statistics() != needs_statistics(scene, options.render))
        throw RenderError("render: the start state does not fit the scene's film");
    const uint32_t start_samples = start.samples_done;
    PassEngine engine(frame, scene, options.render, std::move(start));
    RootExecutor root(session, frame, options, engine.tiles(), start_samples);
    MpiRenderResult out;
    out.result = engine.run(root);
    out.stop_signal = root.stop_signal();
    out.exit_code = root.exit_code(out.result.end);
    out.ranks = session.size();
    out.bytes_sent = root.channel().bytes_sent();
    out.bytes_received = root.channel().bytes_received();
    return out;
}

}  // namespace candela
