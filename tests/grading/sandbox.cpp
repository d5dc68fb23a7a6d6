// Running a program under limits: its own process group, a wall-clock deadline that kills the
// whole group, rlimits on address space, CPU, file size, core files and (for tests) process
// count, stdin from /dev/null, stdout and stderr into a file. Linux (Debian 12).
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <grp.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <algorithm>
#include <chrono>
#include <cmath>
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
        case SIGSEGV: return "SIGSEGV";
        case SIGABRT: return "SIGABRT";
        case SIGFPE: return "SIGFPE";
        case SIGILL: return "SIGILL";
        case SIGBUS: return "SIGBUS";
        case SIGKILL: return "SIGKILL";
        case SIGTERM: return "SIGTERM";
        case SIGXCPU: return "SIGXCPU";
        case SIGXFSZ: return "SIGXFSZ";
        case SIGPIPE: return "SIGPIPE";
        case SIGTRAP: return "SIGTRAP";
        case SIGSYS: return "SIGSYS";
        case SIGINT: return "SIGINT";
        case SIGHUP: return "SIGHUP";
        case SIGALRM: return "SIGALRM";
        case SIGUSR1: return "SIGUSR1";
        case SIGUSR2: return "SIGUSR2";
        default: return "signal " + std::to_string(signal);
    }
}

namespace {

Isolation mode = Isolation::limits_only;
constexpr uid_t nobody = 65534;
const char* const bwrap = "/usr/bin/bwrap";
const char* const prlimit = "/usr/bin/prlimit";

// Everything the sandboxed program sees, after the bubblewrap path.
std::vector<std::string> bwrap_arguments(const std::string& name, long tmp_bytes) {
    std::vector<std::string> a = {
        bwrap,           "--unshare-all",  "--die-with-parent", "--new-session", "--cap-drop", "ALL",
        "--ro-bind",     "/usr",           "/usr",              "--symlink",     "usr/lib",    "/lib",
        "--symlink",     "usr/lib64",      "/lib64",            "--symlink",     "usr/bin",    "/bin",
        "--proc",        "/proc",          "--dev",             "/dev",          "--size",     std::to_string(tmp_bytes),
        "--tmpfs",       "/work",          "--chdir",           "/work",         "--perms",    "0555",
        "--ro-bind-data", "4",             "/run/test/" + name};
    if (access(prlimit, X_OK) == 0) a.insert(a.end(), {prlimit, "--nproc=0:0", "--core=0:0"});
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
            return "sandbox: bubblewrap does not work here (" + (said.empty() ? "exit " + std::to_string(o.exit_code) : said) +
                   "); tests run " + (geteuid() == 0 ? "as the user nobody, " : "") + "with the limits alone";
        }
    }
    if (geteuid() == 0) mode = Isolation::user;
    return std::string(allowed ? "sandbox: no bubblewrap (apt-get install bubblewrap)" : "sandbox: bubblewrap not used (WORKBOOK_GRADE_NO_BWRAP)") + "; tests run " +
           std::string(geteuid() == 0 ? "as the user nobody, " : "") + "with the limits alone";
}

