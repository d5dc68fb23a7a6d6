// A doctest reporter that does nothing: the base of every listener and reporter of the graders
// (the reseeding of tests/main.cpp, the verdicts of tests/grading/engine/reporter.cpp, the judge's in
// tests/grading/engine/remote/), each overriding only the events it acts on.
#pragma once

#include <doctest/doctest.h>

namespace checks {

struct Listener : doctest::IReporter {
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData&) override {}
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

}  // namespace checks
