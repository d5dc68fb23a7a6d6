// The one doctest main shared by every grader binary, and the reseeding of checks::rng().
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <random>

namespace checks {

std::mt19937_64& rng() {
    static std::mt19937_64 generator;
    return generator;
}

}  // namespace checks

namespace {

// Every test case starts from the same seed, whatever ran before it.
struct Reseed : doctest::IReporter {
    explicit Reseed(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData&) override { checks::rng().seed(20261121); }
    void test_case_reenter(const doctest::TestCaseData&) override { checks::rng().seed(20261121); }
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

REGISTER_LISTENER("reseed", 1, Reseed);

}  // namespace
