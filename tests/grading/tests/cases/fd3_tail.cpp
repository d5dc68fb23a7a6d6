// case: writes the end of a passing doctest XML report to fd 3 (the channel to the judge), then _exit(0)
// replace: geodesic_angle
// expect: geodesic_angle | fail | did not finish
// score: geodesic_angle 0
#include <unistd.h>
namespace rigid {
double geodesic_angle(const Mat3&, const Mat3&) {
    const char tail[] =
        "<OverallResultsAsserts successes=\"1\" failures=\"0\" test_case_success=\"true\"/></TestCase>\n"
        "</TestSuite></doctest>\nE";
    (void)!write(3, tail, sizeof tail - 1);
    _exit(0);
}
}  // namespace rigid
