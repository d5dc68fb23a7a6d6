// class_report.html and its plots: the item analysis as a page (item_analysis.hpp). The plots are
// SVG files in <out>/report/, each drawn by gnuplot from a script and a data file written beside
// it (support::run, an argument vector: no shell). The scripts are report/*.gp beside this file,
// embedded at build time (grading::gp::..., class_report.gp.hpp) and filled by support::filled:
// report/head.gp, then the plot's own. Without gnuplot the page says so and keeps the tables. The
// page needs nothing from outside the out folder: no script, font or stylesheet.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "class_report.gp.hpp"
#include "item_analysis.hpp"
#include "mistakes.hpp"
#include "support/process.hpp"
#include "support/script.hpp"

namespace grading {

namespace {

std::string html(const std::string& s) {
    std::string out;
    for (const char c : s) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

// A path as a gnuplot single-quoted string ('' is a quote inside one).
std::string quoted(const std::string& s) { return support::gnuplot_quoted(s); }

std::string fixed(double x, int digits = 2) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, x);
    return std::string(text) == "-0.00" ? "0.00" : text;
}

// The script of the plot `name`: report/head.gp (terminal, output, style), then its own, filled.
std::string plot_script(const std::string& name, int width, int height, const support::Script& body,
                        const support::Fill& values) {
    return support::filled(
               gp::head,
               {{"width", std::to_string(width)}, {"height", std::to_string(height)}, {"svg", quoted(name + ".svg")}}) +
           support::filled(body, values);
}

// A plot: its data and script in dir, drawn by gnuplot. Returns "" or what went wrong.
std::string draw(const std::string& dir, const std::string& name, const std::string& data, const std::string& script) {
    if (!write_file(dir + "/" + name + ".dat", data) || !write_file(dir + "/" + name + ".gp", script))
        return "cannot write " + dir + "/" + name + ".gp";
    support::RunOptions options;
    options.timeout = 120;
    // In its folder (gnuplot's own cd): the script names its files without a path, so that the
    // report's files are the same bytes wherever the out folder is.
    const support::Result r = support::run({"gnuplot", "-e", "cd " + quoted(dir), dir + "/" + name + ".gp"}, options);
    if (r.status == -1) return "gnuplot could not start (" + r.error + ")";
    if (r.status != 0) return "gnuplot failed on " + name + ".gp: " + first_lines(r.err, 300);
    return {};
}

std::string plot_totals(const ItemAnalysis& a, const std::string& dir) {
    const double width = std::max(1.0, std::ceil(a.max_total / 40));
    const int bins = std::max(1, static_cast<int>(std::ceil(a.max_total / width)));
    std::vector<int> count(static_cast<std::size_t>(bins), 0);
    for (const double t : a.totals)
        ++count[static_cast<std::size_t>(std::clamp(static_cast<int>(t / width), 0, bins - 1))];
    std::string data = "# bin start\tsubmissions (the last bin includes the maximum)\n";
    for (int k = 0; k < bins; ++k)
        data += format_number(k * width) + "\t" + std::to_string(count[static_cast<std::size_t>(k)]) + "\n";
    return draw(dir, "totals", data,
                plot_script("totals", 900, 360, gp::totals,
                            {{"submissions", std::to_string(a.submissions)},
                             {"max_total", format_number(a.max_total)},
                             {"box_width", format_number(width * 0.9)},
                             {"xmax", format_number(bins * width)},
                             {"half_width", format_number(width / 2)}}));
}

std::string plot_exercises(const ItemAnalysis& a, const std::string& dir) {
    std::string data = "# index\texercise\tshare passing every test\tshare started\n";
    const double n = std::max(1, a.submissions);
    for (std::size_t k = 0; k < a.exercises.size(); ++k)
        data += std::to_string(k) + "\t" + a.exercises[k].exercise + "\t" + fixed(a.exercises[k].passed / n, 4) + "\t" +
                fixed(a.exercises[k].started / n, 4) + "\n";
    const int width = std::max(900, 14 * static_cast<int>(a.exercises.size()) + 160);
    return draw(dir, "exercises", data, plot_script("exercises", width, 560, gp::exercises, {}));
}

std::string plot_tests(const ItemAnalysis& a, const std::string& topic, const std::string& dir) {
    std::string data = "# number\ttest\tpass\tfail\tcrash or timeout\tbuild error or missing\tnot started\n";
    int k = 0;
    for (const auto& r : a.tests) {
        if (r.topic != topic) continue;
        const double n = std::max(1, r.results);
        const auto& c = r.counts;  // pass, fail, timeout, crash, build error, missing, not started
        ++k;
        data += std::to_string(k) + "\t" + std::to_string(k) + "\t" + fixed(c[0] / n, 4) + "\t" + fixed(c[1] / n, 4) +
                "\t" + fixed((c[2] + c[3]) / n, 4) + "\t" + fixed((c[4] + c[5]) / n, 4) + "\t" + fixed(c[6] / n, 4) +
                "\n";
    }
    const std::string name = "tests_" + topic;
    return draw(dir, name, data,
                plot_script(name, std::max(900, 16 * k + 260), 380, gp::tests,
                            {{"topic", topic}, {"data", quoted(name + ".dat")}}));
}

const char* style =
    "<style>body{font-family:sans-serif;max-width:1200px;margin:1em auto;padding:0 1em;color:#222}"
    "img{max-width:100%;height:auto;border:1px solid #ddd}table{border-collapse:collapse;font-size:90%;margin:1em 0}"
    "td,th{border:1px solid #ccc;padding:2px 6px;vertical-align:top}td.n{text-align:right}"
    "code{font-size:85%;overflow-wrap:anywhere}.note{background:#fff3cd;padding:.5em 1em}</style>\n";

std::string topic_table(const ItemAnalysis& a, const std::string& topic) {
    std::string out =
        "<table><tr><th>#</th><th>Exercise</th><th>Test</th><th>Pass</th><th>Fail</th><th>Timeout</th>"
        "<th>Crash</th><th>Build error</th><th>Missing</th><th>Not started</th><th>D</th>"
        "<th>Most common failing check</th><th>Typical value</th></tr>\n";
    int k = 0;
    for (const auto& r : a.tests) {
        if (r.topic != topic) continue;
        out += "<tr><td class=n>" + std::to_string(++k) + "</td><td><code>" + html(r.exercise) + "</code></td><td>" +
               html(r.test) + "</td>";
        for (const int n : r.counts) out += "<td class=n>" + std::to_string(n) + "</td>";
        out += "<td class=n>" + (r.discrimination ? fixed(*r.discrimination) : "n/a") + "</td><td>" +
               (r.check.empty() ? "" : "<code>" + html(r.check) + "</code> (" + std::to_string(r.check_count) + ")") +
               "</td><td>" + (r.typical.empty() ? "" : "<code>" + html(r.typical) + "</code>") + "</td></tr>\n";
    }
    return out + "</table>\n";
}

std::string exercise_table(const ItemAnalysis& a) {
    std::string out =
        "<table><tr><th>Chapter</th><th>Exercise</th><th>Points</th><th>Tests</th><th>Started</th>"
        "<th>Pass every test</th></tr>\n";
    for (const auto& e : a.exercises)
        out += "<tr><td>" + html(e.chapter) + "</td><td><code>" + html(e.exercise) + "</code></td><td class=n>" +
               format_number(e.points) + "</td><td class=n>" + std::to_string(e.tests) + "</td><td class=n>" +
               std::to_string(e.started) + "</td><td class=n>" + std::to_string(e.passed) + "</td></tr>\n";
    return out + "</table>\n";
}

std::string figure(const std::string& name, const std::string& alt, bool drawn) {
    return drawn ? "<p><img src=\"report/" + name + ".svg\" alt=\"" + html(alt) + "\"></p>\n" : "";
}

// The likely mistakes the class's results name (mistakes.hpp), commonest first: as Markdown for
// item_analysis.md, or as HTML for the page. Empty when no result names one.
std::string mistakes_section(const std::vector<mistakes::ClassCount>& counts, bool as_html) {
    if (counts.empty()) return "";
    const std::string intro =
        "Failing exercises whose pattern of failures is what a catalogued wrong version (the mutation gate's) "
        "gives; likely, not certain: read the code.";
    std::string out = as_html ? "<h2>Likely mistakes across the class</h2>\n<p>" + html(intro) +
                                    "</p>\n<table><tr><th>Students</th><th>Exercise</th><th>Likely mistake</th></tr>\n"
                              : "\n## Likely mistakes across the class\n\n" + intro +
                                    "\n\n| Students | Exercise | Likely mistake |\n|---:|---|---|\n";
    for (const auto& c : counts) {
        if (as_html)
            out += "<tr><td class=n>" + std::to_string(c.students) + "</td><td><code>" + html(c.exercise) +
                   "</code> (" + html(c.topic) + ")</td><td>" + html(c.mistake) + "</td></tr>\n";
        else
            out += "| " + std::to_string(c.students) + " | `" + c.exercise + "` (" + c.topic + ") | " +
                   replace_all(c.mistake, "|", "\\|") + " |\n";
    }
    return out + (as_html ? "</table>\n" : "");
}

std::string page(const ItemAnalysis& a, const std::vector<std::string>& topics, const std::string& problem,
                 const std::string& likely) {
    const bool drawn = problem.empty();
    std::string out = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Class report</title>\n";
    out += std::string(style) + "</head><body>\n<h1>Class report</h1>\n<p>" + std::to_string(a.submissions) +
           " submissions, " + std::to_string(a.exercises.size()) + " exercises, " + std::to_string(a.tests.size()) +
           " tests. The same numbers as tables: <code>item_analysis.md</code> and <code>item_analysis.csv</code>; "
           "per student: <code>summary.md</code>, <code>results/&lt;student&gt;.json</code>.</p>\n";
    if (!drawn) out += "<p class=note>No plots: " + html(problem) + ". The tables below hold every number.</p>\n";
    if (!a.ranking.empty()) out += "<p class=note>Discrimination (D) not computed: " + html(a.ranking) + ".</p>\n";
    out += "<h2>Totals</h2>\n" + figure("totals", "histogram of the class's total scores", drawn);
    out += "<h2>Exercises</h2>\n" + figure("exercises", "share of submissions passing each exercise", drawn);
    out += exercise_table(a);
    out +=
        "<p>D is the pass rate of the top third of the class by total minus that of the bottom third "
        "(ties at a third's boundary share its places); <em>started</em>: the file differs from the stub "
        "and the exercise's <code>todo</code> is gone (item_analysis.md says exactly how).</p>\n";
    for (const auto& topic : topics)
        out += "<h2>Tests of " + html(topic) + "</h2>\n" +
               figure("tests_" + topic, "verdicts of each test of " + topic, drawn) + topic_table(a, topic);
    return out + likely + "</body></html>\n";
}

}  // namespace

std::string write_item_analysis(const Setup& setup, const std::vector<SubmissionResult>& results,
                                const std::vector<ClassFiles>& files, const std::string& out) {
    const ItemAnalysis a = analyse_items(setup, results, files);
    write_file(out + "/item_analysis.csv", item_analysis_csv(a));
    const auto likely = mistakes::count_in_class(out + "/results");
    write_file(out + "/item_analysis.md", item_analysis_markdown(a) + mistakes_section(likely, false));
    const std::string dir = out + "/report";
    remove_tree(dir);
    make_dirs(dir);
    std::vector<std::string> topics;
    for (const auto& t : setup.topics) topics.push_back(t.name);
    std::string problem = plot_totals(a, dir);
    if (problem.empty()) problem = plot_exercises(a, dir);
    for (const auto& t : topics)
        if (problem.empty()) problem = plot_tests(a, t, dir);
    write_file(out + "/class_report.html", page(a, topics, problem, mistakes_section(likely, true)));
    return "Item analysis: " + out + "/item_analysis.md, .csv and " + out + "/class_report.html" +
           (problem.empty() ? "" : " (no plots: " + problem + ")");
}

}  // namespace grading
