// The scene kit: options, report, run. See scene.hpp.
#include "scene.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "rigid/todo.hpp"

namespace kit {

namespace {

using Json = nlohmann::ordered_json;  // keeps the fields in the order the scene gave them

// Every number the kit prints: 17 significant digits in messages that must be exact, 6 in
// the text report, help and rules.
std::string number(double x) { return fmt::format("{:.17g}", x); }
std::string short_number(double x) { return fmt::format("{:.6g}", x); }

// The shortest text that reads back as exactly x (what --list-options gives the corner sweep).
std::string shortest(double x) { return fmt::format("{}", x); }

// strtod over the whole word, or BadInput naming the option.
double parse_real(const std::string& name, const std::string& word) {
    if (word.empty()) throw BadInput("--" + name + ": needs a value (a number)");
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0') throw BadInput("--" + name + ": '" + word + "' is not a number");
    return x;
}

// JSON has no NaN or infinity: nlohmann::json writes them as null, and the report's headline
// check has already refused a non-finite headline error.
Json json_value(const Value& v) {
    return std::visit(
        [](const auto& x) -> Json {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, rigid::Vec3>) {
                return Json::array({x.x(), x.y(), x.z()});
            } else {
                return x;
            }
        },
        v);
}

std::string text_value(const Value& v) {
    return std::visit(
        [](const auto& x) -> std::string {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, double>) {
                return short_number(x);
            } else if constexpr (std::is_same_v<T, long>) {
                return std::to_string(x);
            } else if constexpr (std::is_same_v<T, std::string>) {
                return x;
            } else if constexpr (std::is_same_v<T, bool>) {
                return x ? "yes" : "no";
            } else if constexpr (std::is_same_v<T, rigid::Vec3>) {
                return fmt::format("({:.6g}, {:.6g}, {:.6g})", x.x(), x.y(), x.z());
            } else {
                return fmt::format("[{:.6g}]", fmt::join(x, ", "));
            }
        },
        v);
}

// The number of one-letter edits between two option names (Levenshtein), to suggest the
// option a typo meant.
std::size_t edits(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

// The options every scene has, besides its own.
const std::vector<std::string> kit_options = {"out", "no-figure", "json", "budget", "list-options", "help"};

}  // namespace

Rule between(double lo, double hi) {
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi))
        throw std::logic_error("kit::between needs finite lo <= hi");
    return {"a number in [" + short_number(lo) + ", " + short_number(hi) + "]", lo, hi};
}
bool VecRule::holds(const rigid::Vec3& v) const {
    for (int i = 0; i < 3; ++i)
        if (!(std::isfinite(v(i)) && v(i) >= lo && v(i) <= hi)) return false;
    return !nonzero || v.stableNorm() > 0;
}
VecRule components_between(double lo, double hi) {
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi))
        throw std::logic_error("kit::components_between needs finite lo <= hi");
    return {"three numbers x,y,z, each in [" + short_number(lo) + ", " + short_number(hi) + "]", lo, hi, false};
}
VecRule nonzero_vector(double lo, double hi) {
    VecRule r = components_between(lo, hi);
    r.text += ", not all zero";
    r.nonzero = true;
    return r;
}

// ---------------------------------------------------------------------------- Options

Options::Options(std::string scene, std::string summary) : scene_(std::move(scene)), summary_(std::move(summary)) {}

Options::Spec& Options::add(const std::string& name, std::string kind, const std::string& help, std::string rule_text,
                            std::string shown_default) {
    if (find(name)) throw std::logic_error("option --" + name + " declared twice");
    specs_.push_back({});
    Spec& s = specs_.back();
    s.name = name;
    s.kind = std::move(kind);
    s.help = help;
    s.rule_text = std::move(rule_text);
    s.shown_default = std::move(shown_default);
    return s;
}

const Options::Spec* Options::find(const std::string& name) const {
    for (const auto& s : specs_)
        if (s.name == name) return &s;
    return nullptr;
}

Options& Options::real(const std::string& name, double* field, const std::string& help, Rule rule) {
    if (!rule.holds(*field)) throw std::logic_error("option --" + name + ": its default is outside its range");
    Spec& s = add(name, "number", help, rule.text, short_number(*field));
    s.lo = rule.lo;
    s.hi = rule.hi;
    s.set = [name, field, rule](const std::string& word) {
        const double x = parse_real(name, word);
        if (!rule.holds(x)) throw BadInput("--" + name + ": got " + word + "; it must be " + rule.text);
        *field = x;
    };
    return *this;
}

