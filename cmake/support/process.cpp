#include "support/process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

extern char** environ;

namespace support {

namespace {

using Clock = std::chrono::steady_clock;

int decode(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

// Where one of the program's streams goes: a file, the other stream, a pipe to capture it, or
// /dev/null. The pipe's ends are close-on-exec; dup2 gives the program its own copy.
struct Stream {
    int fd = 1;
    int pipe[2] = {-1, -1};
};

class Actions {
public:
    Actions() { posix_spawn_file_actions_init(&actions_); }
    ~Actions() { posix_spawn_file_actions_destroy(&actions_); }
    Actions(const Actions&) = delete;
    Actions& operator=(const Actions&) = delete;
    posix_spawn_file_actions_t* get() { return &actions_; }

    int to_file(int fd, const std::string& path) {
        return posix_spawn_file_actions_addopen(&actions_, fd, path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    }
    int to_null(int fd, int flags) { return posix_spawn_file_actions_addopen(&actions_, fd, "/dev/null", flags, 0); }
    int to_fd(int fd, int from) { return posix_spawn_file_actions_adddup2(&actions_, from, fd); }

private:
    posix_spawn_file_actions_t actions_;
};

void close_pipe(Stream& s) {
    for (int& end : s.pipe)
        if (end >= 0) close(end), end = -1;
}

// Sets up one stream: to a file, to a pipe when captured, else to /dev/null. 0 or an errno.
int route(Actions& actions, Stream& s, const std::string& file, bool capture) {
    if (!file.empty()) return actions.to_file(s.fd, file);
    if (!capture) return actions.to_null(s.fd, O_WRONLY);
    if (pipe2(s.pipe, O_CLOEXEC) != 0) return errno;
    return actions.to_fd(s.fd, s.pipe[1]);
}

pid_t start(const std::vector<std::string>& argv, const RunOptions& options, bool capture, Stream& out, Stream& err,
            std::string& error) {
    if (argv.empty()) return error = "no program to run", -1;
    Actions actions;
    err.fd = 2;
    int rc = actions.to_null(0, O_RDONLY);
    if (rc == 0) rc = route(actions, out, options.stdout_file, capture);
    if (rc == 0)
        rc = options.stderr_to_stdout ? actions.to_fd(2, 1) : route(actions, err, options.stderr_file, capture);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = -1;
    if (rc == 0) rc = posix_spawnp(&pid, args[0], actions.get(), nullptr, args.data(), environ);
    if (out.pipe[1] >= 0) close(out.pipe[1]), out.pipe[1] = -1;
    if (err.pipe[1] >= 0) close(err.pipe[1]), err.pipe[1] = -1;
    if (rc != 0) {
        close_pipe(out), close_pipe(err);
        error = "cannot run " + argv[0] + ": " + std::strerror(rc);
        return -1;
    }
    return pid;
}

// Reads both pipes until they close or the deadline passes. False at the deadline.
bool drain(Stream& out, Stream& err, std::string& out_text, std::string& err_text, bool limited,
           Clock::time_point deadline) {
    char buffer[65536];
    while (out.pipe[0] >= 0 || err.pipe[0] >= 0) {
        pollfd fds[2] = {{out.pipe[0], POLLIN, 0}, {err.pipe[0], POLLIN, 0}};
        int wait_ms = -1;
        if (limited) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
            if (left <= 0) return false;
            wait_ms = static_cast<int>(left);
        }
        if (poll(fds, 2, wait_ms) < 0 && errno != EINTR) break;
        Stream* streams[2] = {&out, &err};
        std::string* texts[2] = {&out_text, &err_text};
        for (int k = 0; k < 2; ++k) {
            if (streams[k]->pipe[0] < 0 || !(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            const ssize_t n = read(streams[k]->pipe[0], buffer, sizeof buffer);
            if (n > 0)
                texts[k]->append(buffer, static_cast<std::size_t>(n));
            else if (n == 0 || errno != EINTR)
                close(streams[k]->pipe[0]), streams[k]->pipe[0] = -1;
        }
    }
    return true;
}

int reap(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return decode(status);
}

}  // namespace

Result run(const std::vector<std::string>& argv, const RunOptions& options) {
    Result r;
    Stream out, err;
    const pid_t pid = start(argv, options, true, out, err, r.error);
    if (pid < 0) return r;
    const bool limited = options.timeout > 0;
    const auto deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout));
    bool in_time = drain(out, err, r.out, r.err, limited, deadline);
    close_pipe(out), close_pipe(err);
    // Its streams closed, it may still run: its deadline holds until it ends.
    if (in_time && limited) {
        const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
        r.status = wait(pid, left > 0 ? left : 0);
        in_time = r.status != -1;
    }
    if (!in_time) kill(pid, SIGKILL), r.timed_out = true;
    if (!limited || !in_time) r.status = reap(pid);
    return r;
}

pid_t spawn(const std::vector<std::string>& argv, const RunOptions& options, std::string* error) {
    Stream out, err;
    std::string why;
    const pid_t pid = start(argv, options, false, out, err, why);
    if (error) *error = why;
    return pid;
}

int wait(pid_t pid, double seconds) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    for (;;) {
        int status = 0;
        const pid_t got = waitpid(pid, &status, WNOHANG);
        if (got == pid) return decode(status);
        if (got < 0 && errno != EINTR) return -1;
        if (Clock::now() >= end) return -1;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

}  // namespace support
