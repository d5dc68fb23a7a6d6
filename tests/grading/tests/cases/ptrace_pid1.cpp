// case: reaches for another process of its sandbox: attaches to PID 1 with ptrace (bubblewrap's reaper ran there, as the student's user and without the seccomp filter, so a student could make it start a program, issue 42), opens its memory for writing, and looks for any other process in /proc; answers right only if there is none to reach and ptrace is refused
// needs: namespaces
// replace: hat
// expect: * | pass
#include <dirent.h>
#include <fcntl.h>
#include <sys/ptrace.h>
#include <unistd.h>

#include <cstdlib>
namespace {
bool reached_another() {
    bool reached = ptrace(PTRACE_SEIZE, 1, nullptr, nullptr) == 0;  // refused by the filter, whoever PID 1 is
    if (getpid() != 1) {
        const int fd = open("/proc/1/mem", O_RDWR);
        if (fd >= 0) reached = true, close(fd);
    }
    if (DIR* proc = opendir("/proc")) {
        while (const dirent* e = readdir(proc))
            if (std::atoi(e->d_name) > 0 && std::atoi(e->d_name) != getpid()) reached = true;
        closedir(proc);
    }
    return reached;
}
}  // namespace
namespace rigid {
Mat3 hat(const Vec3& w) {
    static const bool reached = reached_another();
    const double s = reached ? -1 : 1;
    Mat3 m;
    m << 0, -s * w.z(), s * w.y(), s * w.z(), 0, -s * w.x(), -s * w.y(), s * w.x(), 0;
    return m;
}
}  // namespace rigid
