// The student's process (serve.hpp): its main loop, its state between the calls of one test,
// and the hardening that runs before any of the student's code can.
//
// Hardening: a function in .preinit_array, which the dynamic linker runs before any
// constructor of the program or of its libraries (only an indirect function's resolver would
// run earlier, and the harness refuses an exercise file that defines one). It sets the output
// limit the harness asks for (WORKBOOK_OUTPUT_LIMIT, read from the environment it was given) and
// installs the seccomp filter that the build made with libseccomp (seccomp_filter.cpp): threads
// may be made, processes may not (clone without CLONE_THREAD, fork, vfork: EPERM; clone3:
// ENOSYS, so that threads are made with clone), and no program may be started (execve,
// execveat: EPERM). Both through the system call itself, not through a library function the
// student's file could define in its place.
#include "serve.hpp"

#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>

namespace workbook_remote::serve {

namespace {

struct State {
    std::vector<std::uint64_t> frames;  // per open call, its generation (0: closed)
    std::uint64_t generations = 0;
    std::vector<Closure> closures;  // the callables the student returned, by number
};

State& state() {
    static State s;
    return s;
}

[[noreturn]] void judge_gone() {
    std::fflush(nullptr);
    std::_Exit(0);
}

void open_frame(std::uint32_t frame) {
    auto& f = state().frames;
    if (frame != f.size()) refuse("the judge opened a call out of order");
    f.push_back(++state().generations);
}

void close_frame(std::uint32_t frame) { state().frames.resize(frame); }

void dispatch(const std::string& message) {
    const auto tag = static_cast<unsigned char>(message[0]);
    if (tag == tag_quit) std::exit(0);  // the test is over: static destructors, atexit, as after main
    std::size_t at = 1;
    NoCallables none;
    Reader<NoCallables> r{message, at, none};
    const std::uint32_t id = r.u32(), frame = r.u32();
    if (tag == tag_call && id < api_count) {
        open_frame(frame);
        api_table[id](message, at, frame);
        close_frame(frame);
    } else if (tag == tag_closure && id < state().closures.size()) {
        open_frame(frame);
        const Closure c = state().closures[id];
        c(message, at, frame);
        close_frame(frame);
    } else {
        refuse("the judge sent a message the student's process does not know");
    }
}

}  // namespace

Channel& channel() {
    static Channel c(false);
    return c;
}

std::recursive_mutex& channel_lock() {
    static std::recursive_mutex m;
    return m;
}

void refuse(const std::string& why) {
    channel().send(std::string(1, static_cast<char>(tag_refuse)) + why);
    std::fflush(nullptr);
    std::_Exit(3);
}

void send(const std::string& message) {
    std::lock_guard<std::recursive_mutex> lock(channel_lock());
    if (!channel().send(message)) judge_gone();
}

std::string receive() {
    std::string message;
    if (channel().receive(message) != Received::message) judge_gone();
    return message;
}

bool frame_open(std::uint32_t frame, std::uint64_t generation) {
    const auto& f = state().frames;
    return frame < f.size() && f[frame] == generation;
}

std::uint64_t frame_generation(std::uint32_t frame) {
    const auto& f = state().frames;
    return frame < f.size() ? f[frame] : 0;
}

void serve_nested(const std::string& message) { dispatch(message); }

std::uint32_t keep(Closure c) {
    state().closures.push_back(std::move(c));
    return static_cast<std::uint32_t>(state().closures.size() - 1);
}

}  // namespace workbook_remote::serve

