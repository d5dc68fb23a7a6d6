// case: floods its output without end
// replace: geodesic_angle
// expect: geodesic_angle | crash | output limit exceeded
#include <cstdio>
namespace rigid {
double geodesic_angle(const Mat3&, const Mat3&) {
    for (;;) std::fputs("all work and no play makes Jack a dull boy\n", stdout);
}
}  // namespace rigid
