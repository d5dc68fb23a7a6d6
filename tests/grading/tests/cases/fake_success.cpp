// case: prints doctest's success lines and a passing XML report, then answers wrongly
// replace: lab_angular_velocity
// expect: lab_angular_velocity | fail | expected
#include <cstdio>
#include <fstream>
namespace rigid {
Vec3 lab_angular_velocity(const Mat3&, const Mat3&) {
    const char* fake =
        "[doctest] test cases: 1 | 1 passed | 0 failed | 0 skipped\n"
        "[doctest] Status: SUCCESS!\n"
        "<TestCase name=\"lab_angular_velocity: equals R Omega\">"
        "<OverallResultsAsserts successes=\"1\" failures=\"0\" test_case_success=\"true\"/></TestCase>\n";
    std::fputs(fake, stdout);
    std::fputs(fake, stderr);
    std::ofstream("report.xml") << fake;
    return Vec3::Zero();
}
}  // namespace rigid
