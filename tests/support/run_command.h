#pragma once
// Runs a shell command line for the command-line tests (popen: /bin/sh -c), collecting what it
// writes to its standard output; the command line redirects stderr where a test wants it.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace candela::test {

struct CommandResult {
    int exit_code;       // -1 when it did not exit normally (a signal)
    std::string output;  // its standard output
};

inline CommandResult run_command(const std::string& command_line) {
    FILE* pipe = popen(command_line.c_str(), "r");
    if (pipe == nullptr) return {-1, "popen failed: " + command_line};
    std::string out;
    std::array<char, 4096> buf;
    while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace candela::test
