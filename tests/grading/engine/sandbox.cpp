// Running a program under limits: its own process group, rlimits on processor time (the
// budget), address space, file size, core files and (for tests) process count, a wall-clock
// backstop that kills the whole group, stdin from /dev/null, stdout and stderr into a file;
// the processor time it used, measured by the kernel. Linux (Debian 12).
#include <dirent.h>
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
#include <memory>
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
const char* const bwrap = "/usr/bin/bwrap";

// What every sandbox has: new namespaces of every kind, no capabilities, its own session, dies
// with the harness; /usr read-only (with the usual links to it), its own /proc and /dev.
std::vector<std::string> bwrap_base() {
    return {bwrap,    "--unshare-all", "--die-with-parent", "--new-session", "--cap-drop", "ALL",       "--ro-bind",
            "/usr",   "/usr",          "--symlink",         "usr/lib",       "/lib",       "--symlink", "usr/lib64",
            "/lib64", "--symlink",     "usr/bin",           "/bin",          "--proc",     "/proc",     "--dev",
            "/dev"};
}

// The student's process: besides the base, an empty size-limited /work as its working folder
// and a copy of its binary, from file descriptor `binary_fd` (opened before the harness gave up
// root, so that no path needs to be reachable by the sandbox's user). The output limit is set
// inside, by the binary itself (remote/serve.cpp), because bubblewrap's copy of the binary must
// not count against it.
std::vector<std::string> bwrap_test(const std::string& name, long tmp_bytes, int binary_fd) {
    std::vector<std::string> a = bwrap_base();
    // --as-pid-1: the student's process is its PID namespace's first and only process. With
    // bubblewrap's own reaper as PID 1 (same user, no filter), a student's thread could attach
    // to it and make it start a program unfiltered (issue 42). A PID 1 ignores signals it has no
    // handler for; the student's side handles the fatal ones itself (remote/serve.cpp, harden).
    a.insert(a.end(), {"--as-pid-1", "--size", std::to_string(tmp_bytes), "--tmpfs", "/work", "--chdir", "/work",
                       "--perms", "0555", "--ro-bind-data", std::to_string(binary_fd), "/run/test/" + name});
    // Nothing else it can fill: bubblewrap's /, /dev and /dev/shm are tmpfs of half the
    // machine's memory, writable, outside the address-space limit (issue 42). /dev/shm gets the
    // size of /work, and / and /dev are made read-only (a device such as /dev/null still takes
    // writes); memfd_create is refused by the filter.
    a.insert(a.end(),
             {"--size", std::to_string(tmp_bytes), "--tmpfs", "/dev/shm", "--remount-ro", "/dev", "--remount-ro", "/"});
    return a;
}

// The student's compile and link: besides the base, an empty /tmp and the folders the harness
// binds (the API headers, the link inputs, the submission's own folder: Limits::binds).
std::vector<std::string> bwrap_build(const Limits& limits) {
    std::vector<std::string> a = bwrap_base();
    a.insert(a.end(), {"--tmpfs", "/tmp"});
    for (const auto& b : limits.binds) a.insert(a.end(), {b.writable ? "--bind" : "--ro-bind", b.source, b.target});
    if (!limits.binds.empty()) a.insert(a.end(), {"--chdir", limits.binds.back().target});
    return a;
}

}  // namespace

Isolation isolation() { return mode; }

// The users sandboxed programs run as when the harness is root: users of their own, which own no
// file. A build's is the harness process's (it owns the job folder); a student's process has one
// from its own process ID, so that the process limit counts its threads alone, and never a
// previous test's processes that the kernel has not yet taken down.
unsigned sandbox_uid() { return 1000000000u + static_cast<unsigned>(getpid()); }
namespace {
unsigned test_uid(pid_t child) { return 2000000000u + static_cast<unsigned>(child); }
}  // namespace

