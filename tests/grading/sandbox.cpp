// Running a program under limits: its own process group, a wall-clock deadline that kills the
// whole group, rlimits on address space, CPU, file size, core files and (for tests) process
// count, stdin from /dev/null, stdout and stderr into a file. Linux (Debian 12).
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "grading.hpp"

namespace grading {

namespace {

void set_limit(int resource, rlim_t soft, rlim_t hard) {
    rlimit current;
    if (getrlimit(resource, &current) == 0) {
        // Never ask for more than the hard limit we were given.
        if (current.rlim_max != RLIM_INFINITY) {
            hard = std::min(hard, current.rlim_max);
            soft = std::min(soft, hard);
        }
    }
    const rlimit wanted{soft, hard};
    setrlimit(resource, &wanted);
}

}  // namespace

std::string signal_name(int signal) {
    switch (signal) {
        case SIGSEGV:
            return "SIGSEGV";
        case SIGABRT:
            return "SIGABRT";
        case SIGFPE:
            return "SIGFPE";
        case SIGILL:
            return "SIGILL";
        case SIGBUS:
            return "SIGBUS";
        case SIGKILL:
            return "SIGKILL";
        case SIGTERM:
            return "SIGTERM";
        case SIGXCPU:
            return "SIGXCPU";
        case SIGXFSZ:
            return "SIGXFSZ";
        case SIGPIPE:
            return "SIGPIPE";
        case SIGTRAP:
            return "SIGTRAP";
        case SIGSYS:
            return "SIGSYS";
        case SIGINT:
            return "SIGINT";
        case SIGHUP:
            return "SIGHUP";
        case SIGALRM:
            return "SIGALRM";
        case SIGUSR1:
            return "SIGUSR1";
        case SIGUSR2:
            return "SIGUSR2";
        default:
            return "signal " + std::to_string(signal);
    }
}

namespace {

Isolation mode = Isolation::limits_only;
constexpr uid_t nobody = 65534;
const char* const bwrap = "/usr/bin/bwrap";
const char* const prlimit = "/usr/bin/prlimit";

// Everything the sandboxed program sees, after the bubblewrap path. The output limit is set
// inside, by prlimit: bubblewrap writes the test binary into the sandbox (--ro-bind-data), and
// that write must not count against what the test may write (a binary over the limit would
// otherwise fail every test with "File too large").
std::vector<std::string> bwrap_arguments(const std::string& name, long tmp_bytes, long output_bytes) {
    std::vector<std::string> a = {bwrap,
                                  "--unshare-all",
                                  "--die-with-parent",
                                  "--new-session",
                                  "--cap-drop",
                                  "ALL",
                                  "--ro-bind",
                                  "/usr",
                                  "/usr",
                                  "--symlink",
                                  "usr/lib",
                                  "/lib",
                                  "--symlink",
                                  "usr/lib64",
                                  "/lib64",
                                  "--symlink",
                                  "usr/bin",
                                  "/bin",
                                  "--proc",
                                  "/proc",
                                  "--dev",
                                  "/dev",
                                  "--size",
                                  std::to_string(tmp_bytes),
                                  "--tmpfs",
                                  "/work",
                                  "--chdir",
                                  "/work",
                                  "--perms",
                                  "0555",
                                  "--ro-bind-data",
                                  "4",
                                  "/run/test/" + name};
    if (access(prlimit, X_OK) == 0) {
        const std::string fsize = std::to_string(output_bytes);
        a.insert(a.end(), {prlimit, "--nproc=0:0", "--core=0:0", "--fsize=" + fsize + ":" + fsize});
    }
    return a;
}

bool drop_to_nobody() {
    if (geteuid() != 0) return true;
    return setgroups(0, nullptr) == 0 && setgid(nobody) == 0 && setuid(nobody) == 0;
}

}  // namespace

Isolation isolation() { return mode; }

namespace {
volatile std::sig_atomic_t running_group = 0;  // the process group of the program run_limited waits for
void stop_and_exit(int) {
    const pid_t group = running_group;
    if (group > 0) kill(-group, SIGKILL);
    _exit(1);
}
}  // namespace

void stop_children_on_signal() {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction action {};
        action.sa_handler = stop_and_exit;
        sigemptyset(&action.sa_mask);
        sigaction(sig, &action, nullptr);
    }
}

