#include "candela/render/progress.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

namespace candela {

ProgressBar::ProgressBar(uint64_t total, bool enabled)
    : total_(total), enabled_(enabled), start_(std::chrono::steady_clock::now()) {
    if (!enabled_) return;
    drawer_ = std::thread([this] {
        std::unique_lock lock(mutex_);
        // Four redraws a second: smooth enough to watch, cheap enough not to matter.
        while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stop_; })) draw(false);
    });
}

ProgressBar::~ProgressBar() {
    if (!enabled_) return;
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    drawer_.join();
    draw(true);
}

double ProgressBar::fraction() const {
    const uint64_t done = done_.load(std::memory_order_relaxed);
    const uint64_t total = total_.load(std::memory_order_relaxed);
    return total > 0 ? std::min(1.0, double(done) / double(total)) : 1.0;
}

void ProgressBar::draw(bool final_line) const {
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double fraction = this->fraction();
    constexpr int kWidth = 30;
    int filled = int(fraction * kWidth);
    std::string bar(size_t(filled), '#');
    bar.resize(kWidth, '.');
    double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    double rate = elapsed > 0.0 ? double(rays_.load(std::memory_order_relaxed)) / elapsed : 0.0;
    // \r and the erase-line code redraw in place; the final call ends the line.
    fmt::print(stderr, "\r\033[K[{}] {:5.1f}%  {} elapsed  ETA {}  {}rays/s{}{}{}", bar, 100.0 * fraction,
               format_duration(elapsed), format_duration(eta), format_count(rate), note_.empty() ? "" : "  ",
               note_, final_line ? "\n" : "");
    std::fflush(stderr);
}

std::string format_duration(double seconds) {
    if (seconds < 60.0) return fmt::format("{:.1f}s", seconds);
    auto s = uint64_t(seconds + 0.5);
    if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
    return fmt::format("{}h{:02}m{:02}s", s / 3600, (s / 60) % 60, s % 60);
}

std::string format_count(double v) {
    if (v >= 1e9) return fmt::format("{:.2f}G", v / 1e9);
    if (v >= 1e6) return fmt::format("{:.2f}M", v / 1e6);
    if (v >= 1e3) return fmt::format("{:.1f}k", v / 1e3);
    return fmt::format("{:.0f}", v);
}

}  // namespace candela
