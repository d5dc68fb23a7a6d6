// case: holds memory outside the address-space limit (--memory), where a classmate's test or the harness would pay for it: memfds (1,536 of 1 MB were held under a 1024 MB limit, issue 42), files in /dev/shm, / and /dev (tmpfs of half the machine's memory each), and more descriptors than a test needs; answers right only if every way is refused or bounded
// needs: namespaces
// replace: hat
// expect: * | pass
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <csignal>
#include <string>
#include <vector>
namespace {
// Writes 64 files of 512 KB (each under the output limit, which bounds a file) into `folder`;
// true when it took them all: 32 MB, more than /work or /dev/shm may hold (4 times the output
// limit, at least 8 MB).
bool fills(const std::string& folder) {
    const std::vector<char> block(512 << 10, 'x');
    int k = 0;
    for (; k < 64; ++k) {
        const int fd = open((folder + "/hoard" + std::to_string(k)).c_str(), O_CREAT | O_WRONLY | O_TRUNC, 0600);
        if (fd < 0) break;
        const bool whole = write(fd, block.data(), block.size()) == static_cast<ssize_t>(block.size());
        close(fd);
        if (!whole) break;
    }
    for (int j = 0; j <= k && j < 64; ++j) unlink((folder + "/hoard" + std::to_string(j)).c_str());
    return k == 64;
}
bool hoarded() {
    bool any = false;
    const int memfd = static_cast<int>(memfd_create("hoard", 0));
    if (memfd >= 0) any = true, close(memfd);
    std::signal(SIGXFSZ, SIG_IGN);  // a write past the output limit fails, not ends the process
    for (const char* folder : {"/dev/shm", "", "/dev", "/run"})
        if (fills(folder)) any = true;
    int opened = 0;
    std::vector<int> fds;
    for (int fd; opened < 200 && (fd = open("/dev/null", O_RDONLY)) >= 0; ++opened) fds.push_back(fd);
    for (const int fd : fds) close(fd);
    return any || opened >= 200;
}
}  // namespace
namespace rigid {
Mat3 hat(const Vec3& w) {
    static const bool hoard = hoarded();
    const double s = hoard ? -1 : 1;
    Mat3 m;
    m << 0, -s * w.z(), s * w.y(), s * w.z(), 0, -s * w.x(), -s * w.y(), s * w.x(), 0;
    return m;
}
}  // namespace rigid
