#include "checks.hpp"
#include "rigid/grioli.hpp"
TEST_SUITE("ch05_grioli_precession") {
TEST_CASE("moments: placeholder") { CHECK(rigid::moments(1, 2, 2.5).A == 1.0); }
}
