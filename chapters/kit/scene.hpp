// The scene kit: what every chapter driver ("scene") shares, and nothing else.
//
//   * named options with --help, the common --out DIR, --no-figure, --json and --budget, and
//     --list-options (every option, its default and its accepted range, as JSON);
//   * one clear message and exit status 2 for bad input, 1 for a numerical failure;
//   * a time budget: a scene estimates its work before it starts and refuses a request over
//     the budget (require_budget); a watchdog stops one that overruns it all the same;
//   * a report that puts the scene's error next to its run time (text or JSON);
//   * figures staged and published only when the whole scene succeeded (figure.hpp).
//
// A scene is a small main(): its parameters are the fields of a struct, each bound to a named
// option with its range and help; parse, compute, report and draw are named steps.
//
//   struct Params {
//       double alpha = 1.0;  // the default is the field's initial value
//   };
//   void declare(kit::Options& opts, Params& p) {
//       opts.real("alpha", &p.alpha, "rotation frequency", kit::between(1e-6, 1e6));
//   }
//   int main(int argc, char** argv) {
//       Params p;
//       kit::Options opts("my_scene", "Chapter N: what it shows");
//       declare(opts, p);
//       return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
//           report(scene, compute(p));  // scene.report.headline(...), kit::Figure fig(scene, "x.svg"); ...
//       });
//   }
//
// An option the scene does not declare (a typo, an option of another scene) is refused at the
// start, with the list of the options the scene has.
#pragma once

#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "rigid/types.hpp"

namespace CLI {
class App;  // CLI11 (<CLI/CLI.hpp>), which reads the command line: scene.cpp alone includes it
}

namespace kit {

// Bad input: exit status 2, the message names the option and the rule it breaks.
struct BadInput : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A numerical failure (NaN, a solver that gave up): exit status 1, the message says why.
struct NumericalFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The range a number must lie in, lo <= x <= hi, both finite: every numeric option declares
// what its scene can do, and --list-options gives it to the corner sweep of the test suite.
struct Rule {
    std::string text;  // e.g. "a number in [1e-06, 1e+06]"
    double lo, hi;
    bool holds(double x) const { return std::isfinite(x) && x >= lo && x <= hi; }
};
Rule between(double lo, double hi);

// The same for a 3-vector: every component in [lo, hi]; with nonzero, not all of them zero.
struct VecRule {
    std::string text;
    double lo, hi;
    bool nonzero;
    bool holds(const rigid::Vec3& v) const;
};
VecRule components_between(double lo, double hi);
VecRule nonzero_vector(double lo, double hi);

class Options {
public:
    Options(std::string scene, std::string summary);

    // An option bound to a typed field: the field's initial value is the default, and parse()
    // writes the value given on the command line into it. The field must outlive the parse.
    // A scene reads its parameters from its fields, never from the options by name.
    Options& real(const std::string& name, double* field, const std::string& help, Rule rule);
    Options& integer(const std::string& name, long* field, const std::string& help, long min, long max);
    Options& integer(const std::string& name, int* field, const std::string& help, int min, int max);
    Options& vector(const std::string& name, rigid::Vec3* field, const std::string& help, VecRule rule);
    Options& choice(const std::string& name, std::string* field, const std::vector<std::string>& choices,
                    const std::string& help);
    // A file name (kind "file"; empty by default), e.g. --motion FILE (motion.hpp).
    Options& file(const std::string& name, std::string* field, const std::string& help);

    // Reads argv with CLI11 (--name VALUE or --name=VALUE, in order; the last of a repeated
    // option wins); throws BadInput naming the option and the rule. Returns false after --help
    // or --list-options.
    bool parse(int argc, char** argv);

    const std::string& scene() const { return scene_; }
    const std::string& summary() const { return summary_; }
    const std::string& out_dir() const { return out_dir_; }
    bool figures() const { return figures_; }
    bool json() const { return json_; }
    double budget_s() const { return budget_s_; }  // --budget SECONDS
    void print_help(std::ostream& os) const;
    void print_option_list(std::ostream& os) const;  // --list-options: JSON
    // "--A, --B, ..., --help": every option the scene accepts, its own and the kit's.
    std::string option_names() const;

private:
    // An integer option of either width: `store` writes the checked value into the field.
    Options& whole(const std::string& name, long fallback, const std::string& help, long min, long max,
                   std::function<void(long)> store);

    struct Spec {
        std::string name, help, kind, rule_text;
        std::vector<std::string> choices;
        std::function<void(const std::string&)> set;  // parses and checks one value, writes its field
        std::string shown_default;
        double lo = 0, hi = 0;  // the accepted range (numbers, integers, vectors)
    };
    Spec& add(const std::string& name, std::string kind, const std::string& help, std::string rule_text,
              std::string shown_default);
    void declare_kit_options(CLI::App& app);
    std::string needs_value(const std::string& name) const;
    std::string unexpected(const std::string& word) const;
    std::string unknown_option(const std::string& name) const;
    const Spec* find(const std::string& name) const;

