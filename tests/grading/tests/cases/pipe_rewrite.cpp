// case: a static initialiser puts its own pipe on fd 3 and, at exit, passes on what came through it with "false" rewritten as "true", with a wrong lab_angular_velocity
// replace: lab_angular_velocity
// expect: lab_angular_velocity | fail | expected
// score: lab_angular_velocity 0
#include <unistd.h>

#include <cstdlib>
#include <string>
namespace rigid {
Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) { return vee(R.transpose() * R_dot); }
}  // namespace rigid
namespace {
int real_fd = -1, pipe_end = -1;
void pass_on() {
    close(3);
    std::string all;
    char buffer[4096];
    ssize_t n;
    while ((n = read(pipe_end, buffer, sizeof buffer)) > 0) all.append(buffer, static_cast<std::size_t>(n));
    for (std::size_t p; (p = all.find("false")) != std::string::npos;) all.replace(p, 5, "true ");
    (void)!write(real_fd, all.data(), all.size());
}
const int installed = [] {
    int p[2];
    if (pipe(p) != 0) return 0;
    real_fd = dup(3);
    dup2(p[1], 3);
    close(p[1]);
    pipe_end = p[0];
    std::atexit(pass_on);
    return 1;
}();
}  // namespace