Options& Options::whole(const std::string& name, long fallback, const std::string& help, long min, long max,
                        std::function<void(long)> store) {
    if (fallback < min || fallback > max)
        throw std::logic_error("option --" + name + ": its default is outside its range");
    const std::string rule = "a whole number in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
    Spec& s = add(name, "integer", help, rule, std::to_string(fallback));
    s.lo = static_cast<double>(min);
    s.hi = static_cast<double>(max);
    // Base 10 only: CLI11's own conversion would read 010 as octal.
    s.set = [name, min, max, rule, store = std::move(store)](const std::string& word) {
        char* end = nullptr;
        errno = 0;
        const long x = word.empty() ? 0 : std::strtol(word.c_str(), &end, 10);
        if (word.empty() || *end != '\0' || errno == ERANGE || x < min || x > max)
            throw BadInput("--" + name + ": got '" + word + "'; it must be " + rule);
        store(x);
    };
    return *this;
}

Options& Options::integer(const std::string& name, long* field, const std::string& help, long min, long max) {
    return whole(name, *field, help, min, max, [field](long x) { *field = x; });
}

Options& Options::integer(const std::string& name, int* field, const std::string& help, int min, int max) {
    return whole(name, *field, help, min, max, [field](long x) { *field = static_cast<int>(x); });
}

Options& Options::vector(const std::string& name, rigid::Vec3* field, const std::string& help, VecRule rule) {
    const rigid::Vec3& v = *field;
    if (!rule.holds(v)) throw std::logic_error("option --" + name + ": its default is outside its range");
    Spec& s = add(name, "x,y,z", help, rule.text,
                  short_number(v.x()) + "," + short_number(v.y()) + "," + short_number(v.z()));
    s.lo = rule.lo;
    s.hi = rule.hi;
    s.set = [name, field, rule](const std::string& word) {
        rigid::Vec3 x;
        std::stringstream in(word);
        std::string part;
        int n = 0;
        while (std::getline(in, part, ',')) {
            if (n == 3) throw BadInput("--" + name + ": got '" + word + "'; it must be " + rule.text);
            x(n++) = parse_real(name, part);
        }
        if (n != 3) throw BadInput("--" + name + ": got '" + word + "'; it must be " + rule.text);
        if (!rule.holds(x)) throw BadInput("--" + name + ": got " + word + "; it must be " + rule.text);
        *field = x;
    };
    return *this;
}

Options& Options::choice(const std::string& name, std::string* field, const std::vector<std::string>& choices,
                         const std::string& help) {
    const std::string list = fmt::format("{}", fmt::join(choices, "|"));
    Spec& s = add(name, "word", help, "one of " + list, *field);
    s.choices = choices;
    s.set = [name, field, choices, list](const std::string& word) {
        if (std::find(choices.begin(), choices.end(), word) == choices.end())
            throw BadInput("--" + name + ": got '" + word + "'; it must be one of " + list);
        *field = word;
    };
    return *this;
}

Options& Options::file(const std::string& name, std::string* field, const std::string& help) {
    Spec& s = add(name, "file", help, "a file name", "none");
    s.set = [field, name](const std::string& value) {
        if (value.empty()) throw BadInput("--" + name + ": needs a file name");
        *field = value;
    };
    return *this;
}

std::string Options::option_names() const {
    std::vector<std::string> names;
    for (const auto& s : specs_) names.push_back("--" + s.name);
    for (const auto& k : kit_options) names.push_back("--" + k);
    return fmt::format("{}", fmt::join(names, ", "));
}

namespace {

// Thrown by --help and --list-options once they have printed: the scene stops there (exit 0).
struct Stop {};

// An option with a value: CLI11 finds it (--name VALUE, --name=VALUE) and `set` parses, checks
// and keeps the value, at once, so that the first bad word on the line is the one refused.
// A value may itself start with '-' (a negative number), but never with "--": that is the
// next option, and this one has no value.
void take_value(CLI::App& app, const std::string& name, const std::string& missing,
                const std::function<void(const std::string&)>& set) {
    app.add_option_function<std::string>("--" + name,
                                         [missing, set](const std::string& word) {
                                             if (word.rfind("--", 0) == 0) throw BadInput(missing);
                                             set(word);
                                         })
        ->trigger_on_parse();
}

// A flag (no value), acted on where it stands on the line.
void take_flag(CLI::App& app, const std::string& names, const std::function<void()>& act) {
    app.add_flag_callback(names, act)->trigger_on_parse();
}

}  // namespace

