#pragma once
// SIGINT and SIGTERM during a render. The first one asks the render to stop: it abandons the
// pass in flight, the program saves the image of the samples done and a checkpoint, and exits
// 128 + the signal's number (130, 143). A second one exits at once with that status, without
// saving: every file candela writes is written atomically, so each is then its last complete
// version (or absent), never a torn one.
namespace candela::cli {

// Installs the handlers (from here on, a signal no longer kills the program outright).
void install_stop_handlers();

// The first stop signal received, 0 while there was none. Safe to call from any thread.
int stop_signal();

}  // namespace candela::cli