// ---- hardening, before any of the student's code ------------------------------------------
namespace {

#if defined(__x86_64__)
long raw_syscall(long n, long a, long b, long c, long d) {
    long ret;
    register long r10 __asm__("r10") = d;
    register long r8 __asm__("r8") = 0;  // the unused arguments are 0 (prctl checks them)
    register long r9 __asm__("r9") = 0;
    __asm__ volatile("syscall"
                     : "=a"(ret)
                     : "a"(n), "D"(a), "S"(b), "d"(c), "r"(r10), "r"(r8), "r"(r9)
                     : "rcx", "r11", "memory");
    return ret;
}
#elif defined(__aarch64__)
long raw_syscall(long n, long a, long b, long c, long d) {
    register long x8 __asm__("x8") = n;
    register long x0 __asm__("x0") = a;
    register long x1 __asm__("x1") = b;
    register long x2 __asm__("x2") = c;
    register long x3 __asm__("x3") = d;
    register long x4 __asm__("x4") = 0;  // the unused arguments are 0 (prctl checks them)
    register long x5 __asm__("x5") = 0;
    __asm__ volatile("svc 0" : "+r"(x0) : "r"(x8), "r"(x1), "r"(x2), "r"(x3), "r"(x4), "r"(x5) : "memory");
    return x0;
}
#else
#error "the grading sandbox's hardening (tests/grading/engine/remote/serve.cpp) is written for x86_64 and aarch64"
#endif

#include "seccomp_filter.inc"  // workbook_filter_bytes[]: the BPF program, made by the build with libseccomp

[[noreturn]] void cannot_harden(const char* why, unsigned long length) {
    raw_syscall(SYS_write, 2, reinterpret_cast<long>(why), static_cast<long>(length), 0);
    raw_syscall(SYS_exit_group, 125, 0, 0, 0);
    __builtin_unreachable();
}

// The student's process is PID 1 of its namespace (sandbox.cpp, bwrap_test), and the kernel does
// not deliver to a PID 1 a signal it has no handler for, but for a fault: abort() would end in a
// SIGSEGV, an output past the limit would not stop it (SIGXFSZ), a kill(getpid(), ...) would do
// nothing. This handler ends the process with 128 + the signal, which bubblewrap reports as it
// reports a death by that signal, and the harness reads as one (sandbox.cpp, decode). Installed
// with the system call itself (no SA_RESTORER: the handler never returns).
void end_by_signal(int signal) {
    raw_syscall(SYS_exit_group, 128 + signal, 0, 0, 0);
    __builtin_unreachable();
}

struct KernelAction {  // the kernel's struct sigaction (asm-generic/signal.h, x86_64, aarch64)
    void (*handler)(int);
    unsigned long flags;
    void (*restorer)();
    unsigned long mask;
};

#if defined(__x86_64__)
// Never called (the handler does not return), but x86_64's kernel sets up no handler's frame
// without a restorer: it would make the signal a SIGSEGV.
void restore() { raw_syscall(SYS_rt_sigreturn, 0, 0, 0, 0); }
#endif

void handle_fatal_signals() {
#if defined(__x86_64__)
    const KernelAction action{end_by_signal, 0x04000000ul /* SA_RESTORER */, restore, ~0ul};
#else
    const KernelAction action{end_by_signal, 0, nullptr, ~0ul};
#endif
    for (const int signal : {SIGHUP, SIGINT, SIGQUIT, SIGILL, SIGTRAP, SIGABRT, SIGBUS, SIGFPE, SIGUSR1, SIGSEGV,
                             SIGUSR2, SIGALRM, SIGTERM, SIGSTKFLT, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, SIGSYS})
        if (raw_syscall(SYS_rt_sigaction, signal, reinterpret_cast<long>(&action), 0, sizeof(unsigned long)) != 0)
            cannot_harden("grading sandbox: cannot handle the fatal signals\n", 49);
}

void harden(int, char**, char** envp) {
    if (raw_syscall(SYS_getpid, 0, 0, 0, 0) == 1) handle_fatal_signals();  // not in the fallback without namespaces
    static const char key[] = "WORKBOOK_OUTPUT_LIMIT=";
    for (char** e = envp; e && *e; ++e) {
        const char* v = *e;
        unsigned long k = 0;
        while (key[k] && v[k] == key[k]) ++k;
        if (key[k]) continue;
        unsigned long limit = 0;
        for (v += k; *v >= '0' && *v <= '9'; ++v) limit = limit * 10 + static_cast<unsigned long>(*v - '0');
        const rlimit r{limit, limit};
        if (raw_syscall(SYS_prlimit64, 0, RLIMIT_FSIZE, reinterpret_cast<long>(&r), 0) != 0)
            cannot_harden("grading sandbox: cannot set the output limit\n", 45);
    }
    const sock_fprog program{static_cast<unsigned short>(sizeof workbook_filter_bytes / sizeof(sock_filter)),
                             reinterpret_cast<sock_filter*>(const_cast<unsigned char*>(workbook_filter_bytes))};
    if (raw_syscall(SYS_prctl, PR_SET_NO_NEW_PRIVS, 1, 0, 0) != 0 ||
        raw_syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, 0, reinterpret_cast<long>(&program), 0) != 0)
        cannot_harden("grading sandbox: cannot install the seccomp filter\n", 51);
}

__attribute__((section(".preinit_array"), used)) void (*const preinit)(int, char**, char**) = harden;

}  // namespace

// The student's process: serves the judge's calls until the judge says the test is over (or
// closes the channel). A write to the channel after the judge has gone fails, not kills.
int main() {
    std::signal(SIGPIPE, SIG_IGN);
    for (;;) {
        std::string message;
        if (workbook_remote::serve::channel().receive(message) != workbook_remote::Received::message) return 0;
        workbook_remote::serve::serve_nested(message);
    }
}
