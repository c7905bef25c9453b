#pragma once
// The candela program as a child process the test can signal: started with posix_spawn, its
// stdout and stderr in a log file, waited for with a timeout.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace candela::test {

class ChildProcess {
  public:
    // Starts `program args...` with stdout and stderr appended to `log`.
    ChildProcess(const std::string& program, const std::vector<std::string>& args, const std::filesystem::path& log)
        : log_(log) {
        std::vector<std::string> argv_strings{program};
        argv_strings.insert(argv_strings.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (std::string& a : argv_strings) argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
        int error = posix_spawn(&pid_, program.c_str(), &actions, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        EXPECT_EQ(error, 0) << "cannot start " << program;
        if (error != 0) pid_ = -1;
    }
    ~ChildProcess() {
        if (pid_ > 0 && !exited_) {  // a failed test: do not leave it running
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
    }
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    pid_t pid() const { return pid_; }
    void signal(int sig) const { kill(pid_, sig); }

    // The exit status, waiting at most `timeout_s`; -1 when it did not exit by itself (killed by
    // a signal) or the wait timed out (the process is then killed).
    int wait_exit(double timeout_s) {
        if (pid_ <= 0) return -1;
        const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
        int status = 0;
        while (waitpid(pid_, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() > until) {
                ADD_FAILURE() << "candela did not exit within " << timeout_s << " s";
                return -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    // True when the process is stopped (SIGSTOP), from /proc/PID/stat's state field.
    bool is_stopped() const {
        std::ifstream stat("/proc/" + std::to_string(pid_) + "/stat");
        std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
        size_t paren = text.rfind(')');  // the command name may hold spaces and parentheses
        return paren != std::string::npos && paren + 2 < text.size() && text[paren + 2] == 'T';
    }

    std::string output() const {
        std::ifstream in(log_, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }

  private:
    std::filesystem::path log_;
    pid_t pid_ = -1;
    bool exited_ = false;
};

// Polls `condition` every 5 ms for up to `timeout_s`; true once it holds.
inline bool wait_until(const std::function<bool()>& condition, double timeout_s) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (!condition()) {
        if (std::chrono::steady_clock::now() > until) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
}

}  // namespace candela::test
