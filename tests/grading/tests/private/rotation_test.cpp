// A private test as an instructor writes one (tests/grading/README.md, "Private tests"), for the
// leak test (test.sh): its source, its inputs and its expected values carry markers that must
// reach no file a student sees. qz7-PRIVATE-MARKER-source: this comment is one of them.
#include "rigid/rotation.hpp"

#include "checks.hpp"

using rigid::Mat3;
using rigid::Vec3;

TEST_CASE("hat: a private case the students have not seen") {
    INFO("qz7-PRIVATE-MARKER-info");                      // printed with a failed check: staff log only
    const Mat3 W = rigid::hat(Vec3(0.0, 0.0, 37.28125));  // an input, and an expected value, that are markers
    CHECK(W(1, 0) == doctest::Approx(37.28125));
    CHECK(W(0, 1) == doctest::Approx(-37.28125));
}

TEST_CASE("vee: a second private case") {
    Mat3 W = Mat3::Zero();
    W(2, 1) = 611.40625;
    W(1, 2) = -611.40625;
    CHECK(rigid::vee(W).x() == doctest::Approx(611.40625));
}