namespace {
constexpr int max_groups = 4;
volatile std::sig_atomic_t running_groups[max_groups] = {0, 0, 0, 0};  // the groups run_limited waits for
void stop_and_exit(int) {
    for (int k = 0; k < max_groups; ++k)
        if (running_groups[k] > 0) kill(-static_cast<pid_t>(running_groups[k]), SIGKILL);
    _exit(1);
}
void remember_group(pid_t pid, bool add) {
    for (int k = 0; k < max_groups; ++k) {
        if (add && running_groups[k] == 0) {
            running_groups[k] = pid;
            return;
        }
        if (!add && running_groups[k] == pid) {
            running_groups[k] = 0;
            return;
        }
    }
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
    const bool root = geteuid() == 0;
    if (allowed && access(bwrap, X_OK) == 0) {
        mode = Isolation::namespaces;
        char dir[] = "/tmp/workbook-probe-XXXXXX";
        if (mkdtemp(dir)) {
            Limits probe;
            probe.cpu_seconds = 20, probe.wall_seconds = 120;
            probe.sandbox = Sandbox::build;
            const std::string out = std::string(dir) + "/out.txt";
            const Outcome o = run_limited({"/bin/true"}, dir, out, probe);
            const std::string said = trim(read_file(out));
            remove_tree(dir);
            if (o.started && !o.timed_out && o.signal == 0 && o.exit_code == 0)
                return std::string("sandbox: bubblewrap namespaces") + (root ? ", as a user of its own" : "");
            mode = root ? Isolation::user : Isolation::limits_only;
            return "sandbox: bubblewrap does not work here (" +
                   (said.empty() ? "exit " + std::to_string(o.exit_code) : said) + "); " +
                   (root ? "students' code runs as a user of its own, with the limits" : "no sandbox");
        }
    }
    if (root) mode = Isolation::user;
    return std::string(allowed ? "sandbox: no bubblewrap (apt-get install bubblewrap)"
                               : "sandbox: bubblewrap not used (WORKBOOK_GRADE_NO_BWRAP)") +
           "; " + (root ? "students' code runs as a user of its own, with the limits" : "no sandbox");
}

namespace {

// What the child needs, all prepared before fork (after it, only async-signal-safe calls).
struct Launch {
    bool namespaces = false, own_user = false;
    uid_t uid = 0;
    std::vector<std::string> command, environment;
    std::vector<char*> args, env;
    std::vector<int> keep;  // the descriptors the program gets as 3, 4, ...
    int program = -1;       // the test binary, for bubblewrap to copy (namespaces) or for fexecve
    rlim_t cpu = 0, memory = 0, output = 0, processes = 0;
    ~Launch() {
        if (program >= 0) close(program);
    }
};

// The command (bubblewrap's, or the program's own), its environment and limits. The binary is
// opened here, before the child gives up root: neither bubblewrap nor fexecve then needs a
// path that the sandbox's user could follow. Returns an empty string or why it cannot start.
std::string prepare_launch(const std::vector<std::string>& argv, const std::string& cwd, const Limits& limits,
                           const std::vector<int>& pass, Launch& l) {
    const bool sandboxed = limits.sandbox != Sandbox::none;
    l.namespaces = sandboxed && mode == Isolation::namespaces;
    l.own_user = sandboxed && geteuid() == 0;
    l.uid = sandbox_uid();
    l.keep = pass;
    const bool test = limits.sandbox == Sandbox::test;
    if (test && (l.namespaces || l.own_user)) {
        l.program = open(argv[0].c_str(), O_RDONLY | O_CLOEXEC);
        if (l.program < 0) return "cannot open " + argv[0] + ": " + std::strerror(errno);
    }
    l.output = static_cast<rlim_t>(limits.output_bytes);
    const int binary_fd = 3 + static_cast<int>(pass.size());
    if (l.namespaces && test) {
        const std::string name = argv[0].substr(argv[0].rfind('/') + 1);
        l.command = bwrap_test(name, std::max<long>(limits.output_bytes * 4, 8L << 20), binary_fd);
        l.command.push_back("/run/test/" + name);
        l.command.insert(l.command.end(), argv.begin() + 1, argv.end());
        // Outside, the limit must let bubblewrap write the binary; inside, the binary sets the real one.
        struct stat st {};
        if (fstat(l.program, &st) == 0) l.output = std::max(l.output, static_cast<rlim_t>(st.st_size) + (64 << 10));
    } else if (l.namespaces) {
        l.command = bwrap_build(limits);
        l.command.insert(l.command.end(), argv.begin(), argv.end());
    } else {
        l.command = argv;
    }
    for (const auto& a : l.command) l.args.push_back(const_cast<char*>(a.c_str()));
    l.args.push_back(nullptr);
    // A sandboxed program gets the system's PATH, not the harness's (root's home folders, an
    // instructor's own tools: issue 42); the trusted ones (the judge) keep the harness's.
    const char* path = sandboxed ? nullptr : std::getenv("PATH");
    const std::string home = l.namespaces ? (test ? "/work" : "/tmp") : cwd;
    l.environment = {std::string("PATH=") + (path ? path : "/usr/local/bin:/usr/bin:/bin"), "LC_ALL=C", "LANG=C",
                     "HOME=" + home, "TMPDIR=" + home};
    if (test) l.environment.push_back("WORKBOOK_OUTPUT_LIMIT=" + std::to_string(limits.output_bytes));
    l.environment.insert(l.environment.end(), limits.environment.begin(), limits.environment.end());
    for (auto& e : l.environment) l.env.push_back(e.data());
    l.env.push_back(nullptr);
    l.cpu = static_cast<rlim_t>(std::max(1.0, std::ceil(limits.cpu_seconds)));
    l.memory = static_cast<rlim_t>(limits.memory_mb) << 20;
    // Threads count as processes. With a user of its own, the limit counts this program alone:
    // its main thread, the threads it may start, and bubblewrap's two processes.
    if (test && l.own_user) l.processes = static_cast<rlim_t>(1 + limits.threads + (l.namespaces ? 2 : 0));
    return {};
}

// The pipes: `exec` reports a failed exec (it closes on a successful one); `channel`, with a
// report, becomes the child's descriptor after the passed ones.
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

// Moves the descriptors the child keeps above fd 100, then into place: 0 from /dev/null, 1 and
// 2 into the output, 3, 4, ... the passed ones, then the report, then the binary for bubblewrap;
// closes every other one but the binary (for fexecve). Returns the descriptor that reports a
// failed exec.
int arrange_descriptors(const Launch& l, Pipes& p, bool with_report, int in, int out, int& program_copy) {
    const int exec_report = fcntl(p.exec[1], F_DUPFD_CLOEXEC, 100);
    std::vector<int> wanted;  // in the order of their final numbers 3, 4, ...
    for (const int fd : l.keep) wanted.push_back(fcntl(fd, F_DUPFD_CLOEXEC, 100));
    if (with_report) wanted.push_back(fcntl(p.channel[1], F_DUPFD_CLOEXEC, 100));
    program_copy = l.program >= 0 ? fcntl(l.program, F_DUPFD_CLOEXEC, 100) : -1;
    if (l.namespaces && program_copy >= 0) wanted.push_back(program_copy);  // bubblewrap reads it, then closes it
    dup2(in, 0);
    dup2(out, 1);
    dup2(out, 2);
    int next = 3;
    for (const int fd : wanted) dup2(fd, next++);  // without O_CLOEXEC: the program keeps them
    for (int fd = next; fd < 1024; ++fd)
        if (fd != exec_report && !(fd == program_copy && !l.namespaces)) close(fd);
    return exec_report;
}

// The child: its own process group, dies with the harness, descriptors in place, default
// signals, the limits, then the program (as the sandbox's own user when the harness is root).
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
    const bool test = limits.sandbox == Sandbox::test;
    const uid_t uid = test ? test_uid(getpid()) : l.uid;
    if (l.own_user && test && !l.namespaces && chown(cwd.c_str(), uid, uid) != 0) exec_failed(report);
    if (l.own_user && (setgroups(0, nullptr) != 0 || setgid(uid) != 0 || setuid(uid) != 0)) exec_failed(report);
    if (l.processes > 0) set_limit(RLIMIT_NPROC, l.processes, l.processes);
    if (test) set_limit(RLIMIT_NOFILE, 64, 64);  // its descriptors and a few dozen of its own, not 1,536 memfds
    if (limits.forbid_processes && limits.sandbox == Sandbox::none) set_limit(RLIMIT_NPROC, 0, 0);
    if (l.own_user && !l.namespaces && program_copy >= 0)
        fexecve(program_copy, l.args.data(), l.env.data());
    else
        execve(l.args[0], l.args.data(), l.env.data());
    exec_failed(report);
}

// What the program writes to its report descriptor, kept up to `limit` bytes.
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

// The processor time of a process and of every process below it, from /proc (their own time
// and that of the children they have waited for), in seconds: what a process tree killed at the
// backstop had used, since the kernel does not count a killed subtree's time towards the
// harness. Processes of other users are readable in /proc/<pid>/stat as well.
double tree_cpu_seconds(pid_t root) {
    std::vector<std::pair<pid_t, pid_t>> parent;  // (pid, parent's pid)
    std::vector<std::pair<pid_t, double>> ticks;
    DIR* proc = opendir("/proc");
    if (!proc) return 0;
    while (const dirent* e = readdir(proc)) {
        char* end = nullptr;
        const long pid = std::strtol(e->d_name, &end, 10);
        if (pid <= 0 || *end) continue;
        char path[64], text[1024];
        std::snprintf(path, sizeof path, "/proc/%ld/stat", pid);
        const int fd = open(path, O_RDONLY | O_CLOEXEC);
        if (fd < 0) continue;
        const ssize_t n = read(fd, text, sizeof text - 1);
        close(fd);
        if (n <= 0) continue;
        text[n] = 0;
        const char* close_paren = std::strrchr(text, ')');  // the name may hold spaces and parentheses
        if (!close_paren) continue;
        // After the name: state ppid pgrp session tty tpgid flags minflt cminflt majflt cmajflt
        // utime stime cutime cstime (fields 3 to 17 of proc(5)).
        char state = 0;
        long ppid = 0, skip = 0;
        unsigned long long ut = 0, st = 0;
        long long cut = 0, cst = 0;
        if (std::sscanf(close_paren + 1, " %c %ld %ld %ld %ld %ld %ld %ld %ld %ld %ld %llu %llu %lld %lld", &state,
                        &ppid, &skip, &skip, &skip, &skip, &skip, &skip, &skip, &skip, &skip, &ut, &st, &cut,
                        &cst) != 15)
            continue;
        parent.emplace_back(static_cast<pid_t>(pid), static_cast<pid_t>(ppid));
        ticks.emplace_back(static_cast<pid_t>(pid), static_cast<double>(ut + st) + static_cast<double>(cut + cst));
    }
    closedir(proc);
    std::vector<pid_t> tree = {root};
    for (std::size_t k = 0; k < tree.size(); ++k)
        for (const auto& [pid, ppid] : parent)
            if (ppid == tree[k] && std::find(tree.begin(), tree.end(), pid) == tree.end()) tree.push_back(pid);
    double sum = 0;
    for (const auto& [pid, t] : ticks)
        if (std::find(tree.begin(), tree.end(), pid) != tree.end()) sum += t;
    return sum / static_cast<double>(sysconf(_SC_CLK_TCK));
}

double seconds_of(const rusage& u) {
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Waits for the child until `deadline` (then kills its group), reading its report meanwhile.
// Returns its wait status; sets *timed_out, and *cpu to the processor time it used.
template <class Deadline>
int wait_until(pid_t pid, Deadline deadline, const ReportReader& report, bool* timed_out, double* cpu) {
    int status = 0;
    rusage used{};
    auto pause = std::chrono::microseconds(200);
    for (;;) {
        const pid_t done = wait4(pid, &status, WNOHANG, &used);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) break;
        if (std::chrono::steady_clock::now() >= deadline) {
            *timed_out = true;
            const double before = tree_cpu_seconds(pid);
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);
            while (wait4(pid, &status, 0, &used) < 0 && errno == EINTR) {
            }
            *cpu = std::max(before, seconds_of(used));
            return status;
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
    *cpu = seconds_of(used);
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

struct Started::Impl {
    Launch launch;
    Pipes pipes;
    pid_t pid = -1;
    std::chrono::steady_clock::time_point start;
    double wall_seconds = 0;
    bool with_report = false;
    ReportReader report;
    int exec_errno = 0;
    bool exec_failed = false;
};

Started::Started() : impl(std::make_unique<Impl>()) {}
Started::~Started() {
    if (impl && impl->pid > 0) wait_limited(*this, 0);  // still running: stopped now
}
Started::Started(Started&&) noexcept = default;
Started& Started::operator=(Started&&) noexcept = default;

Started start_limited(const std::vector<std::string>& argv, const std::string& cwd, const std::string& output_path,
                      const Limits& limits, const std::vector<int>& pass_fds, std::string* report_text,
                      std::size_t report_limit, bool* report_overflow) {
    Started s;
    Started::Impl& r = *s.impl;
    if (report_overflow) *report_overflow = false;
    if (report_text) report_text->clear();
    r.with_report = report_text != nullptr;
    r.wall_seconds = limits.wall_seconds;
    s.outcome.error = prepare_launch(argv, cwd, limits, pass_fds, r.launch);
    if (s.outcome.error.empty()) s.outcome.error = open_pipes(r.with_report, r.pipes);
    if (!s.outcome.error.empty()) return s;
    const pid_t parent = getpid();
    r.start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        s.outcome.error = std::string("fork: ") + std::strerror(errno);
        for (const int fd : {r.pipes.exec[0], r.pipes.exec[1], r.pipes.channel[0], r.pipes.channel[1]})
            if (fd >= 0) close(fd);
        return s;
    }
    if (pid == 0) run_child(r.launch, r.pipes, r.with_report, parent, cwd, output_path, limits);
    setpgid(pid, pid);
    r.pid = pid;
    remember_group(pid, true);
    close(r.pipes.exec[1]);
    if (r.launch.program >= 0) close(r.launch.program), r.launch.program = -1;
    r.report = ReportReader{r.pipes.channel[0], report_text, report_limit, report_overflow};
    if (r.with_report) {
        close(r.pipes.channel[1]);
        fcntl(r.pipes.channel[0], F_SETFL, O_NONBLOCK);
    }
    r.exec_failed = read(r.pipes.exec[0], &r.exec_errno, sizeof r.exec_errno) == sizeof r.exec_errno;
    close(r.pipes.exec[0]);
    return s;
}

Outcome wait_limited(Started& s, double grace_seconds) {
    Started::Impl& r = *s.impl;
    if (r.pid <= 0) return s.outcome;
    auto deadline = r.start + std::chrono::duration<double>(r.wall_seconds);
    if (grace_seconds >= 0)
        deadline = std::min(deadline, std::chrono::steady_clock::now() + std::chrono::duration<double>(grace_seconds));
    bool stopped = false;
    double cpu = 0;
    const int status = wait_until(r.pid, deadline, r.report, &stopped, &cpu);
    // Stopped at its own deadline, it timed out; at the end of its grace, it was only stopped.
    const bool own_deadline =
        std::chrono::steady_clock::now() >= r.start + std::chrono::duration<double>(r.wall_seconds);
    s.outcome.timed_out = stopped && own_deadline;
    s.outcome.stopped = stopped && !own_deadline;
    kill(-r.pid, SIGKILL);  // anything it left behind in its group
    remember_group(r.pid, false);
    if (r.with_report) {
        r.report.drain();
        close(r.pipes.channel[0]);
    }
    s.outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count();
    s.outcome.cpu_seconds = cpu;
    r.pid = -1;
    if (r.exec_failed) {
        s.outcome.error = "cannot run " + r.launch.command[0] + ": " + std::strerror(r.exec_errno);
        return s.outcome;
    }
    record_end(status, r.launch.namespaces, s.outcome);
    // Past its processor time: SIGXCPU at the budget, or SIGKILL a second later if it ignored that.
    s.outcome.out_of_cpu = s.outcome.signal == SIGXCPU ||
                           (s.outcome.signal == SIGKILL && !stopped && cpu >= static_cast<double>(r.launch.cpu));
    return s.outcome;
}

Outcome run_limited(const std::vector<std::string>& argv, const std::string& cwd, const std::string& output_path,
                    const Limits& limits, std::string* report_text, std::size_t report_limit, bool* report_overflow,
                    const std::vector<int>& pass_fds) {
    Started s = start_limited(argv, cwd, output_path, limits, pass_fds, report_text, report_limit, report_overflow);
    return wait_limited(s);
}

}  // namespace grading