std::string configure_sandbox() {
    mode = Isolation::limits_only;
    // WORKBOOK_GRADE_NO_BWRAP=1 tries the fallback where bubblewrap exists.
    const bool allowed = !std::getenv("WORKBOOK_GRADE_NO_BWRAP");
    if (allowed && access(bwrap, X_OK) == 0) {
        mode = Isolation::namespaces;
        char dir[] = "/tmp/workbook-probe-XXXXXX";
        if (mkdtemp(dir)) {
            Limits probe;
            probe.wall_seconds = 20;
            probe.isolate = true;
            const std::string out = std::string(dir) + "/out.txt";
            const Outcome o = run_limited({"/bin/true"}, dir, out, probe);
            const std::string said = trim(read_file(out));
            remove_tree(dir);
            if (o.started && !o.timed_out && o.signal == 0 && o.exit_code == 0)
                return std::string("sandbox: bubblewrap namespaces") + (geteuid() == 0 ? ", as the user nobody" : "");
            mode = Isolation::limits_only;
            if (geteuid() == 0) mode = Isolation::user;
            return "sandbox: bubblewrap does not work here (" +
                   (said.empty() ? "exit " + std::to_string(o.exit_code) : said) + "); tests run " +
                   (geteuid() == 0 ? "as the user nobody, " : "") + "with the limits alone";
        }
    }
    if (geteuid() == 0) mode = Isolation::user;
    return std::string(allowed ? "sandbox: no bubblewrap (apt-get install bubblewrap)"
                               : "sandbox: bubblewrap not used (WORKBOOK_GRADE_NO_BWRAP)") +
           "; tests run " + std::string(geteuid() == 0 ? "as the user nobody, " : "") + "with the limits alone";
}

