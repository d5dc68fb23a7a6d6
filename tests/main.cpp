// The one doctest main shared by every grader binary and the reseeding of checks::rng(). The
// grading run's verdict reporter, linked with it, is beside its reader: tests/grading/engine/reporter.cpp.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <cstdint>
#include <cstdlib>
#include <random>

#include "listener.hpp"

namespace checks {

std::mt19937_64& rng() {
    static std::mt19937_64 generator;
    return generator;
}

}  // namespace checks

namespace {

// Every test case starts from the same seed, whatever ran before it: the public one, or the one
// the instructor's grading run sets (workbook_grade grade --seed, passed to the judge alone as
// WORKBOOK_SEED), so that a table of the answers to the public inputs earns nothing.
std::uint64_t seed() {
    static const std::uint64_t s = [] {
        const char* text = std::getenv("WORKBOOK_SEED");
        char* end = nullptr;
        const unsigned long long value = text ? std::strtoull(text, &end, 10) : 0;
        return text && *text && end && !*end ? static_cast<std::uint64_t>(value) : std::uint64_t(20261121);
    }();
    return s;
}

struct Reseed : checks::Listener {
    explicit Reseed(const doctest::ContextOptions&) {}
    void test_case_start(const doctest::TestCaseData&) override { checks::rng().seed(seed()); }
    void test_case_reenter(const doctest::TestCaseData&) override { checks::rng().seed(seed()); }
};

REGISTER_LISTENER("reseed", 1, Reseed);

}  // namespace
