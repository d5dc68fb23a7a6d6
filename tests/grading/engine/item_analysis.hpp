// The item analysis of a class run (issue 33): what the class did on each test, written by every
// run that writes the class files (workbook_grade grade, cmake/workbook grade) beside summary.md.
//
//   item_analysis.csv   one row per test of every graded topic: the verdict counts, the pass rates
//                       of the top and bottom thirds and their difference (the discrimination),
//                       the most common failing check and a typical value it saw;
//   item_analysis.md    the same as tables, with one table per exercise's "started" count first;
//   class_report.html   the page for the instructor: the plots (report/*.svg, drawn by gnuplot at
//                       run time from report/*.gp and report/*.dat) above the same tables. It opens
//                       offline: no script, no font, no file from outside the out folder.
//
// Definitions (also written at the top of item_analysis.md):
// - Verdicts per test, from TestResult: pass, fail, timeout, crash, build error, missing, and not
//   started (a test that failed on the stub's todo("<exercise>"): counted there, not under fail).
//   Each submission with a result for the test counts once, so the seven columns add up to them.
// - Discrimination: the class ranked by total score; the top third and the bottom third are each
//   exactly n/3 students' worth of weight. Students tied on the score at a third's boundary share
//   the places left equally (a fractional weight each), so the result does not depend on the order
//   of the folders. D = (pass rate of the top third) - (pass rate of the bottom third), from -1 to
//   1. The total includes the test itself. Not computed ("n/a") below 6 submissions (a third of
//   fewer than 2 students) or when every total is the same (no ranking).
// - The most common failing check: the first line of the message of each failed test (verdict
//   fail, not "not started"), "file:line: CHECK( expression ) failed", or its first sentence when
//   the test failed otherwise (an exception); the most frequent, ties to the first in text order.
//   Its typical value: the doctest expansion ("with values: ...") most frequent among the
//   submissions failing that check, ties to the first student in folder order.
// - An exercise is started by a submission when its topic's file was taken (not missing or
//   refused), differs from the committed stub (pristine_stub) other than in white space, and
//   either some test of the exercise ran without failing on todo("<exercise>"), or, when none ran
//   (a build error), the file no longer contains todo("<exercise>").
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "grading.hpp"

namespace grading {

// The verdict columns of the item analysis, in this order.
inline constexpr std::array<Verdict, 7> item_verdicts = {Verdict::pass,       Verdict::fail,        Verdict::timeout,
                                                         Verdict::crash,      Verdict::build_error, Verdict::missing,
                                                         Verdict::not_started};

struct ItemRow {
    std::string chapter, topic, exercise, test;
    std::array<int, item_verdicts.size()> counts{};  // in the order of item_verdicts
    int results = 0;                                 // submissions with a result for this test
    double top = 0, bottom = 0;                      // pass rates of the two thirds
    std::optional<double> discrimination;            // none: n/a (see above)
    std::string check;                               // the most common failing check ("" when none failed)
    int check_count = 0;                             // how many failed on it
    std::string typical;                             // a typical value it saw ("" when doctest showed none)
};

struct ExerciseRow {
    std::string chapter, topic, exercise;
    double points = 0;
    int tests = 0, started = 0, passed = 0;  // passed: every test of it passes
};

struct ItemAnalysis {
    int submissions = 0;
    std::string ranking;  // "" when the discrimination is computed, else why not
    std::vector<double> totals;
    double max_total = 0;
    std::vector<ExerciseRow> exercises;
    std::vector<ItemRow> tests;
};

// Weights of each student in the top (top = true) or bottom third of `totals` (see above).
std::vector<double> third_weights(const std::vector<double>& totals, bool top);
// The most common failing check's parts of one message: its first line, and its doctest values.
std::string failing_check(const std::string& message);
std::string check_values(const std::string& message);

// `files` are the same students as `results`, in the same order (for "started").
ItemAnalysis analyse_items(const Setup& setup, const std::vector<SubmissionResult>& results,
                           const std::vector<ClassFiles>& files);
std::string item_analysis_csv(const ItemAnalysis& a);
std::string item_analysis_markdown(const ItemAnalysis& a);
// Writes item_analysis.csv, item_analysis.md, class_report.html and report/ in out. Returns a line
// for the terminal (and says when gnuplot was missing: the page then has the tables alone).
std::string write_item_analysis(const Setup& setup, const std::vector<SubmissionResult>& results,
                                const std::vector<ClassFiles>& files, const std::string& out);

}  // namespace grading
