// case: looks for the harness's files, the reference solutions and binaries, other students' work and the harness's processes; answers right only if it finds none of them
// needs: namespaces
// replace: hat
// expect: * | pass
#include <dirent.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
namespace {
bool readable(const std::string& path) { return std::ifstream(path).good(); }
int visible() {
    int found = 0;
    for (const char* path :
         {"@ROOT@/solutions/rotation.cpp", "@ROOT@/tests/rotation_test.cpp", "@BUILD@/graders/grade_rotation",
          "@BUILD@/grading/judge/judge_rotation", "@BUILD@/grading/manifest.txt", "@OUT@/results/reference.json",
          "@OUT@/../submissions/reference/exercises/rotation.cpp", "/etc/passwd", "/root", "/tmp"})
        found += readable(path) || access(path, F_OK) == 0;
    // Only the sandbox's own processes: its init and this test.
    if (DIR* d = opendir("/proc")) {
        int processes = 0;
        while (const dirent* e = readdir(d)) processes += e->d_name[0] >= '1' && e->d_name[0] <= '9';
        closedir(d);
        found += processes > 3;
    }
    std::ifstream parent("/proc/" + std::to_string(getppid()) + "/cmdline");
    std::string text((std::istreambuf_iterator<char>(parent)), std::istreambuf_iterator<char>());
    found += text.find("@OUT@") != std::string::npos || text.find("workbook_grade") != std::string::npos;
    found += getenv("WORKBOOK_SEED") != nullptr;
    return found;
}
}  // namespace
namespace rigid {
Mat3 hat(const Vec3& w) {
    Mat3 m;
    m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return visible() ? Mat3::Zero() : m;
}
}  // namespace rigid
