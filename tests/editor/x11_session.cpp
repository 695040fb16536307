#include "editor/x11_session.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace pt::test {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The test's environment with `overrides` (NAME=VALUE) replacing entries of the same name.
std::vector<std::string> mergedEnvironment(const std::vector<std::string>& overrides) {
    std::vector<std::string> env;
    for (char** e = environ; e && *e; ++e) {
        const std::string entry = *e;
        const std::string name = entry.substr(0, entry.find('='));
        bool replaced = false;
        for (const std::string& o : overrides) replaced |= o.substr(0, o.find('=')) == name;
        if (!replaced) env.push_back(entry);
    }
    env.insert(env.end(), overrides.begin(), overrides.end());
    return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> p;
    for (std::string& s : strings) p.push_back(s.data());
    p.push_back(nullptr);
    return p;
}

int decodeStatus(int raw) {
    if (WIFEXITED(raw)) return WEXITSTATUS(raw);
    if (WIFSIGNALED(raw)) return 128 + WTERMSIG(raw);
    return -1;
}

// posix_spawnp with the file actions already set up; throws naming the program on failure.
pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env,
            posix_spawn_file_actions_t& actions) {
    if (argv.empty()) throw std::invalid_argument("spawn: empty command line");
    std::vector<std::string> args = argv, environment = mergedEnvironment(env);
    std::vector<char*> argp = pointers(args), envp = pointers(environment);
    pid_t pid = -1;
    const int rc = posix_spawnp(&pid, argp[0], &actions, nullptr, argp.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(rc));
    return pid;
}

}  // namespace

std::string findOnPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::string rest = path ? path : "";
    while (!rest.empty()) {
        const size_t colon = rest.find(':');
        const std::string dir = rest.substr(0, colon);
        rest = colon == std::string::npos ? "" : rest.substr(colon + 1);
        const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
        struct stat st {};
        if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
            ::access(candidate.c_str(), X_OK) == 0) {
            return candidate;
        }
    }
    return "";
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                           const std::string& logPath, int fd3) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    const std::string log = logPath.empty() ? "/dev/null" : logPath;
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    if (fd3 >= 0) posix_spawn_file_actions_adddup2(&actions, fd3, 3);  // clears close-on-exec there
    pid_ = spawn(argv, env, actions);
}

ChildProcess::~ChildProcess() { stop(); }

bool ChildProcess::running() {
    if (pid_ < 0 || status_) return false;
    int raw = 0;
    const pid_t r = ::waitpid(pid_, &raw, WNOHANG);
    if (r == pid_)
        status_ = decodeStatus(raw);
    else if (r < 0)
        status_ = -1;  // not our child any more: nothing left to wait for
    return !status_;
}

std::optional<int> ChildProcess::waitForExit(double seconds) {
    const auto start = Clock::now();
    while (running()) {
        if (secondsSince(start) >= seconds) return std::nullopt;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return status_;
}

void ChildProcess::stop() {
    if (!running()) return;
    ::kill(pid_, SIGTERM);
    if (waitForExit(3.0)) return;
    ::kill(pid_, SIGKILL);
    int raw = 0;
    if (::waitpid(pid_, &raw, 0) == pid_)
        status_ = decodeStatus(raw);
    else
        status_ = -1;
}

CommandResult runCommand(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                         double timeoutSeconds) {
    int out[2];
    if (::pipe2(out, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_adddup2(&actions, out[1], 2);
    pid_t pid = -1;
    try {
        pid = spawn(argv, env, actions);
    } catch (...) {
        ::close(out[0]);
        ::close(out[1]);
        throw;
    }
    ::close(out[1]);
    CommandResult result;
    const auto start = Clock::now();
    bool timedOut = false;
    for (;;) {
        const double left = timeoutSeconds - secondsSince(start);
        if (left <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{out[0], POLLIN, 0};
        if (::poll(&p, 1, int(left * 1000) + 1) <= 0) continue;
        char buffer[4096];
        const ssize_t n = ::read(out[0], buffer, sizeof(buffer));
        if (n <= 0) break;  // end of output: the command (and anything it started) closed it
        result.output.append(buffer, size_t(n));
    }
    ::close(out[0]);
    if (timedOut) ::kill(pid, SIGKILL);
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    result.status = timedOut ? -1 : decodeStatus(raw);
    return result;
}

std::unique_ptr<X11Session> X11Session::start(const std::string& logPath, double timeoutSeconds,
                                              std::string& error, const std::string& screen) {
    // Xvfb picks a free display number itself and writes it to descriptor 3 once it accepts
    // connections (-displayfd), so neither a guessed number nor a polling loop is needed.
    // -noreset: by default an X server resets when its last client disconnects, and a client
    // that connects during that reset is dropped. The tests poll with short-lived xdotool
    // clients while the editor starts, so without it the editor's GLFW now and then could not
    // open the display (once in CI; 10 of 200 xdpyinfo runs beside an xdotool loop here).
    int ready[2];
    if (::pipe2(ready, O_CLOEXEC) != 0) {
        error = std::string("pipe: ") + std::strerror(errno);
        return nullptr;
    }
    // Moved above 3 so that the child's dup2 onto 3 always clears close-on-exec.
    const int writeEnd = ::fcntl(ready[1], F_DUPFD_CLOEXEC, 10);
    ::close(ready[1]);
    std::unique_ptr<ChildProcess> server;
    try {
        server =
            std::make_unique<ChildProcess>(std::vector<std::string>{"Xvfb", "-displayfd", "3", "-screen", "0",
                                                                    screen, "-nolisten", "tcp", "-noreset"},
                                           std::vector<std::string>{}, logPath, writeEnd);
    } catch (const std::exception& e) {
        error = e.what();
    }
    ::close(writeEnd);
    std::string text;
    const auto start = Clock::now();
    while (server && text.find('\n') == std::string::npos && secondsSince(start) < timeoutSeconds) {
        pollfd p{ready[0], POLLIN, 0};
        if (::poll(&p, 1, 100) <= 0) continue;
        char buffer[64];
        const ssize_t n = ::read(ready[0], buffer, sizeof(buffer));
        if (n <= 0) break;  // the server exited without a display
        text.append(buffer, size_t(n));
    }
    ::close(ready[0]);
    if (!server) return nullptr;
    if (text.find('\n') == std::string::npos || text.find_first_not_of("0123456789\n") != std::string::npos) {
        error = "Xvfb did not report a display within " + std::to_string(int(timeoutSeconds)) + " s (see " +
                logPath + ")";
        return nullptr;
    }
    return std::unique_ptr<X11Session>(
        new X11Session(std::move(server), ":" + text.substr(0, text.find('\n'))));
}

CommandResult X11Session::xdotool(const std::vector<std::string>& args) const {
    std::vector<std::string> argv{"xdotool"};
    argv.insert(argv.end(), args.begin(), args.end());
    return runCommand(argv, {displayEnv()}, 10.0);
}

}  // namespace pt::test
