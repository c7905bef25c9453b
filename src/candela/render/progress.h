#pragma once
// Progress reporting on stderr. On a terminal, a bar redrawn a few times a second (percent,
// elapsed, ETA, rays/s); otherwise nothing until the one summary line at the end.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

namespace candela {

class ProgressBar {
  public:
    // total: units of work (camera samples); enabled: draw the bar (a terminal is attached).
    ProgressBar(uint64_t total, bool enabled);
    ~ProgressBar();  // stops the drawing thread, leaving the line finished

    // Called by render threads; lock-free.
    void advance(uint64_t units, uint64_t rays) {
        done_.fetch_add(units, std::memory_order_relaxed);
        rays_.fetch_add(rays, std::memory_order_relaxed);
    }
    // Re-estimates the work: `remaining` more units after those done so far. Adaptive sampling calls
    // it at its decision points, between passes (no advance() runs concurrently), so that the bar
    // fills as the active pixels' samples are taken, not as if every pixel took every sample.
    void set_remaining(uint64_t remaining) {
        total_.store(done_.load(std::memory_order_relaxed) + remaining, std::memory_order_relaxed);
    }
    // The part of the work done, in [0, 1], as the bar shows it.
    double fraction() const;
    // A short text shown after the rate (e.g. the estimated error), from the calling thread.
    void set_note(std::string note) {
        if (!enabled_) return;
        std::lock_guard lock(mutex_);
        note_ = std::move(note);
    }

  private:
    void draw(bool final_line) const;

    std::atomic<uint64_t> total_;
    bool enabled_;
    std::atomic<uint64_t> done_{0};
    std::atomic<uint64_t> rays_{0};
    std::chrono::steady_clock::time_point start_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread drawer_;
    std::string note_;  // guarded by mutex_
};

// Human-readable durations and rates for progress and summary lines: "1m05s", "12.3M".
std::string format_duration(double seconds);
std::string format_count(double value);

}  // namespace candela
