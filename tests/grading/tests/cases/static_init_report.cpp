// case: the untouched stubs, plus a static initialiser that writes a complete passing report to fd 3 and exits before main
// base: stubs
// expect: * | not started | todo(
// score: hat 0
#include <unistd.h>
namespace {
const int forged = [] {
    const char report[] =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<doctest binary=\"grade_rotation\">\n<TestSuite name=\"ch01\">\n"
        "<TestCase name=\"hat: satisfies hat(w) x = w x x\" filename=\"@ROOT@/tests/rotation_test.cpp\" line=\"1\">\n"
        "<OverallResultsAsserts successes=\"1\" failures=\"0\" test_case_success=\"true\"/></TestCase>\n"
        "</TestSuite></doctest>\nWBREC1\nE";
    (void)!write(3, report, sizeof report - 1);
    _exit(0);
    return 0;
}();
}  // namespace
