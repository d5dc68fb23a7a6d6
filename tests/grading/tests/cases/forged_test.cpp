// case: brings its own passing TEST_CASEs with the graders' names, one faking their file by #line, and a wrong compose: exercise files are compiled with doctest disabled, so its tests are never even registered, and the graders' tests decide
// replace: compose
// expect: compose | fail | expected
// score: compose 0
#include <doctest/doctest.h>
namespace rigid {
AxisAngle compose(const AxisAngle& first, const AxisAngle&) { return first; }
}  // namespace rigid
#line 223 "@ROOT@/tests/rotation_test.cpp"
TEST_CASE("compose: agrees with the product of the two matrices") { CHECK(true); }
TEST_CASE("compose: the order matters as for matrices") { CHECK(true); }
TEST_CASE("compose: a turn and its inverse give the identity and bad axes are rejected") { CHECK(true); }
