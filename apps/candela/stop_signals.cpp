#include "stop_signals.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>

namespace candela::cli {

namespace {

// Signal handlers may only touch lock-free atomics (and call async-signal-safe functions).
static_assert(std::atomic<int>::is_always_lock_free);
std::atomic<int> first_signal{0};
std::atomic<int> signals_received{0};

void say(const char* message) {
    // write(2) is async-signal-safe, stdio is not; a failed write has nobody to tell.
    [[maybe_unused]] ssize_t n = ::write(STDERR_FILENO, message, std::strlen(message));
}

extern "C" void on_stop_signal(int signal) {
    // Any thread may run this, two threads at once for two signals: the counter decides.
    if (signals_received.fetch_add(1) == 0) {
        first_signal.store(signal);
        say("\ncandela: stopping: saving the samples done so far (signal again to quit at once without saving)\n");
        return;
    }
    say("\ncandela: second signal: quitting without saving\n");
    ::_exit(128 + signal);
}

}  // namespace

void install_stop_handlers() {
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    // Both blocked while either handler runs, so the first has set the flag before the second
    // is handled; interrupted system calls (file writes) restart instead of failing.
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGINT);
    sigaddset(&action.sa_mask, SIGTERM);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int stop_signal() { return first_signal.load(); }

}  // namespace candela::cli
