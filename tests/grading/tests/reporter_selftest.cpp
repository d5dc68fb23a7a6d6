// The workbook reporter (reporter.cpp) must name, for a test that fails by an exception, the
// other exercises the test said it uses (ALSO_USES): the exception may come from their code, and
// the student must see which. This test throws with one in scope; ctest requires the reporter's
// exception event to carry that line.
#include <doctest/doctest.h>

#include <stdexcept>

#include "checks.hpp"

TEST_CASE("planted: throws inside another exercise's code") {
    ALSO_USES("planted_exercise");
    throw std::invalid_argument("planted exception");
}
