// The scene kit: what every chapter driver ("scene") shares, and nothing else.
//
//   * named options with --help, the common --out DIR, --no-figure and --json;
//   * one clear message and exit status 2 for bad input, 1 for a numerical failure;
//   * a report that puts the scene's error next to its run time (text or JSON);
//   * figures staged and published only when the whole scene succeeded (figure.hpp).
//
// A scene is a small main():
//
//   int main(int argc, char** argv) {
//       kit::Options opts("my_scene", "Chapter N: what it shows");
//       opts.real("alpha", 1.0, "rotation frequency", kit::positive);
//       return kit::run(argc, argv, opts, [](const kit::Options& o, kit::Scene& scene) {
//           ...compute, scene.report.headline(...), kit::Figure fig(scene, "x.svg"); ...
//       });
//   }
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "rigid/types.hpp"

namespace kit {

// Bad input: exit status 2, the message names the option and the rule it breaks.
struct BadInput : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A numerical failure (NaN, a solver that gave up): exit status 1, the message says why.
struct NumericalFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A rule that a number must obey, with the words that --help and error messages use.
struct Rule {
    std::string text;                     // e.g. "a finite number > 0"
    std::function<bool(double)> holds;
};
Rule finite();
Rule positive();
Rule non_negative();
Rule at_least(double lo);
Rule between(double lo, double hi);       // lo <= x <= hi

// A rule for a 3-vector.
struct VecRule {
    std::string text;
    std::function<bool(const rigid::Vec3&)> holds;
};
VecRule finite_vector();
VecRule nonzero_vector();

class Options {
public:
    Options(std::string scene, std::string summary);

    Options& real(const std::string& name, double fallback, const std::string& help, Rule rule = finite());
    Options& integer(const std::string& name, long fallback, const std::string& help, long min, long max);
    Options& vector(const std::string& name, const rigid::Vec3& fallback, const std::string& help,
                    VecRule rule = finite_vector());
    Options& choice(const std::string& name, const std::string& fallback,
                    const std::vector<std::string>& choices, const std::string& help);

    // Reads argv; throws BadInput naming the option and the rule. Returns false after --help.
    bool parse(int argc, char** argv);

    double real(const std::string& name) const;
    long integer(const std::string& name) const;
    rigid::Vec3 vector(const std::string& name) const;
    const std::string& choice(const std::string& name) const;

    const std::string& scene() const { return scene_; }
    const std::string& summary() const { return summary_; }
    const std::string& out_dir() const { return out_dir_; }
    bool figures() const { return figures_; }
    bool json() const { return json_; }
    void print_help(std::ostream& os) const;

private:
    struct Spec {
        std::string name, help, kind, rule_text;
        std::vector<std::string> choices;
        std::function<void(const std::string&)> set;   // parses and checks one value
        std::string shown_default;
    };
    Spec& add(const std::string& name);
    const Spec* find(const std::string& name) const;

    std::string scene_, summary_;
    std::vector<Spec> specs_;
    std::map<std::string, double> reals_;
    std::map<std::string, long> integers_;
    std::map<std::string, rigid::Vec3> vectors_;
    std::map<std::string, std::string> choices_;
    std::string out_dir_ = ".";
    bool figures_ = true, json_ = false;
};

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
    void table(const std::string& key, std::vector<std::string> columns,
               std::vector<std::vector<double>> rows, bool in_text = true);
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
    void publish_figures();   // renames staged files to their final names
    void discard_figures();   // removes staged files (the scene failed)
    const std::vector<std::string>& figures() const { return published_; }

private:
    const Options& opts_;
    std::vector<std::pair<std::string, std::string>> staged_;
    std::vector<std::string> published_;
};

// Parses options, runs the body, prints the report, maps failures to exit statuses:
// 0 success; 2 bad input (BadInput or std::invalid_argument); 1 numerical failure, an
// exercise not written yet, or any other error. Never leaves a partial figure behind.
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

}  // namespace kit