namespace {

// What the child needs, all prepared before fork (after it, only async-signal-safe calls).
struct Launch {
    bool namespaces = false, as_nobody = false;
    std::vector<std::string> command, environment;
    std::vector<char*> args, env;
    int program = -1;  // the test binary, copied into the sandbox by bubblewrap from fd 4
    rlim_t cpu = 0, memory = 0, output = 0;
    ~Launch() {
        if (program >= 0) close(program);
    }
};

// The command (bubblewrap's, or the program's own), its environment and limits. The binary is
// opened here, before the child gives up root: neither bubblewrap nor fexecve then needs a
// path that the user nobody could follow. Returns an empty string or why it cannot start.
std::string prepare_launch(const std::vector<std::string>& argv, const std::string& cwd, const Limits& limits,
                           Launch& l) {
    l.namespaces = limits.isolate && mode == Isolation::namespaces;
    l.as_nobody = limits.isolate && mode != Isolation::limits_only && geteuid() == 0;
    if (l.namespaces || l.as_nobody) {
        l.program = open(argv[0].c_str(), O_RDONLY | O_CLOEXEC);
        if (l.program < 0) return "cannot open " + argv[0] + ": " + std::strerror(errno);
    }
    l.output = static_cast<rlim_t>(limits.output_bytes);
    if (l.namespaces) {
        const std::string name = argv[0].substr(argv[0].rfind('/') + 1);
        l.command = bwrap_arguments(name, std::max<long>(limits.output_bytes * 4, 8L << 20), limits.output_bytes);
        l.command.push_back("/run/test/" + name);
        l.command.insert(l.command.end(), argv.begin() + 1, argv.end());
        // Outside, the limit must let bubblewrap write the binary; inside, prlimit sets the real one.
        struct stat st {};
        if (fstat(l.program, &st) == 0) l.output = std::max(l.output, static_cast<rlim_t>(st.st_size) + (64 << 10));
    } else {
        l.command = argv;
    }
    for (const auto& a : l.command) l.args.push_back(const_cast<char*>(a.c_str()));
    l.args.push_back(nullptr);
    const char* path = std::getenv("PATH");
    const std::string home = l.namespaces ? "/work" : cwd;
    l.environment = {std::string("PATH=") + (path ? path : "/usr/local/bin:/usr/bin:/bin"), "LC_ALL=C", "LANG=C",
                     "HOME=" + home, "TMPDIR=" + home};
    l.environment.insert(l.environment.end(), limits.environment.begin(), limits.environment.end());
    for (auto& e : l.environment) l.env.push_back(e.data());
    l.env.push_back(nullptr);
    l.cpu = static_cast<rlim_t>(std::ceil(limits.wall_seconds)) + 1;
    l.memory = static_cast<rlim_t>(limits.memory_mb) << 20;
    return {};
}

// The pipes: `exec` reports a failed exec (it closes on a successful one); `channel`, with a
// report, becomes fd 3 of the child.
struct Pipes {
    int exec[2] = {-1, -1};
    int channel[2] = {-1, -1};
};

std::string open_pipes(bool with_report, Pipes& p) {
    if (pipe2(p.exec, O_CLOEXEC) != 0) return std::string("pipe: ") + std::strerror(errno);
    if (with_report && pipe2(p.channel, O_CLOEXEC) != 0) {
        const std::string why = std::string("pipe: ") + std::strerror(errno);
        close(p.exec[0]);
        close(p.exec[1]);
        return why;
    }
    return {};
}

[[noreturn]] void exec_failed(int fd) {
    const int e = errno;
    (void)!write(fd, &e, sizeof e);
    _exit(127);
}

// Moves the descriptors the child keeps above fd 10, then into place: 0 from /dev/null, 1 and 2
// into the output, 3 the report, 4 the binary for bubblewrap; closes every other one but the
// binary (for fexecve). Returns the descriptor that reports a failed exec.
int arrange_descriptors(const Launch& l, Pipes& p, bool with_report, int in, int out, int& program_copy) {
    const int exec_report = fcntl(p.exec[1], F_DUPFD_CLOEXEC, 10);
    const int report_end = with_report ? fcntl(p.channel[1], F_DUPFD_CLOEXEC, 10) : -1;
    program_copy = l.program >= 0 ? fcntl(l.program, F_DUPFD_CLOEXEC, 10) : -1;
    dup2(in, 0);
    dup2(out, 1);
    dup2(out, 2);
    if (with_report) dup2(report_end, 3);     // without O_CLOEXEC: the program keeps it
    if (l.namespaces) dup2(program_copy, 4);  // bubblewrap reads it, then closes it
    const int first_closed = l.namespaces ? 5 : with_report ? 4 : 3;
    for (int fd = first_closed; fd < 1024; ++fd)
        if (fd != exec_report && !(fd == program_copy && !l.namespaces)) close(fd);
    if (!with_report && l.namespaces) close(3);
    return exec_report;
}

// The child: its own process group, dies with the harness, descriptors in place, default
// signals, the limits, then the program (as nobody when asked).
[[noreturn]] void run_child(const Launch& l, Pipes& p, bool with_report, pid_t parent, const std::string& cwd,
                            const std::string& output_path, const Limits& limits) {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // the harness dies: so does the test
    if (getppid() != parent) _exit(127);
    close(p.exec[0]);
    const int in = open("/dev/null", O_RDONLY);
    const int out = open(output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || (!l.namespaces && chdir(cwd.c_str()) != 0)) exec_failed(p.exec[1]);
    int program_copy = -1;
    const int report = arrange_descriptors(l, p, with_report, in, out, program_copy);
    for (int s = 1; s < NSIG; ++s) signal(s, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    set_limit(RLIMIT_AS, l.memory, l.memory);
    set_limit(RLIMIT_CPU, l.cpu, l.cpu + 1);
    set_limit(RLIMIT_FSIZE, l.output, l.output);
    set_limit(RLIMIT_CORE, 0, 0);
    if (l.as_nobody && !drop_to_nobody()) exec_failed(report);
    // In the namespaces, bubblewrap needs its own processes; the limit is set inside.
    if (limits.forbid_processes && !l.namespaces) set_limit(RLIMIT_NPROC, 0, 0);
    if (l.as_nobody && !l.namespaces)
        fexecve(program_copy, l.args.data(), l.env.data());
    else
        execve(l.args[0], l.args.data(), l.env.data());
    exec_failed(report);
}

// What the program writes to fd 3, kept up to `limit` bytes.
struct ReportReader {
    int fd = -1;
    std::string* text = nullptr;
    std::size_t limit = 0;
    bool* overflow = nullptr;
    void drain() const {
        if (!text) return;
        char buffer[65536];
        ssize_t n;
        while ((n = read(fd, buffer, sizeof buffer)) > 0) {
            if (text->size() + static_cast<std::size_t>(n) <= limit)
                text->append(buffer, static_cast<std::size_t>(n));
            else if (overflow)
                *overflow = true;
        }
    }
};

// Waits for the child until `deadline` (then kills its group), reading its report meanwhile.
// Returns its wait status; sets *timed_out.
template <class Deadline>
int wait_until(pid_t pid, Deadline deadline, const ReportReader& report, bool* timed_out) {
    int status = 0;
    auto pause = std::chrono::microseconds(200);
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) break;
        if (std::chrono::steady_clock::now() >= deadline) {
            *timed_out = true;
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            break;
        }
        if (report.text) {
            pollfd p{report.fd, POLLIN, 0};
            poll(&p, 1, static_cast<int>(std::max<long>(1, pause.count() / 1000)));
            report.drain();
        } else {
            std::this_thread::sleep_for(pause);
        }
        pause = std::min(pause * 2, std::chrono::microseconds(10000));
    }
    return status;
}