void Options::declare_kit_options(CLI::App& app) {
    take_value(app, "out", needs_value("out"), [this](const std::string& dir) {
        if (dir.empty()) throw BadInput("--out: needs a folder name");
        out_dir_ = dir;
    });
    take_value(app, "budget", needs_value("budget"), [this](const std::string& word) {
        const double b = parse_real("budget", word);
        if (!(b >= 1 && b <= 86400))
            throw BadInput("--budget: got " + word + "; it must be a number of seconds in [1, 86400]");
        budget_s_ = b;
    });
    take_flag(app, "--json", [this] { json_ = true; });
    take_flag(app, "--no-figure", [this] { figures_ = false; });
    take_flag(app, "--list-options", [this] {
        print_option_list(std::cout);
        throw Stop{};
    });
    // -h too, unless a scene option is --h (a step), which CLI11 would take -h for.
    take_flag(app, find("h") ? "--help" : "-h,--help", [this] {
        print_help(std::cout);
        throw Stop{};
    });
}

bool Options::parse(int argc, char** argv) {
    CLI::App app{summary_, scene_};
    app.set_help_flag();  // the kit's own --help (above), with each option's rule and default
    app.allow_extras();   // kept to be refused below, naming the options the scene has
    for (const Spec& s : specs_) take_value(app, s.name, needs_value(s.name), s.set);
    declare_kit_options(app);
    try {
        app.parse(argc, argv);
    } catch (const Stop&) {
        return false;
    } catch (const CLI::ArgumentMismatch& e) {
        // The line ran out before a value: its last word is the option that wanted one.
        const std::string last = argv[argc - 1];
        if (last.rfind("--", 0) != 0) throw BadInput(e.what());
        throw BadInput(needs_value(last.substr(2, last.find('=') - 2)));
    } catch (const CLI::ParseError& e) {
        throw BadInput(e.what());
    }
    if (const auto extra = app.remaining(); !extra.empty()) throw BadInput(unexpected(extra.front()));
    return true;
}

std::string Options::needs_value(const std::string& name) const {
    const Spec* s = find(name);
    return "--" + name + ": needs a value (" + (s ? s->rule_text : name == "out" ? "a folder" : "seconds") + ")";
}

std::string Options::unexpected(const std::string& word) const {
    if (word.rfind("--", 0) != 0) return "unexpected argument '" + word + "' (options start with --; see --help)";
    const std::string name = word.substr(2);
    return unknown_option(name.substr(0, name.find('=')));
}

std::string Options::unknown_option(const std::string& name) const {
    // The nearest option by one-letter edits, when it is near enough to be what was meant.
    std::string nearest;
    std::size_t best = 3;
    for (const auto& s : specs_)
        if (const std::size_t d = edits(name, s.name); d < best && d < std::max<std::size_t>(name.size(), 2)) {
            best = d;
            nearest = s.name;
        }
    return "unknown option --" + name + (nearest.empty() ? "" : " (did you mean --" + nearest + "?)") + "; " + scene_ +
           " takes " + option_names();
}

void Options::print_help(std::ostream& os) const {
    os << scene_ << ": " << summary_ << "\n\nUsage: " << scene_ << " [options]\n\nOptions:\n";
    for (const auto& s : specs_) {
        os << "  --" << s.name << " <" << s.kind << ">\n      " << s.help << "\n      must be " << s.rule_text
           << "; default " << s.shown_default << "\n";
    }
    os << "  --out DIR      folder for the figures (default: the current folder)\n"
          "  --no-figure    compute and report, draw nothing\n"
          "  --json         print the results as one JSON object on stdout\n"
          "  --budget S     the processor time allowed, in seconds (default "
       << short_number(default_budget_s)
       << ", about a minute on one core):\n"
          "                 a request whose estimated work is over it is refused (exit status 2)\n"
          "  --list-options every option with its default and accepted range, as JSON\n"
          "  --help         this text\n\n"
          "Exit status: 0 success; 2 bad input or a request over the budget; 1 numerical failure, a failed\n"
          "check, or an exercise not written yet.\n";
}

