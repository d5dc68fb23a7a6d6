// Private tests (README.md, "Private tests"): an instructor's own graders, which students never
// see. The build links them into the judges alone (tests/grading/grading.cmake) and lists them in
// the manifest as `private` lines; here, what a student's results may say about them.
#include <cstdlib>
#include <map>

#include "grading.hpp"

namespace grading {

bool has_private_tests(const Setup& setup) {
    for (const auto& topic : setup.topics)
        for (const auto& e : topic.exercises)
            for (const auto& t : e.tests)
                if (!t.private_file.empty()) return true;
    return false;
}

std::string set_private_feedback(Setup& setup, const std::string& mode) {
    if (mode != "names" && mode != "total") return "--private-feedback takes names or total, not '" + mode + "'";
    setup.private_names = mode == "names";
    if (!has_private_tests(setup)) return {};
    // A private test's checks are in no file the fingerprint reads (its folder is the instructor's,
    // anywhere): the judges that hold them stand for them, so that a result graded before a private
    // test changed is not reused. The results .json differs with the mode, too.
    std::string all = setup.fingerprint + "\nprivate-feedback " + mode + "\n";
    for (const auto& topic : setup.topics) {
        bool any = false;
        for (const auto& e : topic.exercises)
            for (const auto& t : e.tests) any = any || !t.private_file.empty();
        if (any) all += topic.judge + " " + hex(hash(read_file(topic.judge))) + "\n";
    }
    setup.fingerprint = hex(hash(all));
    return {};
}

void drop_private_tests(Setup& setup) {
    for (auto& topic : setup.topics)
        for (auto& e : topic.exercises) std::erase_if(e.tests, [](const Test& t) { return !t.private_file.empty(); });
}

namespace {

// What a student reads of a private test that did not pass: its verdict, never why. (A failed
// check's message holds the expected value; a crash, a timeout or an exception can carry what
// the student's code printed or threw about the private inputs.)
std::string withheld_message(Verdict v, const std::string& message) {
    switch (v) {
        case Verdict::pass:
            return "";
        case Verdict::timeout:
            return "a private test did not finish in time; its inputs are not shown";
        case Verdict::crash:
            return "a private test crashed your code; its inputs are not shown";
        case Verdict::build_error:
        case Verdict::missing:
            return message;  // about the student's own file, before any test ran
        default:
            return "a private test: what it checks, its inputs and its expected values are not shown";
    }
}

}  // namespace

void withhold_private(TestResult& t, const Setup& setup, const std::string& log_dir) {
    t.hidden = true;
    if (!log_dir.empty()) {
        const std::string path = log_dir + "/private.txt";
        std::string entry = "== " + t.name + ": " + to_string(t.verdict) + "\n";
        if (!t.message.empty()) entry += t.message + "\n";
        if (!t.output.empty()) entry += "-- the test printed:\n" + t.output + "\n";
        write_file(path, read_file(path) + entry);
    }
    // With --private-feedback total not even its name leaves the worker (the .tsv keeps each test).
    if (!setup.private_names) t.name = t.exercise + ": a private test";
    // The leak test's planted fault (tests/grading/tests/private/test.sh): the detail stays in the results.
    if (const char* plant = std::getenv("WORKBOOK_GRADING_PLANT"); plant && std::string(plant) == "leak-private")
        return;
    if (!t.not_started) t.message = withheld_message(t.verdict, t.message);
    t.output.clear();
}

// --private-feedback total: one entry per exercise for its private tests, where the first was.
std::vector<TestResult> student_view(const Setup& setup, const std::vector<TestResult>& tests) {
    if (setup.private_names) return tests;
    std::vector<TestResult> view;
    std::map<std::string, std::size_t> entry;  // topic/exercise -> its entry in view
    std::map<std::string, int> passed, count;
    for (const auto& t : tests) {
        if (!t.hidden) {
            view.push_back(t);
            continue;
        }
        const std::string key = t.topic + "/" + t.exercise;
        if (!entry.count(key)) {
            entry[key] = view.size();
            TestResult total = t;
            total.name = t.exercise + ": private tests";
            total.score = total.max_score = 0;
            total.not_started = true;
            total.verdict = Verdict::pass;
            view.push_back(total);
        }
        TestResult& total = view[entry[key]];
        total.score += t.score, total.max_score += t.max_score;
        total.not_started = total.not_started && t.not_started;
        if (total.verdict == Verdict::pass && t.verdict != Verdict::pass) total.verdict = t.verdict;
        if (t.verdict == Verdict::build_error || t.verdict == Verdict::missing) total.message = t.message;
        passed[key] += t.verdict == Verdict::pass, ++count[key];
    }
    for (const auto& [key, k] : entry) {
        TestResult& total = view[k];
        if (total.verdict == Verdict::build_error || total.verdict == Verdict::missing) continue;
        total.message = std::to_string(passed[key]) + " of " + std::to_string(count[key]) +
                        " private tests pass (they are not shown)";
    }
    return view;
}

}  // namespace grading