// How the program ended, from its wait status. bubblewrap reports a program killed by signal n
// as the exit status 128 + n.
void record_end(int status, bool namespaces, Outcome& outcome) {
    outcome.started = true;
    if (WIFSIGNALED(status))
        outcome.signal = WTERMSIG(status);
    else if (WIFEXITED(status))
        outcome.exit_code = WEXITSTATUS(status);
    if (namespaces && outcome.exit_code > 128 && outcome.exit_code < 128 + NSIG)
        outcome.signal = outcome.exit_code - 128, outcome.exit_code = -1;
}

}  // namespace

Outcome run_limited(const std::vector<std::string>& argv, const std::string& cwd, const std::string& output_path,
                    const Limits& limits, std::string* report_text, std::size_t report_limit, bool* report_overflow) {
    Outcome outcome;
    if (report_overflow) *report_overflow = false;
    if (report_text) report_text->clear();
    Launch launch;
    Pipes pipes;
    outcome.error = prepare_launch(argv, cwd, limits, launch);
    if (outcome.error.empty()) outcome.error = open_pipes(report_text != nullptr, pipes);
    if (!outcome.error.empty()) return outcome;
    const pid_t parent = getpid();
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        outcome.error = std::string("fork: ") + std::strerror(errno);
        for (const int fd : {pipes.exec[0], pipes.exec[1], pipes.channel[0], pipes.channel[1]})
            if (fd >= 0) close(fd);
        return outcome;
    }
    if (pid == 0) run_child(launch, pipes, report_text != nullptr, parent, cwd, output_path, limits);
    setpgid(pid, pid);
    running_group = pid;
    close(pipes.exec[1]);
    if (launch.program >= 0) close(launch.program), launch.program = -1;
    const ReportReader report{pipes.channel[0], report_text, report_limit, report_overflow};
    if (report_text) {
        close(pipes.channel[1]);
        fcntl(pipes.channel[0], F_SETFL, O_NONBLOCK);
    }
    int exec_errno = 0;
    const bool exec_failed = read(pipes.exec[0], &exec_errno, sizeof exec_errno) == sizeof exec_errno;
    close(pipes.exec[0]);
    const int status =
        wait_until(pid, start + std::chrono::duration<double>(limits.wall_seconds), report, &outcome.timed_out);
    kill(-pid, SIGKILL);  // anything it left behind in its group
    running_group = 0;
    if (report_text) {
        report.drain();
        close(pipes.channel[0]);
    }
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (exec_failed) {
        outcome.error = "cannot run " + launch.command[0] + ": " + std::strerror(exec_errno);
        return outcome;
    }
    record_end(status, launch.namespaces, outcome);
    return outcome;
}

}  // namespace grading