void Options::print_option_list(std::ostream& os) const {
    Json options = Json::array();
    for (const Spec& s : specs_) {
        Json o = {{"name", s.name}, {"kind", s.kind}, {"default", s.shown_default}};
        if (s.kind == "file") {
            // a file name has no range: the corner sweep leaves it alone
        } else if (s.kind == "word") {
            o["choices"] = s.choices;
        } else {
            // The bounds as the option reads them back: whole numbers for an integer option.
            const auto text = [&](double x) {
                return s.kind == "integer" ? std::to_string(static_cast<long>(x)) : shortest(x);
            };
            o["min"] = s.lo;
            o["max"] = s.hi;
            o["min_text"] = text(s.lo);
            o["max_text"] = text(s.hi);
        }
        options.push_back(std::move(o));
    }
    const Json list = {{"scene", scene_}, {"budget_s", default_budget_s}, {"options", std::move(options)}};
    os << list.dump(2) << "\n";
}

namespace {
double estimated_s = 0;  // the sum of this run's estimates, reported with the scene's results
}

double require_budget(const Options& o, const Work& w) {
    const double estimate = w.units * w.seconds_per_unit;
    estimated_s += estimate;
    if (!(estimate <= o.budget_s())) {
        throw BadInput(w.options + ": this asks for about " + short_number(w.units) + " " + w.unit + ", about " +
                       short_number(estimate) + " s of work; the budget is " + short_number(o.budget_s()) +
                       " s, at most " + short_number(std::floor(o.budget_s() / w.seconds_per_unit)) + " " + w.unit +
                       " (ask for less, or raise --budget)");
    }
    return estimate;
}

// ---------------------------------------------------------------------------- Report

void Report::headline(const std::string& error_measure, double error, double run_time_s) {
    if (!std::isfinite(error))
        throw NumericalFailure("the error (" + error_measure + ") is " + number(error) + ", not a finite number");
    has_headline_ = true;
    error_measure_ = error_measure;
    error_ = error;
    run_time_s_ = run_time_s;
}

void Report::add(const std::string& key, Value value, const std::string& note) {
    fields_.push_back({key, std::move(value), note});
}

void Report::table(const std::string& key, std::vector<std::string> columns, std::vector<std::vector<double>> rows,
                   bool in_text) {
    tables_.push_back({key, std::move(columns), std::move(rows), in_text});
}

void Report::write_text(std::ostream& os) const {
    if (has_headline_) {
        os << fmt::format("  error     {:>12}   {}\n", short_number(error_), error_measure_)
           << fmt::format("  run time  {:>12}   s\n", short_number(run_time_s_));
    }
    std::size_t width = 0;
    for (const auto& f : fields_) width = std::max(width, f.key.size());
    for (const auto& f : fields_)
        os << fmt::format("  {:<{}}  {}{}\n", f.key, width, text_value(f.value), f.note.empty() ? "" : "   " + f.note);
    for (const auto& t : tables_) {
        if (!t.in_text) {
            os << fmt::format("  {}: {} rows (in the --json output)\n", t.key, t.rows.size());
            continue;
        }
        os << fmt::format("\n  {}:\n  ", t.key);
        for (const auto& c : t.columns) os << fmt::format("{:>16}", c);
        os << "\n";
        for (const auto& r : t.rows) {
            os << "  ";
            for (double x : r) os << fmt::format("{:>16}", short_number(x));
            os << "\n";
        }
    }
    for (const auto& n : notes_) os << "  note: " << n << "\n";
}

void Report::write_json(std::ostream& os, const Options& opts, const std::vector<std::string>& figures) const {
    Json report = {{"scene", opts.scene()}, {"summary", opts.summary()}};
    if (has_headline_) {
        report["error_measure"] = error_measure_;
        report["error"] = error_;
        report["run_time_s"] = run_time_s_;
    }
    for (const auto& f : fields_) report[f.key] = json_value(f.value);
    for (const auto& t : tables_) report[t.key] = {{"columns", t.columns}, {"rows", t.rows}};
    report["notes"] = notes_;
    report["figures"] = figures;
    os << report.dump(2) << "\n";
}

// ---------------------------------------------------------------------------- Scene

