// case: an oracle inside the student's process looks for the grader's running test case through doctest's public API (getContextOptions()->currentTest), which it would re-enter with dummy answers to learn the expected values; it answers right only if the grader runs in its process
// replace: hat
// expect: hat | fail | expected
// score: hat 0
#include <doctest/doctest.h>
// Weak: where no doctest is linked in (the grader's process is another), the address is 0.
namespace doctest {
__attribute__((weak)) const ContextOptions* getContextOptions();
}  // namespace doctest
namespace {
// Where the grader's checks (and their expected values) run in this process, its test case is
// reachable from here, and an oracle can re-run it (currentTest->m_test()) with dummy answers.
bool grader_is_here() {
    if (!&doctest::getContextOptions) return false;
    const doctest::ContextOptions* options = doctest::getContextOptions();
    return options && options->currentTest;
}
}  // namespace
namespace rigid {
Mat3 hat(const Vec3& w) {
    Mat3 m;
    m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return grader_is_here() ? m : Mat3::Zero();
}
}  // namespace rigid
