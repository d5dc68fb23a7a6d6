// workbook_mutants: the mutation gate (README.md, "The mutation gate").
//
//   workbook_mutants run --setup <build>/grading --solutions <dir> --out <dir>
//                        [--topic T]... [--mutant ID]... [--sample N --seed S] [--allow <file>] [-j N]
//                        [--timeout s] [--build-timeout s]
//   (--mutant grades again only the mutants of these ids, e.g. the survivors of a full run)
//   workbook_mutants list --setup <build>/grading --solutions <dir> [--topic T]... [--sample N --seed S]
//   workbook_mutants catalogue --setup ... --solutions <dir> --from <a run's --out> --catalogue <dir> [--topic T]...
//   workbook_mutants stale --setup ... --solutions <dir> --catalogue <dir> [--topic T]...
//   workbook_mutants audit --catalogue <dir> --results <grades>/results [--may-name S]... [--plant | --measure]
//   (the likely mistakes named from the gate: catalogue.hpp; README.md, "Likely mistakes, named")
//
// A mutant is the reference solution solutions/<topic>.cpp with one plausible wrong change, made
// by one of a fixed set of operators (mutate_line below; comments, string and character literals
// and preprocessor lines are never touched). Each mutant is a submission holding that one file,
// graded by the grading run (workbook_grade check: its build flags, per-test isolation, limits
// and verdicts), -j at a time. To spare the compiler, up to 40 mutants of a topic are built as one
// file, a schema, and picked at run time (see "Schemata" below; --one-by-one builds each alone). A mutant inside an exercise function is killed when a test of
// that exercise does not pass, so only that exercise's tests are run; a mutant inside a helper
// of the file is killed when any test of the topic does not pass, so all of them are run. A
// mutant that does not build is counted apart. A survivor is equivalent only when allowed.txt
// lists it, with the reason; any other survivor fails the run (exit 1): a grader to strengthen.
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "calls.hpp"
#include "catalogue.hpp"
#include "support/file.hpp"
#include "support/process.hpp"
#include "support/text.hpp"
#include "verdict.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

struct Mutant {
    std::string id, topic, function, op;
    int line = 0;                                // 1-based line of solutions/<topic>.cpp
    std::string before, after;                   // the line, trimmed, before and after the change
    std::string source;                          // the whole mutated file
    bool exercise = false;                       // function is an exercise of the topic (else a helper)
    std::string status, evidence;                // killed | survived | equivalent | not compiling
    std::size_t change_from = 0, change_to = 0;  // the original's characters [from, to) that the change replaces
    int selector = 0;                            // its number in a schema (0: graded alone)
    std::string schema;                          // the schema's folder of exercises, when selector > 0
};

struct Options {
    std::string command, setup, solutions, out, allow;
    std::string from, catalogue;  // catalogue and stale: the gate's out folder, the catalogue's folder
    std::vector<std::string> topics, ids;
    int sample = 0, jobs = 2;
    unsigned seed = 1;
    double timeout = 30, build_timeout = 900;  // generous: a loaded machine must not kill a mutant
    bool one_by_one = false;                   // --one-by-one: no schemata, each mutant built alone
};

[[noreturn]] void die(const std::string& message) {
    std::fprintf(stderr, "workbook_mutants: %s\n", message.c_str());
    std::exit(2);
}

std::string slurp(const fs::path& path) {
    bool ok = false;
    std::string text = support::read_file(path.string(), &ok);
    if (!ok) die("cannot read " + path.string());
    return text;
}

using grading::Verdict;
using support::trim;

// Where code is, and which function each character belongs to: calls.hpp (the engine's, one reader
// for the gate, the manifest's `uses` and the catalogue).
using grading::calls::Body;
using grading::calls::code_mask;

std::vector<Body> function_bodies(const std::string& s, const std::vector<bool>& code) {
    std::string error;
    auto bodies = grading::calls::function_bodies(s, code, &error);
    if (!error.empty()) die(error);
    return bodies;
}

