#pragma once
// Driving a real X11 program from a test (POSIX only): child processes that end with their
// owner, a private Xvfb server on a display number it picks itself (-displayfd), and xdotool
// commands run against that display. Used by editor_e2e_test.cpp.
#include <sys/types.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pt::test {

// The full path of `program` on $PATH; "" when it is not there.
std::string findOnPath(const std::string& program);

// A process started with posix_spawn. Its stdout and stderr are appended to `logPath` (or
// discarded when empty); `env` holds NAME=VALUE entries that replace or extend the test's own
// environment; `fd3`, when not -1, becomes the child's descriptor 3. The destructor ends a
// process still running (SIGTERM, SIGKILL after 3 s) and reaps it, so no test leaves one behind.
class ChildProcess {
public:
    ChildProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                 const std::string& logPath, int fd3 = -1);
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    bool running();
    pid_t pid() const { return pid_; }
    // The exit status once the process ended within `seconds` (128 + N after signal N), else none.
    std::optional<int> waitForExit(double seconds);
    void stop();

private:
    pid_t pid_ = -1;
    std::optional<int> status_;
};

struct CommandResult {
    int status = -1;     // exit status; -1 when it ran past its time limit and was killed
    std::string output;  // stdout and stderr together
};

// Runs a command to completion (at most `timeoutSeconds`), capturing its output.
CommandResult runCommand(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                         double timeoutSeconds);

// A private X server (Xvfb, one screen of `screen`, WxHxDEPTH). start() returns it once it
// accepts connections, or nullptr with `error` set; the destructor ends the server.
class X11Session {
public:
    static std::unique_ptr<X11Session> start(const std::string& logPath, double timeoutSeconds,
                                             std::string& error, const std::string& screen = "1280x1024x24");

    const std::string& display() const { return display_; }  // ":N"
    std::string displayEnv() const { return "DISPLAY=" + display_; }
    // xdotool with these arguments on this display (10 s limit).
    CommandResult xdotool(const std::vector<std::string>& args) const;

private:
    X11Session(std::unique_ptr<ChildProcess> server, std::string display)
        : server_(std::move(server)), display_(std::move(display)) {}

    std::unique_ptr<ChildProcess> server_;
    std::string display_;
};

}  // namespace pt::test
