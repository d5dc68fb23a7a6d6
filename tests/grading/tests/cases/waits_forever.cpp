// case: waits for something that never comes (a sleep in a loop): it uses no processor time, so only the wall-clock backstop ends it, and only after the test was run again alone
// replace: lab_angular_velocity
// expect: lab_angular_velocity | timeout | wall-clock backstop of 12 s (twice, the second time alone)
#include <unistd.h>
namespace rigid {
Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) {
    for (;;) sleep(1);
    return vee(R_dot * R.transpose());
}
}  // namespace rigid