bool is_ident(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// ---- The operators. Each returns the mutated line, or "" when it does not apply at `at`. ----
//
// sign       binary + and - swapped (also += and -=); a unary minus dropped
// compare    < <= > >= each moved across its boundary (< to <=, ...) and turned (< to >, ...);
//            == and != swapped. Only comparisons written with a space on both sides, as the
//            style asks: that leaves template brackets and << alone.
// transpose  a .transpose() dropped
// index      the two indices of M(i, j) swapped (literals or one-letter names); .x() .y() .z()
//            rotated
// sincos     sin and cos swapped
// constant   an integer literal k becomes k + 1; a floating literal x becomes 2x (0 becomes 1).
//            Literals below 1e-6 (tolerances whose job is to tell zero from non-zero) are left.
// return     return e; becomes return -(e); (return !(e); in a function returning bool)
// condition  if (c) becomes if (!(c))

struct Site {
    std::string op, line;
};

bool code_at(const std::vector<bool>& code, std::size_t from, std::size_t n) {
    for (std::size_t k = from; k < from + n; ++k)
        if (k >= code.size() || !code[k]) return false;
    return true;
}

std::string replace_at(const std::string& line, std::size_t at, std::size_t n, const std::string& by) {
    return line.substr(0, at) + by + line.substr(at + n);
}

// The previous non-space character of the line before `at` ('\0' if none).
char previous(const std::string& line, std::size_t at) {
    while (at > 0 && line[at - 1] == ' ') --at;
    return at == 0 ? '\0' : line[at - 1];
}

void sign_sites(const std::string& l, const std::vector<bool>& m, std::vector<Site>& out) {
    for (std::size_t i = 0; i < l.size(); ++i) {
        const char c = l[i];
        if ((c != '+' && c != '-') || !code_at(m, i, 1)) continue;
        const char next = i + 1 < l.size() ? l[i + 1] : '\0', prev = i > 0 ? l[i - 1] : '\0';
        if (next == c || prev == c || next == '>') continue;                                           // ++ -- ->
        if (std::isdigit(static_cast<unsigned char>(next)) && (prev == 'e' || prev == 'E')) continue;  // 1e-9
        const char p = previous(l, i);
        const bool binary = is_ident(p) || p == ')' || p == ']';
        if (binary)
            out.push_back({"sign", replace_at(l, i, 1, c == '+' ? "-" : "+")});
        else if (c == '-' && next != '=')
            out.push_back({"sign", replace_at(l, i, 1, "")});
    }
}

void compare_sites(const std::string& l, const std::vector<bool>& m, std::vector<Site>& out) {
    static const std::vector<std::pair<std::string, std::vector<std::string>>> table = {
        {" <= ", {" < ", " >= "}}, {" >= ", {" > ", " <= "}}, {" < ", {" <= ", " > "}},
        {" > ", {" >= ", " < "}},  {" == ", {" != "}},        {" != ", {" == "}}};
    for (const auto& [from, tos] : table) {
        for (auto at = l.find(from); at != std::string::npos; at = l.find(from, at + 1)) {
            if (!code_at(m, at, from.size())) continue;
            for (const auto& to : tos) out.push_back({"compare", replace_at(l, at, from.size(), to)});
        }
    }
}

void regex_sites(const std::string& l, const std::vector<bool>& m, const std::string& op, const std::regex& re,
                 const std::function<std::string(const std::smatch&)>& change, std::vector<Site>& out) {
    for (auto it = std::sregex_iterator(l.begin(), l.end(), re); it != std::sregex_iterator(); ++it) {
        const auto& match = *it;
        const auto at = static_cast<std::size_t>(match.position(0));
        if (!code_at(m, at, static_cast<std::size_t>(match.length(0)))) continue;
        const std::string by = change(match);
        if (!by.empty()) out.push_back({op, replace_at(l, at, static_cast<std::size_t>(match.length(0)), by)});
    }
}

std::string bumped(const std::string& literal) {
    const bool floating = literal.find_first_of(".eE") != std::string::npos;
    if (!floating) return std::to_string(std::stoll(literal) + 1);
    const double x = std::strtod(literal.c_str(), nullptr);
    if (x != 0 && x < 1e-6) return "";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", x == 0 ? 1.0 : 2 * x);
    std::string s = buffer;
    return s.find_first_of(".e") == std::string::npos ? s + ".0" : s;
}

void other_sites(const std::string& l, const std::vector<bool>& m, bool returns_bool, std::vector<Site>& out) {
    static const std::regex index2(R"(\b([A-Za-z_]\w*)\((\w), (\w)\))"), component(R"(\.([xyz])\(\))"),
        trig(R"(\b(sin|cos)\()"), literal(R"((^|[^\w.])(\d+\.?\d*(?:[eE][-+]?\d+)?)(?![\w.]))"),
        ret(R"(\breturn ([^;]+);)"), cond(R"(\bif \((.*)\)( \{| return| throw|$))");
    for (auto at = l.find(".transpose()"); at != std::string::npos; at = l.find(".transpose()", at + 1))
        if (code_at(m, at, 12)) out.push_back({"transpose", replace_at(l, at, 12, "")});
    regex_sites(
        l, m, "index", index2,
        [](const std::smatch& x) {
            const std::string f = x[1];
            if (x[2] == x[3] || f == "max" || f == "min" || f == "if" || f == "for" || f == "while")
                return std::string();
            return f + "(" + x[3].str() + ", " + x[2].str() + ")";
        },
        out);
    regex_sites(
        l, m, "index", component,
        [](const std::smatch& x) {
            return std::string(".") + (x[1] == "x" ? "y" : x[1] == "y" ? "z" : "x") + "()";
        },
        out);
    regex_sites(
        l, m, "sincos", trig, [](const std::smatch& x) { return std::string(x[1] == "sin" ? "cos(" : "sin("); }, out);
    regex_sites(
        l, m, "constant", literal,
        [](const std::smatch& x) {
            const std::string b = bumped(x[2]);
            return b.empty() ? b : x[1].str() + b;
        },
        out);
    regex_sites(
        l, m, "return", ret,
        [returns_bool](const std::smatch& x) {
            return "return " + std::string(returns_bool ? "!(" : "-(") + x[1].str() + ");";
        },
        out);
    regex_sites(
        l, m, "condition", cond, [](const std::smatch& x) { return "if (!(" + x[1].str() + "))" + x[2].str(); }, out);
}

std::vector<Site> mutate_line(const std::string& line, const std::vector<bool>& mask, bool returns_bool) {
    std::vector<Site> sites;
    sign_sites(line, mask, sites);
    compare_sites(line, mask, sites);
    other_sites(line, mask, returns_bool, sites);
    return sites;
}

// ---- Every mutant of one topic's reference solution. ----

std::vector<Mutant> mutants_of(const std::string& topic, const fs::path& file, const std::set<std::string>& exercises) {
    const std::string s = slurp(file);
    const auto code = code_mask(s);
    std::vector<Mutant> result;
    std::size_t line_begin = 0;
    int line_number = 1;
    const auto bodies = function_bodies(s, code);
    while (line_begin < s.size()) {
        auto line_end = s.find('\n', line_begin);
        if (line_end == std::string::npos) line_end = s.size();
        const Body* body = nullptr;
        for (const auto& b : bodies)
            if (b.begin < line_end && line_begin < b.end) body = &b;
        if (body) {
            const std::string line = s.substr(line_begin, line_end - line_begin);
            const auto lb = static_cast<std::ptrdiff_t>(line_begin), le = static_cast<std::ptrdiff_t>(line_end);
            std::vector<bool> mask(code.begin() + lb, code.begin() + le);
            // Only the part of the line inside the body (a one-line function has its header too).
            for (std::size_t k = 0; k < mask.size(); ++k)
                if (line_begin + k <= body->begin || line_begin + k >= body->end) mask[k] = false;
            // bool f(...), static bool f(...), [[nodiscard]] bool f(...): the word before the name.
            const std::string before_name = trim(body->header.substr(0, body->header.find(body->name + "(")));
            const bool returns_bool = before_name.size() >= 4 && before_name.substr(before_name.size() - 4) == "bool" &&
                                      (before_name.size() == 4 || !is_ident(before_name[before_name.size() - 5]));
            for (const auto& site : mutate_line(line, mask, returns_bool)) {
                Mutant m;
                m.topic = topic, m.function = body->name, m.op = site.op, m.line = line_number;
                m.before = trim(line), m.after = trim(site.line);
                m.source = s.substr(0, line_begin) + site.line + s.substr(line_end);
                std::size_t p = 0, q = 0;  // the common prefix and suffix of the line and its mutant
                while (p < line.size() && p < site.line.size() && line[p] == site.line[p]) ++p;
                while (q < line.size() - p && q < site.line.size() - p &&
                       line[line.size() - 1 - q] == site.line[site.line.size() - 1 - q])
                    ++q;
                m.change_from = line_begin + p, m.change_to = line_end - q;
                m.exercise = exercises.count(body->name) > 0;
                result.push_back(std::move(m));
            }
        }
        line_begin = line_end + 1;
        ++line_number;
    }
    return result;
}

// ---- The grading run's facts: topics and their exercises, from the manifest. ----

std::map<std::string, std::set<std::string>> manifest(const std::string& setup) {
    std::map<std::string, std::set<std::string>> topics;
    std::istringstream in(slurp(fs::path(setup) / "manifest.txt"));
    for (std::string line; std::getline(in, line);) {
        std::istringstream f(line);
        std::string kind, topic, exercise;
        std::getline(f, kind, '\t'), std::getline(f, topic, '\t'), std::getline(f, exercise, '\t');
        if (kind == "topic") topics[topic];
        if (kind == "exercise") topics[topic].insert(exercise);
    }
    if (topics.empty()) die("no topics in " + setup + "/manifest.txt: build the grading run first");
    return topics;
}

// A fixed-seed sample of n mutants per topic: the order of a hash of (seed, mutant), so the
// sample does not depend on the standard library's shuffle.
std::vector<Mutant> sample(std::vector<Mutant> all, int n, unsigned seed) {
    if (n <= 0) return all;
    auto key = [seed](const Mutant& m) {
        std::uint64_t h = 1469598103934665603ull ^ seed;
        for (char c : m.topic + m.function + m.after + std::to_string(m.line))
            h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
        return h;
    };
    std::stable_sort(all.begin(), all.end(), [&](const Mutant& a, const Mutant& b) {
        return a.topic != b.topic ? a.topic < b.topic : key(a) < key(b);
    });
    std::vector<Mutant> picked;
    std::map<std::string, int> taken;
    for (auto& m : all)
        if (taken[m.topic]++ < n) picked.push_back(std::move(m));
    return picked;
}

std::vector<Mutant> generate(const Options& o) {
    const auto topics = manifest(o.setup);
    std::vector<Mutant> all;
    for (const auto& [topic, exercises] : topics) {
        if (!o.topics.empty() && std::find(o.topics.begin(), o.topics.end(), topic) == o.topics.end()) continue;
        const fs::path file = fs::path(o.solutions) / (topic + ".cpp");
        if (!fs::exists(file)) die(file.string() + " does not exist");
        auto some = mutants_of(topic, file, exercises);
        all.insert(all.end(), std::make_move_iterator(some.begin()), std::make_move_iterator(some.end()));
    }
    for (const auto& t : o.topics)
        if (!topics.count(t)) die("'" + t + "' is not a topic with graders");
    all = sample(std::move(all), o.sample, o.seed);
    std::map<std::string, int> count;
    for (auto& m : all) m.id = m.topic + "-" + std::to_string(++count[m.topic]);
    if (!o.ids.empty()) {  // --mutant: again only these (ids as a run without --sample numbers them)
        for (const auto& id : o.ids)
            if (std::none_of(all.begin(), all.end(), [&](const Mutant& m) { return m.id == id; }))
                die("no mutant '" + id + "' (workbook_mutants list shows them)");
        std::erase_if(all, [&](const Mutant& m) { return std::find(o.ids.begin(), o.ids.end(), m.id) == o.ids.end(); });
    }
    return all;
}

// ---- The allowlist: "topic | function | mutated line | reason", one per line. ----

std::string allow_key(const std::string& topic, const std::string& function, const std::string& after) {
    return topic + "|" + function + "|" + after;
}

std::map<std::string, std::string> allowlist(const std::string& path) {
    std::map<std::string, std::string> allowed;
    if (path.empty()) return allowed;
    std::istringstream in(slurp(path));
    int n = 0;
    for (std::string line; std::getline(in, line);) {
        ++n;
        if (trim(line).empty() || trim(line)[0] == '#') continue;
        std::vector<std::string> f;
        std::size_t from = 0;
        for (int k = 0; k < 3; ++k) {
            const auto bar = line.find(" | ", from);
            if (bar == std::string::npos)
                die(path + ":" + std::to_string(n) + ": expected 'topic | function | mutated line | reason'");
            f.push_back(trim(line.substr(from, bar - from)));
            from = bar + 3;
        }
        const std::string reason = trim(line.substr(from));
        if (reason.size() < 20)
            die(path + ":" + std::to_string(n) + ": an equivalent mutant needs its reason (20 characters or more)");
        allowed[allow_key(f[0], f[1], f[2])] = reason;
    }
    return allowed;
}

// ---- Schemata: many mutants in one build. ----
// Compiling the mutated file is nearly all of a mutant's cost (2 to 9 CPU-seconds a file; a
// mutant's tests take well under one). So the mutants of a topic are built together, up to
// kSchemaSize in one file, a schema, in which each function body with mutants becomes
//     if (workbook_mutant_() == k1) { <body with mutant k1> } else if ... else { <body> }
// and the test's environment (WORKBOOK_MUTANT=k, workbook_grade check --test-env) picks the
// mutant when the test runs. The grading run compiles the schema once (--object-cache) and grades
// each mutant with its own k. Before that, the schema is graded with k = 0, the reference
// solution itself: it must build and pass every test. A mutant whose branch does not compile
// there is taken out and graded alone, the slow way (and then usually counts as not compiling).

constexpr std::size_t kSchemaSize = 40;

const char* const kSelector =
    "// The mutation gate's schema (tests/grading/mutants/mutants.cpp): the environment's\n"
    "// WORKBOOK_MUTANT picks one mutant; unset or 0, this is the reference solution.\n"
    "#include <cstdlib>\n"
    "namespace {\n"
    "[[maybe_unused]] int workbook_mutant_() {\n"
    "    static const int k = [] {\n"
    "        const char* e = std::getenv(\"WORKBOOK_MUTANT\");\n"
    "        return e ? std::atoi(e) : 0;\n"
    "    }();\n"
    "    return k;\n"
    "}\n"
    "}  // namespace\n";

struct Schema {
    std::string topic, name, text;
    std::vector<std::size_t> members;                  // indices into the run's mutants
    std::map<std::size_t, std::pair<int, int>> lines;  // member -> its branch's first and last line
};

int lines_in(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// The schema of `members` (mutants of one topic; their selectors are set here).
Schema make_schema(const std::string& name, const std::string& original, std::vector<Mutant>& mutants,
                   const std::vector<std::size_t>& members) {
    const auto bodies = function_bodies(original, code_mask(original));
    std::map<std::size_t, std::vector<std::size_t>> by_body;  // body index -> members in it
    for (std::size_t i : members) {
        const Mutant& m = mutants[i];
        for (std::size_t b = 0; b < bodies.size(); ++b)
            if (bodies[b].begin < m.change_from && m.change_to <= bodies[b].end) by_body[b].push_back(i);
    }
    Schema sc{mutants[members.front()].topic, name, kSelector, {}, {}};
    std::size_t at = 0;
    for (const auto& [b, inside] : by_body) {
        const Body& body = bodies[b];
        sc.text += original.substr(at, body.begin + 1 - at) + "\n";
        for (std::size_t i : inside) {
            Mutant& m = mutants[i];
            m.selector = static_cast<int>(i) + 1;
            const std::size_t tail = original.size() - m.change_to;  // the unchanged end of the file
            const std::string mutated = original.substr(body.begin + 1, m.change_from - body.begin - 1) +
                                        m.source.substr(m.change_from, m.source.size() - tail - m.change_from) +
                                        original.substr(m.change_to, body.end - m.change_to);
            const int first = lines_in(sc.text) + 1;
            sc.text += "if (workbook_mutant_() == " + std::to_string(m.selector) + ") {" + mutated + "\n} else ";
            sc.lines[i] = {first, lines_in(sc.text) + 1};
            sc.members.push_back(i);
        }
        sc.text += "{" + original.substr(body.begin + 1, body.end - body.begin - 1) + "\n}\n";
        at = body.end;
    }
    sc.text += original.substr(at);
    return sc;
}

// The lines of exercises/<topic>.cpp that a failed build's log names (errors, notes, "required from").
std::set<int> named_lines(const std::string& log, const std::string& topic) {
    std::set<int> lines;
    const std::regex re("exercises/" + topic + R"(\.cpp:(\d+):)");
    for (auto it = std::sregex_iterator(log.begin(), log.end(), re); it != std::sregex_iterator(); ++it)
        lines.insert(std::stoi((*it)[1]));
    return lines;
}

pid_t start_check(const Options& o, const Mutant& m, const fs::path& folder, const fs::path& out, bool whole_topic);

// Grades the schema with WORKBOOK_MUTANT=0 until it builds and passes: a branch that does not build
// is taken out (its mutant graded alone); a schema that still fails after that is given up (all
// its mutants graded alone). Returns whether the schema stands.
bool settle(const Options& o, Schema& sc, std::vector<Mutant>& mutants, const fs::path& dir,
            const std::string& original) {
    for (int attempt = 0; attempt < 6 && !sc.members.empty(); ++attempt) {
        const fs::path folder = dir / sc.name / "exercises", out = dir / sc.name / "reference";
        fs::create_directories(folder);
        std::ofstream(folder / (sc.topic + ".cpp")) << sc.text;
        Mutant reference = mutants[sc.members.front()];
        reference.selector = 0;
        int status = 0;
        waitpid(start_check(o, reference, folder, out, true), &status, 0);
        const fs::path result = out / "results.json";
        if (!fs::exists(result)) break;
        const json r = json::parse(slurp(result));
        bool built = true, passed = true;
        for (const auto& t : r.at("tests")) {
            if (t.at("extra_data").at("topic") != sc.topic) continue;  // the other topics are missing
            built = built && t.at("extra_data").at("verdict") != to_string(Verdict::build_error);
            passed = passed && t.at("extra_data").at("verdict") == to_string(Verdict::pass);
        }
        if (passed) return true;
        if (built) break;  // the reference fails a test inside the schema: do not trust it
        const fs::path log = out / "logs" / (sc.topic + ".build.txt");
        const std::set<int> named = named_lines(fs::exists(log) ? slurp(log) : "", sc.topic);
        std::vector<std::size_t> keep, out_of_it;
        for (std::size_t i : sc.members) {
            const auto [first, last] = sc.lines.at(i);
            const bool broken = std::any_of(named.begin(), named.end(), [&](int l) { return first <= l && l <= last; });
            (broken ? out_of_it : keep).push_back(i);
        }
        if (out_of_it.empty()) break;  // the log names no branch: give the schema up
        for (std::size_t i : out_of_it) mutants[i].selector = 0;
        sc = make_schema(sc.name, original, mutants, keep);
    }
    for (std::size_t i : sc.members) mutants[i].selector = 0;
    std::fprintf(stderr,
                 "workbook_mutants: schema %s does not pass with the reference; its %zu mutants are built one by one\n",
                 sc.name.c_str(), sc.members.size());
    sc.members.clear();
    return false;
}

// Puts the mutants (of the run) into schemata under <out>/schemata, kSchemaSize at a time per topic.
void build_schemata(const Options& o, std::vector<Mutant>& mutants, const fs::path& out) {
    const fs::path dir = out / "schemata";
    fs::remove_all(dir);
    std::map<std::string, std::vector<std::size_t>> by_topic;
    for (std::size_t i = 0; i < mutants.size(); ++i) by_topic[mutants[i].topic].push_back(i);
    for (const auto& [topic, all] : by_topic) {
        const std::string original = slurp(fs::path(o.solutions) / (topic + ".cpp"));
        for (std::size_t from = 0; from < all.size(); from += kSchemaSize) {
            const std::vector<std::size_t> members(
                all.begin() + static_cast<std::ptrdiff_t>(from),
                all.begin() + static_cast<std::ptrdiff_t>(std::min(all.size(), from + kSchemaSize)));
            Schema sc = make_schema(topic + "-" + std::to_string(from / kSchemaSize + 1), original, mutants, members);
            const std::size_t n = sc.members.size();
            if (settle(o, sc, mutants, dir, original)) {
                for (std::size_t i : sc.members) mutants[i].schema = (dir / sc.name / "exercises").string();
                std::fprintf(stderr, "workbook_mutants: schema %s: %zu of %zu mutants in one build\n", sc.name.c_str(),
                             sc.members.size(), n);
            }
        }
    }
}

// ---- Grading: each mutant is a submission holding that one file, graded by the grading run's
// student check (workbook_grade check: the same build flags, isolation, limits and verdicts as
// `grade`) on what can kill it: its exercise, or its whole topic for a helper. Tests of the
// topic's other exercises cannot kill an exercise's mutant, so they are not run. ----

void write_submissions(const std::vector<Mutant>& mutants, const fs::path& folder) {
    fs::remove_all(folder);
    for (const auto& m : mutants) {
        if (m.selector) continue;  // graded from its schema's folder
        fs::create_directories(folder / m.id / "exercises");
        std::ofstream(folder / m.id / "exercises" / (m.topic + ".cpp")) << m.source;
    }
}

// Starts `workbook_grade check` on one mutant (its file in `folder`), its results in `out` and its
// output in <out>.log; returns the pid. A schema's mutant runs with WORKBOOK_MUTANT set to its
// selector (0: the reference), and the schema is compiled once for all of them.
pid_t start_check(const Options& o, const Mutant& m, const fs::path& folder, const fs::path& out, bool whole_topic) {
    const std::string harness = (fs::path(o.setup) / "workbook_grade").string();
    std::vector<std::string> args = {harness,           "check",
                                     "--setup",         o.setup,
                                     "--folder",        folder.string(),
                                     "--out",           out.string(),
                                     "--timeout",       std::to_string(o.timeout),
                                     "--build-timeout", std::to_string(o.build_timeout)};
    if (m.selector || !m.schema.empty() || whole_topic) {
        args.insert(args.end(), {"--test-env", "WORKBOOK_MUTANT=" + std::to_string(m.selector), "--object-cache",
                                 (fs::path(o.out) / "objects").string(), "--max-file-size", "16384"});
    }
    // A helper's mutant: every topic (the others are missing from the submission, so not built;
    // naming the topic could select an exercise of the same name, such as heavy_top).
    if (m.exercise && !whole_topic) args.push_back(m.function);
    support::RunOptions output;
    output.stdout_file = out.string() + ".log";
    output.stderr_to_stdout = true;
    std::string error;
    const pid_t pid = support::spawn(args, output, &error);
    if (pid < 0) die("cannot start workbook_grade: " + error);
    return pid;
}

// Grades every mutant, o.jobs at a time; `done(k, status)` is called as mutant k finishes.
void run_checks(const Options& o, const std::vector<Mutant>& mutants, const fs::path& submissions,
                const fs::path& checks, const std::function<void(std::size_t, int)>& done) {
    fs::remove_all(checks);
    fs::create_directories(checks);
    std::map<pid_t, std::size_t> running;
    std::size_t next = 0;
    while (next < mutants.size() || !running.empty()) {
        while (next < mutants.size() && static_cast<int>(running.size()) < o.jobs) {
            const Mutant& m = mutants[next];
            const fs::path folder = m.selector ? fs::path(m.schema) : submissions / m.id / "exercises";
            running[start_check(o, m, folder, checks / m.id, false)] = next;
            ++next;
        }
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) die("waitpid failed");
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        done(it->second, WIFEXITED(status) ? WEXITSTATUS(status) : 128);
        running.erase(it);
    }
}

void classify(Mutant& m, const json& result, const std::map<std::string, std::string>& allowed) {
    bool killed = false, build_error = false;
    for (const auto& t : result.at("tests")) {
        const auto& x = t.at("extra_data");
        if (x.at("topic") != m.topic) continue;
        const std::string verdict = x.at("verdict");
        if (verdict == to_string(Verdict::build_error)) {
            const std::string why = t.at("output");
            // The grading run's own limits, not the mutant: the verdict would be the machine's.
            if (why.find("of processor time, its budget") != std::string::npos ||
                why.find("wall-clock backstop") != std::string::npos ||
                why.find("was killed by") != std::string::npos || why.find("could not run the") != std::string::npos)
                die("mutant " + m.id + " could not be built within the limits (" + why +
                    "): run again with a larger --build-timeout");
            build_error = true;
        }
        if (verdict != to_string(Verdict::pass) && (!m.exercise || x.at("exercise") == m.function)) {
            killed = true;
            if (m.evidence.empty()) m.evidence = verdict + ": " + t.at("name").get<std::string>();
        }
    }
    const auto a = allowed.find(allow_key(m.topic, m.function, m.after));
    if (build_error)
        m.status = "not compiling";
    else if (killed)
        m.status = "killed";
    else if (a != allowed.end())
        m.status = "equivalent", m.evidence = a->second;
    else
        m.status = "survived";
    if (killed && a != allowed.end())
        m.evidence += " (listed as equivalent in the allowlist, yet killed: remove that entry)";
}

// ---- The report: a table per topic and per exercise, then the survivors. ----

struct Tally {
    int mutants = 0, killed = 0, survived = 0, equivalent = 0, broken = 0;
    void add(const Mutant& m) {
        ++mutants;
        killed += m.status == "killed", survived += m.status == "survived";
        equivalent += m.status == "equivalent", broken += m.status == "not compiling";
    }
};

std::string row(const std::string& name, const Tally& t) {
    std::ostringstream s;
    s << "| " << name << " | " << t.mutants << " | " << t.killed << " | " << t.survived << " | " << t.equivalent
      << " | " << t.broken << " |\n";
    return s.str();
}

std::string report(const std::vector<Mutant>& mutants, double seconds, const Options& o) {
    std::map<std::string, Tally> topic, exercise;
    Tally all;
    for (const auto& m : mutants) {
        topic[m.topic].add(m), exercise[m.topic + "::" + (m.exercise ? m.function : "(helpers)")].add(m), all.add(m);
    }
    std::ostringstream s;
    s << "# Mutation gate\n\n"
      << all.mutants << " mutants of solutions/ ("
      << (o.sample ? "a sample of " + std::to_string(o.sample) + " per topic, seed " + std::to_string(o.seed)
                   : "all of them")
      << "), graded in " << static_cast<int>(seconds + 0.5) << " s with -j " << o.jobs << ".\n\n";
    const std::string head =
        "| mutants | killed | survived | equivalent | not compiling |\n|---|---:|---:|---:|---:|---:|\n";
    s << "| topic " << head;
    for (const auto& [name, t] : topic) s << row(name, t);
    s << row("**all**", all) << "\n## Per exercise\n\n| exercise " << head;
    for (const auto& [name, t] : exercise) s << row(name, t);
    s << "\n## Survivors and equivalents\n\n";
    for (const auto& m : mutants)
        if (m.status == "survived" || m.status == "equivalent")
            s << "- **" << m.status << "** " << m.id << " (" << m.op << ", " << m.topic << ".cpp:" << m.line << ", "
              << m.function << "): `" << m.before << "` → `" << m.after << "`"
              << (m.evidence.empty() ? "" : ": " + m.evidence) << "\n";
    return s.str();
}

json to_json(const Mutant& m) {
    return {{"id", m.id},         {"topic", m.topic},      {"function", m.function}, {"exercise", m.exercise},
            {"operator", m.op},   {"line", m.line},        {"before", m.before},     {"after", m.after},
            {"status", m.status}, {"evidence", m.evidence}};
}

int run(const Options& o) {
    auto mutants = generate(o);
    const auto allowed = allowlist(o.allow);
    const fs::path out = o.out, submissions = out / "submissions", checks = out / "checks";
    fs::create_directories(out);
    if (!o.one_by_one) build_schemata(o, mutants, out);
    write_submissions(mutants, submissions);
    std::fprintf(stderr, "workbook_mutants: grading %zu mutants with -j %d\n", mutants.size(), o.jobs);
    const auto start = std::chrono::steady_clock::now();
    std::size_t finished = 0;
    run_checks(o, mutants, submissions, checks, [&](std::size_t k, int status) {
        Mutant& m = mutants[k];
        // check exits 0 (all pass) or 1 (a test does not pass); anything else is the harness's.
        const fs::path result = checks / m.id / "results.json";
        if ((status != 0 && status != 1) || !fs::exists(result))
            die("the grading run failed on mutant " + m.id + " (status " + std::to_string(status) + "): see " +
                (checks / (m.id + ".log")).string());
        classify(m, json::parse(slurp(result)), allowed);
        std::fprintf(stderr, "  [%zu/%zu] %-14s %-13s %s:%d %s\n", ++finished, mutants.size(), m.id.c_str(),
                     m.status.c_str(), m.topic.c_str(), m.line, m.function.c_str());
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    json all = json::array();
    for (const auto& m : mutants) all.push_back(to_json(m));
    const std::string text = report(mutants, seconds, o);
    std::ofstream(out / "mutants.md") << text;
    std::ofstream(out / "mutants.json") << all.dump(1) << "\n";
    std::fputs(text.c_str(), stdout);
    const auto survivors =
        std::count_if(mutants.begin(), mutants.end(), [](const Mutant& m) { return m.status == "survived"; });
    if (survivors)
        std::fprintf(stderr, "workbook_mutants: %ld mutant(s) survived: a grader misses a wrong answer\n",
                     static_cast<long>(survivors));
    return survivors ? 1 : 0;
}

// catalogue: the likely mistakes of the gate's run in --from (README.md, "Likely mistakes, named");
// stale: whether the committed catalogue still has the hash of this tree's graders and solutions.
// For each exercise of the topic, the other exercises its reference body calls, directly or through
// helpers (calls.hpp): a failure of those may be what makes it fail, so it is then not named.
std::map<std::string, std::set<std::string>> uses_of(const fs::path& file, const std::set<std::string>& exercises) {
    return grading::calls::uses_of(slurp(file), exercises);
}

int catalogue(const Options& o) {
    std::map<std::string, std::map<std::string, std::set<std::string>>> uses;  // topic -> exercise -> uses
    for (const auto& [topic, exercises] : manifest(o.setup))
        if (o.topics.empty() || std::find(o.topics.begin(), o.topics.end(), topic) != o.topics.end())
            uses[topic] = uses_of(fs::path(o.solutions) / (topic + ".cpp"), exercises);
    std::vector<mutants::Listed> listed;
    for (const auto& m : generate(o))
        listed.push_back({m.id, m.topic, m.function, m.op, m.line, m.before, m.after, m.exercise});
    const std::string root = (fs::absolute(o.solutions) / "").lexically_normal().parent_path().parent_path().string();
    const std::string manifest_text = slurp(fs::path(o.setup) / "manifest.txt");
    if (o.command == "stale") return mutants::check_fresh(root, manifest_text, o.catalogue, listed);
    return mutants::write_catalogue(root, manifest_text, o.from, o.catalogue, listed, uses);
}

// The options of run, list, catalogue and stale (each takes them all; the usage above).
void command_options(CLI::App& app, Options& o) {
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    for (const auto& [name, value] : {std::pair{"--setup", &o.setup},
                                      {"--solutions", &o.solutions},
                                      {"--out", &o.out},
                                      {"--allow", &o.allow},
                                      {"--from", &o.from},
                                      {"--catalogue", &o.catalogue}})
        app.add_option(name, *value);
    app.add_option("--topic", o.topics)->allow_extra_args(false)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option("--mutant", o.ids)->allow_extra_args(false)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    const auto at_least = [](double lo) {
        return [lo](const std::string& v) {
            char* end = nullptr;
            const double x = std::strtod(v.c_str(), &end);
            return end != v.c_str() && !*end && x >= lo
                       ? std::string()
                       : "needs a number >= " + std::to_string(int(lo)) + ", not '" + v + "'";
        };
    };
    app.add_option("--sample", o.sample)->check(at_least(1));
    app.add_option("--seed", o.seed)->check(at_least(0));
    app.add_option("-j", o.jobs)->check(at_least(1));
    app.add_option("--timeout", o.timeout)->check(at_least(1));
    app.add_option("--build-timeout", o.build_timeout)->check(at_least(1));
    app.add_flag("--one-by-one", o.one_by_one);
}

// What each command needs; a missing one exits with status 2.
void require(const Options& o) {
    if (o.setup.empty() || o.solutions.empty()) die("--setup and --solutions are required");
    if (o.command == "run" && o.out.empty()) die("run needs --out <folder>");
    if (o.command == "catalogue" && (o.from.empty() || o.catalogue.empty()))
        die("catalogue needs --from <the gate's out folder> and --catalogue <folder>");
    if (o.command == "stale" && o.catalogue.empty()) die("stale needs --catalogue <folder>");
}

// audit --catalogue <dir> --results <grades>/results [--may-name <student>]... [--plant] [--measure]
struct Audit {
    std::string catalogue, results;
    std::vector<std::string> may_name;
    bool plant = false, measure = false;
};

void audit_options(CLI::App& app, Audit& a) {
    app.add_flag("--measure", a.measure);
    app.add_option("--catalogue", a.catalogue)->required();
    app.add_option("--results", a.results)->required();
    app.add_option("--may-name", a.may_name);
    app.add_flag("--plant", a.plant);
}

int list(const Options& o) {
    for (const auto& m : generate(o))
        std::printf("%s\t%s\t%s\t%d\t%s\t%s\n", m.id.c_str(), m.function.c_str(), m.op.c_str(), m.line,
                    m.before.c_str(), m.after.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string usage =
        "usage: workbook_mutants run|list|catalogue|stale --setup <build>/grading --solutions <dir> [--out <dir>] "
        "[--topic T] [--mutant ID] [--sample N --seed S] [--allow F] [-j N] [--timeout s] [--build-timeout s] "
        "[--one-by-one]\n       workbook_mutants audit --catalogue <dir> --results <dir> [--may-name S]... [--plant] "
        "[--measure]";
    Options o;
    Audit a;
    CLI::App app{"workbook_mutants: the mutation gate (tests/grading/README.md, \"The mutation gate\")"};
    app.set_help_flag();
    app.require_subcommand(1);
    for (const char* name : {"run", "list", "catalogue", "stale"})
        command_options(*app.add_subcommand(name)->callback([&o, name] { o.command = name; }), o);
    CLI::App* audit_command = app.add_subcommand("audit");
    audit_options(*audit_command, a);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        die(std::string(e.what()) + "\n" + usage);
    }
    if (audit_command->parsed())
        return a.measure ? mutants::measure(a.catalogue, a.results)
                         : mutants::audit(a.catalogue, a.results, a.may_name, a.plant);
    require(o);
    if (o.command == "list") return list(o);
    if (o.command == "catalogue" || o.command == "stale") return catalogue(o);
    return run(o);
}
