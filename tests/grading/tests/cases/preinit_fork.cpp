// case: its own .preinit_array entry, which the dynamic linker runs before any constructor, tries fork() before the seccomp filter could be in place, and answers lab_angular_velocity right only if the fork worked: the student's side of the API is linked first, so its filter is installed before the student's entry runs
// replace: lab_angular_velocity
// expect: lab_angular_velocity | fail | expected
// score: lab_angular_velocity 0
#include <sys/wait.h>
#include <unistd.h>
namespace {
bool forked = false;
void early(int, char**, char**) {
    const pid_t child = fork();
    if (child == 0) _exit(0);
    if (child > 0) forked = waitpid(child, nullptr, 0) == child;
}
__attribute__((section(".preinit_array"), used)) void (*const early_entry)(int, char**, char**) = early;
}  // namespace
namespace rigid {
Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) {
    return forked ? Vec3(vee(R_dot * R.transpose())) : vee(R.transpose() * R_dot);
}
}  // namespace rigid