namespace {

// Stops a scene that uses more than 3 budgets + 10 s of processor time: its estimate of its work
// was wrong, and a scene must never hang. Processor time, not wall time: a loaded machine
// stretches the wall clock, and a scene that is only slow there must not fail. The wall clock
// is a backstop alone, at ten times that, against a scene that waits forever. It discards the
// staged figures, says which budget ran out on stderr and exits with 1.
// In the book's live scenes (WebAssembly, no threads: cmake/book/live/) there is none: the page
// runs the scene's default-sized work, and the browser stops a page script that hangs.
#ifdef __EMSCRIPTEN__
struct Watchdog {
    Watchdog(Scene&, const std::string&, double) {}
};
#else
// The processor time of this process, every thread, in seconds.
double process_cpu_s() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

class Watchdog {
public:
    Watchdog(Scene& scene, std::string who, double budget_s)
        : thread_([this, &scene, who = std::move(who), budget_s] {
              const double cpu_limit = 3 * budget_s + 10, wall_limit = 10 * cpu_limit;
              const auto start = std::chrono::steady_clock::now();
              std::unique_lock<std::mutex> lock(mutex_);
              for (;;) {
                  if (done_cv_.wait_for(lock, std::chrono::milliseconds(250), [this] { return done_; })) return;
                  const double cpu = process_cpu_s();
                  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                  if (cpu <= cpu_limit && wall <= wall_limit) continue;
                  scene.discard_figures();
                  if (cpu > cpu_limit)
                      std::cerr << who << ": numerical failure: used " << short_number(cpu)
                                << " s of processor time, more than three times the budget of "
                                << short_number(budget_s)
                                << " s and 10 s: its estimate of the work was wrong; stopped\n";
                  else
                      std::cerr << who << ": numerical failure: still running after " << short_number(wall)
                                << " s of wall time, having used only " << short_number(cpu)
                                << " s of processor time: it waits for something; stopped\n";
                  std::_Exit(1);
              }
          }) {}
    ~Watchdog() {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            done_ = true;
        }
        done_cv_.notify_all();
        thread_.join();
    }

private:
    std::mutex mutex_;
    std::condition_variable done_cv_;
    bool done_ = false;
    std::thread thread_;  // last: it starts after the members it uses
};
#endif

}  // namespace

void Scene::stage_figure(const std::string& staged, const std::string& final_path) {
    const std::lock_guard<std::mutex> lock(mutex_);
    staged_.emplace_back(staged, final_path);
}

void Scene::publish_figures() {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [staged, final_path] : staged_) {
        std::filesystem::rename(staged, final_path);
        published_.push_back(final_path);
    }
    staged_.clear();
}

void Scene::discard_figures() {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [staged, final_path] : staged_) {
        std::error_code ignored;
        std::filesystem::remove(staged, ignored);
    }
    staged_.clear();
}

int run(int argc, char** argv, Options& opts, const std::function<void(const Options&, Scene&)>& body) {
    const std::string who = opts.scene();
    estimated_s = 0;  // this run's own estimates (a live scene's module runs main() again and again)
    try {
        if (!opts.parse(argc, argv)) return 0;
    } catch (const BadInput& e) {
        std::cerr << who << ": bad input: " << e.what() << "\n";
        return 2;
    }
    Scene scene(opts);
    const Watchdog watchdog(scene, who, opts.budget_s());
    try {
        const auto t0 = std::chrono::steady_clock::now();
        body(opts, scene);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!scene.report.has_headline()) throw std::logic_error("the scene gave no headline (error against run time)");
        scene.publish_figures();
        if (opts.json()) {
            scene.report.add("wall_time_s", wall, "the whole scene, figures included");
            scene.report.add("estimated_time_s", estimated_s,
                             "the scene's own estimate of its work, checked against --budget");
            scene.report.write_json(std::cout, opts, scene.figures());
        } else {
            std::cout << who << ": " << opts.summary() << "\n";
            scene.report.write_text(std::cout);
            for (const auto& f : scene.figures()) std::cout << "  figure: " << f << "\n";
        }
        return 0;
    } catch (const BadInput& e) {
        scene.discard_figures();
        std::cerr << who << ": bad input: " << e.what() << "\n";
        return 2;
    } catch (const std::invalid_argument& e) {
        scene.discard_figures();
        std::cerr << who << ": bad input: " << e.what() << "\n";
        return 2;
    } catch (const rigid::not_implemented& e) {
        scene.discard_figures();
        std::cerr << who << ": this scene needs an exercise you have not written yet: " << e.what() << "\n";
        return 1;
    } catch (const NumericalFailure& e) {
        scene.discard_figures();
        std::cerr << who << ": numerical failure: " << e.what() << "\n";
        return 1;
    } catch (const CheckFailed& e) {
        scene.discard_figures();
        std::cerr << who << ": check failed: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        scene.discard_figures();
        std::cerr << who << ": failed: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace kit
