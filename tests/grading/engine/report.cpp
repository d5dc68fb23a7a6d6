// Reports: the class CSV and Markdown summary (instructor), and the student's check.
#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>

#include "grading.hpp"
#include "hints.hpp"
#include "mistakes.hpp"

namespace grading {

ExerciseStatus status_of(const SubmissionResult& r, const std::string& topic, const std::string& exercise) {
    ExerciseStatus s;
    int not_started = 0;
    std::map<Verdict, int> verdicts;
    for (const auto& t : r.tests) {
        if (t.topic != topic || t.exercise != exercise) continue;
        ++s.total;
        s.score += t.score;
        ++verdicts[t.verdict];
        if (t.verdict == Verdict::pass)
            ++s.passed;
        else if (!s.first_problem)
            s.first_problem = &t;
        not_started += t.not_started;
    }
    if (s.total == 0)
        s.status.reset();
    else if (s.passed == s.total)
        s.status = Verdict::pass;
    else if (verdicts[Verdict::build_error])
        s.status = Verdict::build_error;
    else if (verdicts[Verdict::missing])
        s.status = Verdict::missing;
    else if (not_started == s.total)
        s.status = Verdict::not_started;
    else if (verdicts[Verdict::crash])
        s.status = Verdict::crash;
    else if (verdicts[Verdict::timeout])
        s.status = Verdict::timeout;
    else
        s.status = Verdict::fail;
    return s;
}

std::vector<Blame> blame(const Setup& setup, const SubmissionResult& r) {
    std::vector<Blame> out;
    for (const auto& topic : setup.topics)
        for (const auto& e : topic.exercises) {
            const ExerciseStatus s = status_of(r, topic.name, e.name);
            // An exercise that did not run (its file does not build, is missing, or it is not
            // started) is not blamed on another: the file is the problem.
            if (!s.status || *s.status == Verdict::pass || *s.status == Verdict::not_started ||
                *s.status == Verdict::build_error || *s.status == Verdict::missing)
                continue;
            Blame b{topic.name, e.name, {}, ""};
            std::vector<std::string> parts;
            const auto calls = r.uses.find(topic.name + "/" + e.name);
            if (calls == r.uses.end()) continue;
            for (const auto& u : calls->second) {
                const ExerciseStatus c = status_of(r, topic.name, u);
                if (!c.status || *c.status == Verdict::pass) continue;  // not graded here, or it passes
                b.callees.push_back(u);
                parts.push_back(*c.status == Verdict::not_started
                                    ? "is not started"
                                    : "fails " + std::to_string(c.total - c.passed) + " of its " +
                                          std::to_string(c.total) + " test" + (c.total == 1 ? "" : "s"));
            }
            if (b.callees.empty()) continue;
            const bool none_started =
                std::all_of(parts.begin(), parts.end(), [](const std::string& p) { return p == "is not started"; });
            const std::string first = none_started ? "write " : "fix ";
            if (b.callees.size() == 1) {
                b.text = e.name + " calls your " + b.callees[0] + ", which " + parts[0] + ": " + first + "that first";
            } else {
                std::string list;
                for (std::size_t k = 0; k < b.callees.size(); ++k)
                    list += (k == 0                      ? ""
                             : k + 1 == b.callees.size() ? " and "
                                                         : ", ") +
                            b.callees[k] + " (" + parts[k].substr(parts[k].rfind("is ", 0) == 0 ? 3 : 0) + ")";
                b.text = e.name + " calls your " + list + ": " + first + "those first";
            }
            out.push_back(b);
        }
    return out;
}

namespace {

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    return "\"" + replace_all(s, "\"", "\"\"") + "\"";
}

std::string md_cell(const std::string& s) {
    std::string out = replace_all(replace_all(s, "|", "\\|"), "\n", " ");
    return out;
}

}  // namespace

std::string class_csv(const Setup& setup, const std::vector<SubmissionResult>& results) {
    std::string out = "student,score,max_score,tests_passed,tests";
    for (const auto& topic : setup.topics)
        for (const auto& e : topic.exercises) out += "," + csv_field(topic.chapter + " " + e.name);
    out += ",problems\n";
    for (const auto& r : results) {
        int passed = 0;
        for (const auto& t : r.tests) passed += t.verdict == Verdict::pass;
        out += csv_field(r.student) + "," + format_number(r.score) + "," + format_number(r.max_score) + "," +
               std::to_string(passed) + "," + std::to_string(r.tests.size());
        for (const auto& topic : setup.topics)
            for (const auto& e : topic.exercises) out += "," + format_number(status_of(r, topic.name, e.name).score);
        std::string notes;
        for (const auto& n : r.notes) notes += (notes.empty() ? "" : "; ") + n;
        out += "," + csv_field(notes) + "\n";
    }
    return out;
}

