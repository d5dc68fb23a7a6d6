// case: exit(0) in the middle of a test, which fools graders that trust the exit status
// replace: geodesic_angle
// expect: geodesic_angle | fail | did not finish
#include <cstdlib>
namespace rigid {
double geodesic_angle(const Mat3&, const Mat3&) { std::exit(0); }
}  // namespace rigid
