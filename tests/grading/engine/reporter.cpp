// The grading run's verdict reporter (--reporters=workbook), linked into every grader binary with
// the doctest main (tests/main.cpp). Its reader is the grading run's (grade.cpp, which turns its
// lines into verdicts) and the stub gate's (stub_gate.cpp).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "listener.hpp"

// Defined only in the grading run's judges (tests/grading/engine/remote/judge.cpp): why the test case
// cannot pass although its checks may have, or an empty string.
extern "C" const char* workbook_remote_verdict() __attribute__((weak));
extern "C" unsigned long long workbook_remote_round_trips() __attribute__((weak));
extern "C" unsigned long long workbook_remote_sent_hash() __attribute__((weak));

namespace {

// The grading run's reporter (--reporters=workbook): one JSON object per line, written and
// flushed as things happen, so that a process that dies leaves what it had said.
//   {"test": name, "file": ..., "line": n}                 per test case, for --list-test-cases
//   {"event": "start", "name": ..., "file": ..., "line": n}
//   {"event": "assert", "file", "line", "type", "expression", "expanded", "info": [...], ...}
//                                                           every failed check
//   {"event": "site", ...}                                  with --success alone (the message lint,
//                        cmake/checks/messages.py): a check that passed, the first time each check of
//                        the test case ran, with what its failure message would hold
//   {"event": "message", "file", "line", "text", "severity"}   MESSAGE, WARN, FAIL
//   {"event": "exception", "text": ..., "crash": bool}      what escaped the test case
//   {"event": "end", "name": ..., "success": bool, "failed_checks": n, "checks": n, "remote": ...}
//   {"event": "run", "cases": n, "failed": n}               the run is over
struct Verdicts : checks::Listener {
    const doctest::ContextOptions& opt;
    const doctest::TestCaseData* current = nullptr;
    std::set<std::pair<std::string, int>> sites;  // --success: the checks of this test case already shown
    explicit Verdicts(const doctest::ContextOptions& o) : opt(o) {}

    void emit(const nlohmann::json& j) {
        *opt.cout << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        opt.cout->flush();
    }
    static std::string text(const doctest::String& s) { return s.c_str(); }
    static nlohmann::json contexts() {
        nlohmann::json info = nlohmann::json::array();
        const int n = get_num_active_contexts();
        const auto all = get_active_contexts();
        for (int i = 0; i < n; ++i) {
            std::ostringstream s;
            all[i]->stringify(&s);
            info.push_back(s.str());
        }
        return info;
    }

    void report_query(const doctest::QueryData& q) override {
        for (unsigned i = 0; i < q.num_data; ++i)
            emit({{"test", q.data[i]->m_name},
                  {"file", text(q.data[i]->m_file)},
                  {"line", q.data[i]->m_line},
                  {"timeout", q.data[i]->m_timeout}});
    }
    void test_run_end(const doctest::TestRunStats& st) override {
        emit({{"event", "run"}, {"cases", st.numTestCasesPassingFilters}, {"failed", st.numTestCasesFailed}});
    }
    void test_case_start(const doctest::TestCaseData& t) override {
        current = &t;
        sites.clear();
        emit({{"event", "start"}, {"name", t.m_name}, {"file", text(t.m_file)}, {"line", t.m_line}});
    }
    void test_case_end(const doctest::CurrentTestCaseStats& st) override {
        nlohmann::json j{{"event", "end"},
                         {"name", current ? current->m_name : ""},
                         {"success", st.testCaseSuccess},
                         {"failed_checks", st.numAssertsFailedCurrentTest},
                         {"checks", st.numAssertsCurrentTest}};
        if (workbook_remote_verdict) {
            const std::string problem = workbook_remote_verdict();
            j["remote"] = problem;
            j["round_trips"] = workbook_remote_round_trips ? workbook_remote_round_trips() : 0;
            j["sent"] = workbook_remote_sent_hash ? workbook_remote_sent_hash() : 0;
            if (!problem.empty()) j["success"] = false;
        }
        emit(j);
    }
    void test_case_exception(const doctest::TestCaseException& e) override {
        // The INFO lines in scope where it was thrown (doctest keeps them while the stack unwinds):
        // ALSO_USES names the other exercises the test called, which may be the ones that threw.
        nlohmann::json info = nlohmann::json::array();
        const int n = get_num_stringified_contexts();
        const doctest::String* all = get_stringified_contexts();
        for (int i = n - 1; i >= 0; --i) info.push_back(text(all[i]));
        emit({{"event", "exception"}, {"text", text(e.error_string)}, {"crash", e.is_crash}, {"info", info}});
    }
    void log_assert(const doctest::AssertData& a) override {
        if (!a.m_failed && !(opt.success && sites.emplace(a.m_file, a.m_line).second)) return;
        nlohmann::json j{{"event", a.m_failed ? "assert" : "site"},
                         {"file", a.m_file},
                         {"line", a.m_line},
                         {"type", doctest::assertString(a.m_at)},
                         {"expression", a.m_expr},
                         {"expanded", text(a.m_decomp)},
                         {"info", contexts()}};
        if (a.m_threw) j["threw"] = text(a.m_exception);
        if (a.m_exception_type) j["expected_exception"] = a.m_exception_type;
        emit(j);
    }
    void log_message(const doctest::MessageData& m) override {
        emit({{"event", "message"},
              {"file", m.m_file},
              {"line", m.m_line},
              {"text", text(m.m_string)},
              {"severity", doctest::failureString(m.m_severity)},
              {"info", contexts()}});
    }
};

REGISTER_REPORTER("workbook", 1, Verdicts);

}  // namespace