std::string class_summary(const Setup& setup, const std::vector<SubmissionResult>& results,
                          const std::vector<std::string>& ignored) {
    std::size_t exercises = 0, tests = 0;
    double points = 0;
    for (const auto& topic : setup.topics)
        for (const auto& e : topic.exercises) ++exercises, tests += e.tests.size(), points += e.points;
    std::string out = "# Grading summary\n\n";
    out += std::to_string(results.size()) + " submissions, graded on " + std::to_string(setup.topics.size()) +
           " topics, " + std::to_string(exercises) + " exercises, " + std::to_string(tests) + " tests, " +
           format_number(points) + " points (harness " + harness_version + ", instructor files " + setup.fingerprint +
           ").\n\n";
    out +=
        "Verdicts are counted per test. Per-student results: `results/<student>.json` (Gradescope's\n"
        "results.json format); build logs: `logs/<student>/`; all scores: `class.csv`.\n\n";
    out += "| Student | Score | Pass | Fail | Timeout | Crash | Build error | Missing |\n";
    out += "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& r : results) {
        std::map<Verdict, int> count;
        for (const auto& t : r.tests) ++count[t.verdict];
        out += "| " + md_cell(r.student) + " | " + format_number(r.score) + " / " + format_number(r.max_score);
        for (const Verdict v : test_verdicts) out += " | " + std::to_string(count[v]);
        out += " |\n";
    }
    out += "\n## Exercises\n\nHow many submissions pass each exercise completely.\n\n";
    out += "| Chapter | Exercise | Points | Pass | Not started | Other |\n|---|---|---:|---:|---:|---:|\n";
    for (const auto& topic : setup.topics) {
        const Chapter* c = find_chapter(setup, topic.chapter);
        for (const auto& e : topic.exercises) {
            int pass = 0, not_started = 0;
            for (const auto& r : results) {
                const auto s = status_of(r, topic.name, e.name).status;
                pass += s == Verdict::pass;
                not_started += s == Verdict::not_started;
            }
            out += "| " + (c ? std::to_string(c->number) + ". " + md_cell(c->title) : topic.chapter) + " | `" + e.name +
                   "` | " + format_number(e.points) + " | " + std::to_string(pass) + " | " +
                   std::to_string(not_started) + " | " +
                   std::to_string(static_cast<int>(results.size()) - pass - not_started) + " |\n";
        }
    }
    bool any = false;
    for (const auto& r : results)
        for (const auto& n : r.notes) {
            if (!any) out += "\n## Files that were missing, refused or did not build\n\n", any = true;
            out += "- " + md_cell(r.student) + ": " + md_cell(n) + "\n";
        }
    if (!ignored.empty()) {
        out += "\n## Not graded\n\n";
        for (const auto& i : ignored) out += "- " + md_cell(i) + "\n";
    }
    return out;
}

// Hint 1 of the exercise's ladder, as the terminal shows it (hints.cpp).
std::string hint_for(const Setup& setup, const std::string& exercise) {
    const hints::Hints h = hints::read(setup.root + "/exercises/hints.md");
    const hints::Ladder* ladder = h.error.empty() ? hints::find(h, exercise) : nullptr;
    return ladder ? hints::for_terminal(*ladder, 1) : h.error.empty() ? "" : "\n" + h.error + "\n";
}