Outcome run_limited(const std::vector<std::string>& argv, const std::string& cwd,
                    const std::string& output_path, const Limits& limits, std::string* report_text,
                    std::size_t report_limit, bool* report_overflow) {
    Outcome outcome;
    if (report_overflow) *report_overflow = false;
    const bool namespaces = limits.isolate && mode == Isolation::namespaces;
    const bool as_nobody = limits.isolate && mode != Isolation::limits_only && geteuid() == 0;
    // Everything the child needs is prepared before fork.
    std::vector<std::string> command;
    int program = -1;  // the test binary, copied into the sandbox by bubblewrap from fd 4
    if (namespaces) {
        const std::string name = argv[0].substr(argv[0].rfind('/') + 1);
        command = bwrap_arguments(name, std::max<long>(limits.output_bytes * 4, 8L << 20));
        command.push_back("/run/test/" + name);
        command.insert(command.end(), argv.begin() + 1, argv.end());
    } else {
        command = argv;
    }
    // The binary is opened here, before the child gives up root: neither bubblewrap nor fexecve
    // then needs a path that the user nobody could follow.
    if (namespaces || as_nobody) {
        program = open(argv[0].c_str(), O_RDONLY | O_CLOEXEC);
        if (program < 0) {
            outcome.error = "cannot open " + argv[0] + ": " + std::strerror(errno);
            return outcome;
        }
    }
    std::vector<char*> args;
    for (const auto& a : command) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const char* path = std::getenv("PATH");
    const std::string home = namespaces ? "/work" : cwd;
    std::vector<std::string> environment = {
        std::string("PATH=") + (path ? path : "/usr/local/bin:/usr/bin:/bin"),
        "LC_ALL=C", "LANG=C", "HOME=" + home, "TMPDIR=" + home};
    environment.insert(environment.end(), limits.environment.begin(), limits.environment.end());
    std::vector<char*> env;
    for (auto& e : environment) env.push_back(e.data());
    env.push_back(nullptr);
    const rlim_t cpu = static_cast<rlim_t>(std::ceil(limits.wall_seconds)) + 1;
    const rlim_t memory = static_cast<rlim_t>(limits.memory_mb) << 20;
    const rlim_t output = static_cast<rlim_t>(limits.output_bytes);

    auto close_program = [&]() {
        if (program >= 0) close(program);
    };
    int report[2];  // the child reports a failed exec here; closes on a successful one
    if (pipe2(report, O_CLOEXEC) != 0) {
        outcome.error = std::string("pipe: ") + std::strerror(errno);
        close_program();
        return outcome;
    }
    int channel[2] = {-1, -1};  // the report pipe, fd 3 in the child
    if (report_text) {
        report_text->clear();
        if (pipe2(channel, O_CLOEXEC) != 0) {
            outcome.error = std::string("pipe: ") + std::strerror(errno);
            close(report[0]);
            close(report[1]);
            close_program();
            return outcome;
        }
    }
    const pid_t parent = getpid();
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        outcome.error = std::string("fork: ") + std::strerror(errno);
        close(report[0]);
        close(report[1]);
        if (report_text) close(channel[0]), close(channel[1]);
        close_program();
        return outcome;
    }
    if (pid == 0) {
        setpgid(0, 0);
        prctl(PR_SET_PDEATHSIG, SIGKILL);  // the harness dies: so does the test
        if (getppid() != parent) _exit(127);
        close(report[0]);
        const int in = open("/dev/null", O_RDONLY);
        const int out = open(output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in < 0 || out < 0 || (!namespaces && chdir(cwd.c_str()) != 0)) {
            const int e = errno;
            (void)!write(report[1], &e, sizeof e);
            _exit(127);
        }
        // Every descriptor the child keeps moves above fd 10 first, out of the way of 0 to 4.
        const int exec_report = fcntl(report[1], F_DUPFD_CLOEXEC, 10);
        const int report_end = report_text ? fcntl(channel[1], F_DUPFD_CLOEXEC, 10) : -1;
        const int program_copy = program >= 0 ? fcntl(program, F_DUPFD_CLOEXEC, 10) : -1;
        dup2(in, 0);
        dup2(out, 1);
        dup2(out, 2);
        if (report_text) dup2(report_end, 3);  // without O_CLOEXEC: the program keeps it
        if (namespaces) dup2(program_copy, 4);  // bubblewrap reads it, then closes it
        const int first_closed = namespaces ? 5 : report_text ? 4 : 3;
        for (int fd = first_closed; fd < 1024; ++fd)
            if (fd != exec_report && !(fd == program_copy && !namespaces)) close(fd);
        if (!report_text && namespaces) close(3);
        report[1] = exec_report;
        for (int s = 1; s < NSIG; ++s) signal(s, SIG_DFL);
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, nullptr);
        set_limit(RLIMIT_AS, memory, memory);
        set_limit(RLIMIT_CPU, cpu, cpu + 1);
        set_limit(RLIMIT_FSIZE, output, output);
        set_limit(RLIMIT_CORE, 0, 0);
        if (as_nobody && !drop_to_nobody()) {
            const int e = errno;
            (void)!write(report[1], &e, sizeof e);
            _exit(127);
        }
        // In the namespaces, bubblewrap needs its own processes; the limit is set inside.
        if (limits.forbid_processes && !namespaces) set_limit(RLIMIT_NPROC, 0, 0);
        if (as_nobody && !namespaces) fexecve(program_copy, args.data(), env.data());
        else execve(args[0], args.data(), env.data());
        const int e = errno;
        (void)!write(report[1], &e, sizeof e);
        _exit(127);
    }
    setpgid(pid, pid);
    running_group = pid;
    close(report[1]);
    close_program();
    if (report_text) {
        close(channel[1]);
        fcntl(channel[0], F_SETFL, O_NONBLOCK);
    }
    // What the program writes to fd 3, kept up to report_limit.
    auto drain = [&]() {
        if (!report_text) return;
        char buffer[65536];
        ssize_t n;
        while ((n = read(channel[0], buffer, sizeof buffer)) > 0) {
            if (report_text->size() + static_cast<std::size_t>(n) <= report_limit)
                report_text->append(buffer, static_cast<std::size_t>(n));
            else if (report_overflow)
                *report_overflow = true;
        }
    };
    int exec_errno = 0;
    const bool exec_failed = read(report[0], &exec_errno, sizeof exec_errno) == sizeof exec_errno;
    close(report[0]);

    const auto deadline = start + std::chrono::duration<double>(limits.wall_seconds);
    int status = 0;
    auto pause = std::chrono::microseconds(200);
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) break;
        if (std::chrono::steady_clock::now() >= deadline) {
            outcome.timed_out = true;
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
            break;
        }
        if (report_text) {
            pollfd p{channel[0], POLLIN, 0};
            poll(&p, 1, static_cast<int>(std::max<long>(1, pause.count() / 1000)));
            drain();
        } else {
            std::this_thread::sleep_for(pause);
        }
        pause = std::min(pause * 2, std::chrono::microseconds(10000));
    }
    kill(-pid, SIGKILL);  // anything it left behind in its group
    running_group = 0;
    if (report_text) {
        drain();
        close(channel[0]);
    }
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (exec_failed) {
        outcome.error = "cannot run " + command[0] + ": " + std::strerror(exec_errno);
        return outcome;
    }
    outcome.started = true;
    if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
    else if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
    // bubblewrap reports a program killed by signal n as the exit status 128 + n.
    if (namespaces && outcome.exit_code > 128 && outcome.exit_code < 128 + NSIG)
        outcome.signal = outcome.exit_code - 128, outcome.exit_code = -1;
    return outcome;
}

}  // namespace grading
