#pragma once
// A candela command run to its end as a child process (its exit status and everything it
// printed), and a render stopped by --time-limit after at least one pass, for the command-line
// tests of stops, shards and MPI.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "app/child_process.h"

namespace candela::test {

struct CliRun {
    int exit_code;       // -1 when it did not exit by itself or ran past the timeout
    std::string output;  // stdout and stderr together
};

// Runs `program args...` to its end, its output in `log`.
inline CliRun run_to_exit(const std::string& program, const std::vector<std::string>& args,
                          const std::filesystem::path& log, double timeout_s) {
    ChildProcess p(program, args, log);
    const int code = p.wait_exit(timeout_s);
    return {code, p.output()};
}

// A render that `run_with_limit(seconds)` stops at the time limit after its first pass. The limit
// counts from the program's start, scene loading (and MPI's start-up) included, so on a loaded
// machine `first_seconds` may pass before the first pass is done, and the render then rightly
// writes nothing. The tests are about what a stop writes, not about the machine's speed: such a
// run is tried again with twice the limit, up to 64 times `first_seconds`.
inline CliRun run_stopped_after_a_pass(const std::function<CliRun(const std::string& seconds)>& run_with_limit,
                                       double first_seconds) {
    CliRun r{};
    for (double seconds = first_seconds; seconds <= 64 * first_seconds; seconds *= 2) {
        r = run_with_limit(std::to_string(seconds));
        if (r.output.find("before the first pass was complete") == std::string::npos) break;
    }
    return r;
}

}  // namespace candela::test
