// The item analysis of a class run (item_analysis.hpp has the definitions).
#include "item_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>

namespace grading {

// ---- the numbers -----------------------------------------------------------------------------

std::vector<double> third_weights(const std::vector<double>& totals, bool top) {
    std::vector<double> weight(totals.size(), 0.0);
    std::vector<double> scores = totals;
    std::sort(scores.begin(), scores.end());
    scores.erase(std::unique(scores.begin(), scores.end()), scores.end());
    if (top) std::reverse(scores.begin(), scores.end());
    double left = static_cast<double>(totals.size()) / 3.0;  // places left in the third
    for (const double s : scores) {
        if (left <= 0) break;
        const auto tied = static_cast<double>(std::count(totals.begin(), totals.end(), s));
        const double each = std::min(1.0, left / tied);
        for (std::size_t k = 0; k < totals.size(); ++k)
            if (totals[k] == s) weight[k] = each;
        left -= each * tied;
    }
    return weight;
}

namespace {

std::size_t cut_at(const std::string& s, std::size_t from) {
    const std::size_t line = s.find('\n', from), flat = s.find("   ", from);  // the .tsv flattens lines
    return std::min(line, flat);
}

}  // namespace

std::string failing_check(const std::string& message) {
    const std::size_t failed = message.find(") failed");
    const std::size_t end = cut_at(message, 0);
    if (failed != std::string::npos && failed < end) return message.substr(0, failed + 8);
    return trim(message.substr(0, end));
}

std::string check_values(const std::string& message) {
    const std::string marker = "with values: ";
    const std::size_t at = message.find(marker);
    if (at == std::string::npos) return {};
    const std::size_t from = at + marker.size();
    const std::size_t end = cut_at(message, from);
    return trim(message.substr(from, end == std::string::npos ? std::string::npos : end - from));
}

namespace {

std::string without_space(const std::string& s) {
    std::string out;
    for (const char c : s)
        if (!std::isspace(static_cast<unsigned char>(c))) out += c;
    return out;
}

// Started, as item_analysis.hpp defines it, for each exercise of the topic's file.
bool started(const SubmittedFile* file, const std::string& stub, const std::vector<const TestResult*>& tests,
             const std::string& exercise) {
    if (!file || file->state != "ok" || without_space(file->content) == without_space(stub)) return false;
    bool ran = false;
    for (const TestResult* t : tests) {
        if (t->verdict == Verdict::build_error || t->verdict == Verdict::missing) continue;
        ran = true;
        if (!t->not_started) return true;
    }
    return !ran && file->content.find("todo(\"" + exercise + "\")") == std::string::npos;
}

// The most frequent of the values, ties to the first given (values in student order).
std::pair<std::string, int> most_common(const std::vector<std::string>& values, bool ties_to_smallest) {
    std::map<std::string, int> count;
    for (const auto& v : values) ++count[v];
    std::pair<std::string, int> best{"", 0};
    if (ties_to_smallest) {
        for (const auto& [v, n] : count)
            if (n > best.second) best = {v, n};
    } else {
        for (const auto& v : values)
            if (count[v] > best.second) best = {v, count[v]};
    }
    return best;
}

// One test's row: counts, the two thirds' pass rates, the most common failing check.
ItemRow item_row(const Topic& topic, const Exercise& e, const Test& test, const std::vector<SubmissionResult>& results,
                 const std::vector<double>& top, const std::vector<double>& bottom) {
    ItemRow row{topic.chapter, topic.name, e.name, test.name, {}, 0, 0, 0, std::nullopt, "", 0, ""};
    std::vector<std::string> checks, messages;
    double top_pass = 0, bottom_pass = 0;
    for (std::size_t s = 0; s < results.size(); ++s)
        for (const auto& t : results[s].tests) {
            if (t.topic != topic.name || t.exercise != e.name || t.name != test.name) continue;
            const Verdict v = t.not_started ? Verdict::not_started : t.verdict;
            ++row.counts[static_cast<std::size_t>(std::find(item_verdicts.begin(), item_verdicts.end(), v) -
                                                  item_verdicts.begin())];
            ++row.results;
            top_pass += top[s] * (v == Verdict::pass);
            bottom_pass += bottom[s] * (v == Verdict::pass);
            if (v == Verdict::fail) checks.push_back(failing_check(t.message)), messages.push_back(t.message);
        }
    const double third = static_cast<double>(results.size()) / 3.0;
    row.top = third > 0 ? top_pass / third : 0;
    row.bottom = third > 0 ? bottom_pass / third : 0;
    std::tie(row.check, row.check_count) = most_common(checks, true);
    std::vector<std::string> values;
    for (std::size_t k = 0; k < checks.size(); ++k)
        if (checks[k] == row.check) values.push_back(check_values(messages[k]));
    row.typical = most_common(values, false).first;
    return row;
}

}  // namespace

ItemAnalysis analyse_items(const Setup& setup, const std::vector<SubmissionResult>& results,
                           const std::vector<ClassFiles>& files) {
    ItemAnalysis a;
    a.submissions = static_cast<int>(results.size());
    for (const auto& r : results) a.totals.push_back(r.score), a.max_total = std::max(a.max_total, r.max_score);
    const bool all_equal =
        std::adjacent_find(a.totals.begin(), a.totals.end(), std::not_equal_to<>()) == a.totals.end();
    if (a.submissions < 6)
        a.ranking = "fewer than 6 submissions: a third would hold fewer than 2 students";
    else if (all_equal)
        a.ranking = "every submission has the same total: there is no ranking";
    const std::vector<double> top = third_weights(a.totals, true), bottom = third_weights(a.totals, false);
    for (const auto& topic : setup.topics) {
        bool ok = false;
        const std::string stub = read_file(pristine_stub(setup, topic.name), &ok);
        for (const auto& e : topic.exercises) {
            ExerciseRow ex{topic.chapter, topic.name, e.name, e.points, static_cast<int>(e.tests.size()), 0, 0};
            for (std::size_t s = 0; s < results.size(); ++s) {
                std::vector<const TestResult*> tests;
                for (const auto& t : results[s].tests)
                    if (t.topic == topic.name && t.exercise == e.name) tests.push_back(&t);
                const SubmittedFile* file = nullptr;
                if (s < files.size())
                    for (const auto& f : files[s].files)
                        if (f.topic == topic.name) file = &f;
                ex.started += ok && started(file, stub, tests, e.name);
                ex.passed += !tests.empty() && std::all_of(tests.begin(), tests.end(), [](const TestResult* t) {
                    return t->verdict == Verdict::pass;
                });
            }
            a.exercises.push_back(ex);
            for (const auto& test : e.tests) {
                a.tests.push_back(item_row(topic, e, test, results, top, bottom));
                if (a.ranking.empty()) a.tests.back().discrimination = a.tests.back().top - a.tests.back().bottom;
            }
        }
    }
    return a;
}

// ---- the tables ------------------------------------------------------------------------------
namespace {

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    return "\"" + replace_all(s, "\"", "\"\"") + "\"";
}

std::string md_cell(const std::string& s) { return replace_all(replace_all(s, "|", "\\|"), "\n", " "); }

std::string fixed(double x, int digits = 2) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, x);
    return std::string(text) == "-0.00" ? "0.00" : text;
}

