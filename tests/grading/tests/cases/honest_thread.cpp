// case: honest code that computes geodesic_angle in a std::thread and joins it (and uses two more threads elsewhere): full marks
// replace: geodesic_angle
// expect: * | pass
#include <cmath>
#include <thread>
namespace rigid {
double geodesic_angle(const Mat3& R1, const Mat3& R2) {
    double angle = 0;
    std::thread worker([&] {
        const Mat3 D = R1.transpose() * R2;
        angle = std::atan2(vee(D).norm(), 0.5 * (D.trace() - 1));
    });
    worker.join();
    std::thread a([] {}), b([] {});
    a.join();
    b.join();
    return angle;
}
}  // namespace rigid
