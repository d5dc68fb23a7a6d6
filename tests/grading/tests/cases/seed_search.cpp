// case: looks for the instructor's --seed from the inputs it is given: hat's first test draws w = 3 (u1, u2, u3) with u uniform on [-1, 1) from the test's generator, so a submission can try seeds 0 to 300,000 until one draws the same w; when the seed itself seeded the generator, the suite's 4242 was found at once (issue 42: a class found seed 7); with each test's seed a keyed hash (SipHash) of the test's name, no seed draws it. Answers right only if it finds none
// replace: hat
// expect: * | pass
// seeded: * | pass
#include <algorithm>
#include <array>
#include <random>
namespace {
bool seed_found(const rigid::Vec3& w) {
    std::array<double, 3> seen{w.x(), w.y(), w.z()};
    std::sort(seen.begin(), seen.end());
    for (unsigned long s = 0; s <= 300000; ++s) {
        std::mt19937_64 g(s);
        std::uniform_real_distribution<double> u(-1, 1);
        std::array<double, 3> drawn{3 * u(g), 3 * u(g), 3 * u(g)};
        std::sort(drawn.begin(), drawn.end());
        if (drawn == seen) return true;
    }
    return false;
}
}  // namespace
namespace rigid {
Mat3 hat(const Vec3& w) {
    static const bool found = seed_found(w);  // the first call: the first test's first draw
    const double s = found ? -1 : 1;
    Mat3 m;
    m << 0, -s * w.z(), s * w.y(), s * w.z(), 0, -s * w.x(), -s * w.y(), s * w.x(), 0;
    return m;
}
}  // namespace rigid