std::string rate(int n, int of) { return of > 0 ? fixed(static_cast<double>(n) / of) : "n/a"; }

std::string short_text(const std::string& s, std::size_t n = 160) { return s.size() <= n ? s : s.substr(0, n) + "..."; }

}  // namespace

std::string item_analysis_csv(const ItemAnalysis& a) {
    std::string out = "chapter,topic,exercise,test,submissions";
    for (const Verdict v : item_verdicts) out += "," + replace_all(to_string(v), " ", "_");
    out +=
        ",pass_rate,top_third_pass_rate,bottom_third_pass_rate,discrimination,common_check,common_check_count,"
        "typical_value\n";
    for (const auto& r : a.tests) {
        out += csv_field(r.chapter) + "," + csv_field(r.topic) + "," + csv_field(r.exercise) + "," + csv_field(r.test) +
               "," + std::to_string(r.results);
        for (const int n : r.counts) out += "," + std::to_string(n);
        out += "," + rate(r.counts[0], r.results) + "," + fixed(r.top, 4) + "," + fixed(r.bottom, 4) + "," +
               (r.discrimination ? fixed(*r.discrimination, 4) : "n/a") + "," + csv_field(r.check) + "," +
               std::to_string(r.check_count) + "," + csv_field(r.typical) + "\n";
    }
    return out;
}

namespace {

const char* definitions =
    "Verdicts are counted per test, one per submission with a result for it; *not started* is a\n"
    "test that failed on the stub's `todo(\"<exercise>\")`, counted apart from *fail*. **D**, the\n"
    "discrimination: the pass rate of the top third of the class by total score minus that of the\n"
    "bottom third (from -1 to 1; near 0: the test does not separate strong from weak submissions;\n"
    "negative: the weak pass it more often). Each third is n/3 students' worth: students tied at a\n"
    "third's boundary share its places left equally. Not computed below 6 submissions or when every\n"
    "total is the same. The most common failing check is the first line of each failed test's\n"
    "message; its typical value is doctest's expansion seen most often with it (ties: the first\n"
    "student in folder order). An exercise is *started* when its file was submitted, differs from\n"
    "the committed stub in more than white space, and either a test of it ran without failing on\n"
    "its `todo`, or (when the file did not build) the file no longer holds its `todo(\"<name>\")`.\n\n";

std::string exercise_table(const ItemAnalysis& a) {
    std::string out = "## Exercises\n\n| Chapter | Exercise | Points | Tests | Started | Pass (every test) |\n";
    out += "|---|---|---:|---:|---:|---:|\n";
    for (const auto& e : a.exercises)
        out += "| " + e.chapter + " | `" + e.exercise + "` | " + format_number(e.points) + " | " +
               std::to_string(e.tests) + " | " + std::to_string(e.started) + " | " + std::to_string(e.passed) + " |\n";
    return out;
}

}  // namespace

std::string item_analysis_markdown(const ItemAnalysis& a) {
    std::string out = "# Item analysis\n\n" + std::to_string(a.submissions) + " submissions, " +
                      std::to_string(a.exercises.size()) + " exercises, " + std::to_string(a.tests.size()) + " tests" +
                      (a.ranking.empty() ? "" : "; discrimination not computed: " + a.ranking) + ".\n\n";
    out += definitions + exercise_table(a);
    std::string topic;
    for (const auto& r : a.tests) {
        if (r.topic != topic) {
            topic = r.topic;
            out += "\n## " + topic + " (" + r.chapter +
                   ")\n\n| Test | Pass | Fail | Timeout | Crash | Build error | "
                   "Missing | Not started | D | Most common failing check | Typical value |\n"
                   "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n";
        }
        out += "| " + md_cell(r.test);
        for (const int n : r.counts) out += " | " + std::to_string(n);
        out +=
            " | " + (r.discrimination ? fixed(*r.discrimination) : "n/a") + " | " +
            (r.check.empty() ? "" : "`" + md_cell(short_text(r.check)) + "` (" + std::to_string(r.check_count) + ")") +
            " | " + (r.typical.empty() ? "" : "`" + md_cell(short_text(r.typical, 80)) + "`") + " |\n";
    }
    return out;
}

}  // namespace grading