namespace {

// An exercise that does not pass, with the test that shows it.
struct Problem {
    std::string topic, exercise;
    Verdict status;
    const TestResult* test;
};

struct Tally {
    std::vector<Problem> problems;
    int pass = 0, total = 0;
};

// One table per chapter: each selected exercise's status (and for a partial pass, how many tests
// pass); collects the exercises that do not pass.
Tally print_chapters(const Setup& setup, const SubmissionResult& r) {
    Tally tally;
    const std::vector<Blame> blamed = blame(setup, r);
    for (const auto& chapter : setup.chapters) {
        std::vector<std::pair<std::string, ExerciseStatus>> rows;
        for (const auto& topic : setup.topics) {
            if (topic.chapter != chapter.label) continue;
            for (const auto& e : topic.exercises) {
                const ExerciseStatus s = status_of(r, topic.name, e.name);
                if (!s.status) continue;  // not selected
                rows.emplace_back(e.name, s);
                if (s.status != Verdict::pass)
                    tally.problems.push_back({topic.name, e.name, *s.status, s.first_problem});
            }
        }
        if (rows.empty()) continue;
        int pass = 0;
        for (const auto& [name, s] : rows) pass += s.status == Verdict::pass;
        tally.pass += pass;
        tally.total += static_cast<int>(rows.size());
        std::printf("\nChapter %d, %s: %d of %zu exercises pass\n", chapter.number, chapter.title.c_str(), pass,
                    rows.size());
        for (const auto& [name, s] : rows) {
            std::string detail;
            if (s.status != Verdict::pass && s.status != Verdict::not_started && s.status != Verdict::missing &&
                s.status != Verdict::build_error)
                detail = std::to_string(s.passed) + " of " + std::to_string(s.total) + " tests pass";
            for (const auto& b : blamed)
                if (b.exercise == name) {
                    std::string list;
                    for (const auto& c : b.callees) list += (list.empty() ? "" : ", ") + c;
                    detail += "; it calls your " + list +
                              (b.callees.size() == 1 ? ", which does not pass" : ", which do not pass");
                }
            char row[256];
            std::snprintf(row, sizeof row, "  %-12s %-26s %s", to_string(*s.status).c_str(), name.c_str(),
                          detail.c_str());
            std::printf("%s\n", trim(row).insert(0, "  ").c_str());
        }
    }
    return tally;
}

// The first exercise to work on: the first one that fails, else the first not started.
const Problem& first_problem(const std::vector<Problem>& problems) {
    for (const auto& p : problems)
        if (p.status != Verdict::not_started) return p;
    return problems.front();
}

// What the student sees of that exercise: its failing test and message (or that it is not
// started), then a nudge: Hint 1 for a started exercise, the command for the next rungs otherwise.
void print_first(const Setup& setup, const SubmissionResult& r, const Problem& first, const std::string& folder) {
    const TestResult& t = *first.test;
    std::printf("\n%s: %s (%s/%s.cpp)\n",
                first.status == Verdict::not_started ? "Next exercise" : "First exercise to fix",
                first.exercise.c_str(), folder.c_str(), first.topic.c_str());
    if (first.status == Verdict::not_started) {
        std::printf("  not started: its body is still todo(\"%s\")\n", first.exercise.c_str());
        std::printf("  a hint when you want one: cmake/workbook check %s --hint 1\n", first.exercise.c_str());
        return;
    }
    for (const auto& b : blame(setup, r))
        if (b.topic == first.topic && b.exercise == first.exercise)
            std::printf("  %s (cmake/workbook check %s)\n", b.text.c_str(), b.callees.front().c_str());
    std::printf("  test: %s\n  %s", t.name.c_str(), to_string(t.verdict).c_str());
    if (t.verdict == Verdict::fail || t.verdict == Verdict::build_error || t.verdict == Verdict::missing) {
        std::printf(":\n");
        for (const auto& line : split(t.message, '\n')) std::printf("    %s\n", line.c_str());
    } else {
        std::printf(": %s\n", t.message.c_str());
    }
    if (!t.output.empty()) {
        std::printf("  the test printed:\n");
        for (const auto& line : split(t.output, '\n')) std::printf("    %s\n", line.c_str());
    }
    for (const auto& n : mistakes::name(mistakes::for_root(setup.root), mistakes::outcomes_of(r)))
        if (n.topic == first.topic && n.exercise == first.exercise) std::printf("  %s\n", n.text().c_str());
    std::printf("%s", hint_for(setup, first.exercise).c_str());
}

}  // namespace

bool print_check(const Setup& setup, const SubmissionResult& r, const std::string& folder) {
    const Tally tally = print_chapters(setup, r);
    if (tally.problems.empty()) {
        std::printf("\nAll %d exercises pass.\n", tally.total);
        return true;
    }
    const Problem& first = first_problem(tally.problems);
    if (first.status == Verdict::build_error || first.status == Verdict::missing) {
        // The whole file is the problem, not one exercise.
        const TestResult& t = *first.test;
        std::printf("\n%s/%s.cpp: %s\n  %s\n", folder.c_str(), first.topic.c_str(),
                    first.status == Verdict::missing ? "not graded" : "does not build", t.message.c_str());
        const Chapter* c = find_chapter(setup, t.chapter);
        std::printf("\n%d of %d exercises pass. Check this chapter alone: cmake/workbook check %s\n", tally.pass,
                    tally.total, c ? std::to_string(c->number).c_str() : t.chapter.c_str());
        return false;
    }
    print_first(setup, r, first, folder);
    if (tally.total > 1)
        std::printf("\n%d of %d exercises pass. Check this one alone: cmake/workbook check %s\n", tally.pass,
                    tally.total, first.exercise.c_str());
    return false;
}

}  // namespace grading