    std::string scene_, summary_;
    std::vector<Spec> specs_;
    std::string out_dir_ = ".";
    bool figures_ = true, json_ = false;
    double budget_s_ = default_budget_s;

public:
    // About a minute on one core: what a scene may take unless --budget says otherwise.
    static constexpr double default_budget_s = 60;
};

// The work a request asks for, estimated before the scene starts: `units` of work (steps,
// samples, runs) at about `seconds_per_unit` each (measured on one core of the machine the
// workbook was written on), `unit` names them and `options` the options that set their number.
struct Work {
    double units;
    double seconds_per_unit;
    std::string unit;     // "rk8pd steps"
    std::string options;  // "--T, --h"
};

// Refuses (BadInput: exit status 2) a request whose estimated run time is over the budget,
// with a message naming the options, the estimate, and the largest number of units allowed.
// Returns the estimate in seconds.
double require_budget(const Options& o, const Work& w);

// One value in a report: a number, a count, a word, a 3-vector, or a list of numbers.
using Value = std::variant<double, long, std::string, bool, rigid::Vec3, std::vector<double>>;

// The scene's results. Every scene gives one headline: what its error measures, the error,
// and the run time of the computation that produced it.
class Report {
public:
    void headline(const std::string& error_measure, double error, double run_time_s);
    void add(const std::string& key, Value value, const std::string& unit_or_note = "");
    // A table (e.g. a work-precision sweep): column names and rows of numbers. Every table
    // goes to the JSON; with in_text false, a long one stays out of the printed report.
    void table(const std::string& key, std::vector<std::string> columns, std::vector<std::vector<double>> rows,
               bool in_text = true);
    void note(const std::string& text) { notes_.push_back(text); }

    bool has_headline() const { return has_headline_; }
    double error() const { return error_; }
    void write_text(std::ostream& os) const;
    void write_json(std::ostream& os, const Options& opts, const std::vector<std::string>& figures) const;

private:
    struct Field {
        std::string key;
        Value value;
        std::string note;
    };
    struct Table {
        std::string key;
        std::vector<std::string> columns;
        std::vector<std::vector<double>> rows;
        bool in_text;
    };
    bool has_headline_ = false;
    std::string error_measure_;
    double error_ = 0, run_time_s_ = 0;
    std::vector<Field> fields_;
    std::vector<Table> tables_;
    std::vector<std::string> notes_;
};

// What a running scene holds: its options, its report and the figures it has staged.
class Scene {
public:
    explicit Scene(const Options& opts) : opts_(opts) {}
    const Options& options() const { return opts_; }
    Report report;

    // Called by kit::Figure: a finished figure waits at `staged` until the scene succeeds.
    void stage_figure(const std::string& staged, const std::string& final_path);
    void publish_figures();  // renames staged files to their final names
    void discard_figures();  // removes staged files (the scene failed, or overran its budget)
    const std::vector<std::string>& figures() const { return published_; }

private:
    const Options& opts_;
    std::vector<std::pair<std::string, std::string>> staged_;
    std::vector<std::string> published_;
    std::mutex mutex_;  // the watchdog may discard the staged figures from its own thread
};

// A scene's own check failed (a label that would be wrong, a property that does not hold):
// exit status 1, and the message says which check and by how much.
struct CheckFailed : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Parses options, runs the body, prints the report, maps failures to exit statuses:
// 0 success; 2 bad input (BadInput or std::invalid_argument, a request over the budget);
// 1 numerical failure, a failed check, an exercise not written yet, or any other error.
// Never leaves a partial figure behind. A watchdog stops a scene that uses more processor time
// than three times its budget plus 10 s (its estimate was wrong), or that is still running
// after ten times that in wall time (it waits forever): exit status 1, with a message.
int run(int argc, char** argv, Options& opts, const std::function<void(const Options&, Scene&)>& body);

// The smallest wall time of `repeats` calls of f, in seconds: the least-disturbed measurement.
template <class F>
double min_time(F&& f, int repeats = 5) {
    double best = 1e300;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        const auto t1 = std::chrono::steady_clock::now();
        best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
    }
    return best;
}

// Keeps a computed value alive so the optimiser cannot drop a timed loop.
template <class T>
inline void keep(const T& value) {
    asm volatile("" : : "g"(&value) : "memory");
}

// The run time of one call of f(i), over `calls` calls with i = 0, 1, ... (their results summed
// and kept), as the least-disturbed of five batches.
template <class F>
double time_per_call(F&& f, int calls = 1000) {
    return min_time([&] {
               double sum = 0;
               for (int i = 0; i < calls; ++i) sum += f(i);
               keep(sum);
           }) /
           calls;
}

}  // namespace kit
