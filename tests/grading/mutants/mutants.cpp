// workbook_mutants: the mutation gate (README.md, "The mutation gate").
//
//   workbook_mutants run --setup <build>/grading --solutions <dir> --out <dir>
//                        [--topic T]... [--mutant ID]... [--sample N --seed S] [--allow <file>] [-j N]
//                        [--timeout s] [--build-timeout s]
//   (--mutant grades again only the mutants of these ids, e.g. the survivors of a full run)
//   workbook_mutants list --setup <build>/grading --solutions <dir> [--topic T]... [--sample N --seed S]
//
// A mutant is the reference solution solutions/<topic>.cpp with one plausible wrong change, made
// by one of a fixed set of operators (mutate_line below; comments, string and character literals
// and preprocessor lines are never touched). Each mutant is a submission holding that one file,
// graded by the grading run (workbook_grade check: its build flags, per-test isolation, limits
// and verdicts), -j at a time. A mutant inside an exercise function is killed when a test of
// that exercise does not pass, so only that exercise's tests are run; a mutant inside a helper
// of the file is killed when any test of the topic does not pass, so all of them are run. A
// mutant that does not build is counted apart. A survivor is equivalent only when allowed.txt
// lists it, with the reason; any other survivor fails the run (exit 1): a grader to strengthen.
#include <sys/wait.h>
#include <unistd.h>

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

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

struct Mutant {
    std::string id, topic, function, op;
    int line = 0;                  // 1-based line of solutions/<topic>.cpp
    std::string before, after;     // the line, trimmed, before and after the change
    std::string source;            // the whole mutated file
    bool exercise = false;         // function is an exercise of the topic (else a helper)
    std::string status, evidence;  // killed | survived | equivalent | not compiling
};

struct Options {
    std::string command, setup, solutions, out, allow;
    std::vector<std::string> topics, ids;
    int sample = 0, jobs = 2;
    unsigned seed = 1;
    double timeout = 30, build_timeout = 900;  // generous: a loaded machine must not kill a mutant
};

[[noreturn]] void die(const std::string& message) {
    std::fprintf(stderr, "workbook_mutants: %s\n", message.c_str());
    std::exit(2);
}

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) die("cannot read " + path.string());
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// ---- Where code is: a mask over the file, false inside comments, literals and # lines. ----

std::vector<bool> code_mask(const std::string& s) {
    std::vector<bool> code(s.size(), true);
    std::size_t i = 0;
    bool line_start = true;
    auto blank = [&](std::size_t from, std::size_t to) {
        for (std::size_t k = from; k < to && k < s.size(); ++k) code[k] = false;
    };
    while (i < s.size()) {
        const char c = s[i];
        std::size_t end = i + 1;
        if (line_start && c == '#') {
            end = s.find('\n', i);
        } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            end = s.find('\n', i);
        } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            end = s.find("*/", i + 2);
            end = end == std::string::npos ? end : end + 2;
        } else if (c == '"' || c == '\'') {
            end = i + 1;
            while (end < s.size() && s[end] != c) end += s[end] == '\\' ? 2 : 1;
            ++end;
        } else {
            if (c == '\n')
                line_start = true;
            else if (c != ' ' && c != '\t')
                line_start = false;
            ++i;
            continue;
        }
        if (end == std::string::npos || end > s.size()) end = s.size();
        blank(i, end);
        i = end;
    }
    return code;
}

// ---- Which function each character belongs to: namespace-level bodies, by brace depth. ----

struct Body {
    std::size_t begin, end;  // the braces' positions
    std::string name, header;
};

bool is_ident(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The name of the function whose header ends at `open` (a '{'), or "" if it is not a function.
std::string function_name(const std::string& s, const std::vector<bool>& code, std::size_t from, std::size_t open,
                          std::string* header) {
    std::string h;
    for (std::size_t k = from; k < open; ++k) h += code[k] ? s[k] : ' ';
    *header = trim(h);
    const auto paren = h.find('(');
    if (paren == std::string::npos || h.find("namespace") != std::string::npos) return "";
    auto e = paren;
    while (e > 0 && h[e - 1] == ' ') --e;
    auto b = e;
    while (b > 0 && is_ident(h[b - 1])) --b;
    return h.substr(b, e - b);
}

std::vector<Body> function_bodies(const std::string& s, const std::vector<bool>& code) {
    std::vector<Body> bodies;
    std::vector<bool> is_function;  // a stack: true for a function's brace
    std::size_t header_from = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!code[i]) continue;
        const bool inside = std::find(is_function.begin(), is_function.end(), true) != is_function.end();
        if (s[i] == '{') {
            std::string header, name;
            if (!inside) name = function_name(s, code, header_from, i, &header);
            is_function.push_back(!name.empty());
            if (!name.empty()) bodies.push_back({i, std::string::npos, name, header});
        } else if (s[i] == '}') {
            if (is_function.empty()) die("unbalanced braces");
            if (is_function.back() && std::count(is_function.begin(), is_function.end(), true) == 1)
                bodies.back().end = i;
            is_function.pop_back();
        }
        const bool inside_now = std::find(is_function.begin(), is_function.end(), true) != is_function.end();
        if (!inside_now && (s[i] == ';' || s[i] == '{' || s[i] == '}')) header_from = i + 1;
    }
    return bodies;
}

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
            const bool returns_bool = body->header.rfind("bool ", 0) == 0;
            for (const auto& site : mutate_line(line, mask, returns_bool)) {
                Mutant m;
                m.topic = topic, m.function = body->name, m.op = site.op, m.line = line_number;
                m.before = trim(line), m.after = trim(site.line);
                m.source = s.substr(0, line_begin) + site.line + s.substr(line_end);
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

// ---- Grading: each mutant is a submission holding that one file, graded by the grading run's
// student check (workbook_grade check: the same build flags, isolation, limits and verdicts as
// `grade`) on what can kill it: its exercise, or its whole topic for a helper. Tests of the
// topic's other exercises cannot kill an exercise's mutant, so they are not run. ----

void write_submissions(const std::vector<Mutant>& mutants, const fs::path& folder) {
    fs::remove_all(folder);
    for (const auto& m : mutants) {
        fs::create_directories(folder / m.id / "exercises");
        std::ofstream(folder / m.id / "exercises" / (m.topic + ".cpp")) << m.source;
    }
}

// Starts `workbook_grade check` on one mutant, its output to <checks>/<id>.log; returns the pid.
pid_t start_check(const Options& o, const Mutant& m, const fs::path& submissions, const fs::path& checks) {
    const std::string harness = (fs::path(o.setup) / "workbook_grade").string();
    std::vector<std::string> args = {harness,           "check",
                                     "--setup",         o.setup,
                                     "--folder",        (submissions / m.id / "exercises").string(),
                                     "--out",           (checks / m.id).string(),
                                     "--timeout",       std::to_string(o.timeout),
                                     "--build-timeout", std::to_string(o.build_timeout)};
    // A helper's mutant: every topic (the others are missing from the submission, so not built;
    // naming the topic could select an exercise of the same name, such as heavy_top).
    if (m.exercise) args.push_back(m.function);
    const std::string log = (checks / (m.id + ".log")).string();
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) die("cannot fork");
    if (pid == 0) {
        if (!std::freopen(log.c_str(), "w", stdout) || dup2(fileno(stdout), 2) < 0) _exit(127);
        execv(argv[0], argv.data());
        std::perror("workbook_mutants: cannot start workbook_grade");
        _exit(127);
    }
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
            running[start_check(o, mutants[next], submissions, checks)] = next;
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
        if (verdict == "build error") {
            const std::string why = t.at("output");
            // The grading run's own limits, not the mutant: the verdict would be the machine's.
            if (why.find("took longer than") != std::string::npos || why.find("was killed by") != std::string::npos ||
                why.find("could not run the") != std::string::npos)
                die("mutant " + m.id + " could not be built within the limits (" + why +
                    "): run again on a quieter machine or with a larger --build-timeout");
            build_error = true;
        }
        if (verdict != "pass" && (!m.exercise || x.at("exercise") == m.function)) {
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

Options parse(int argc, char** argv) {
    Options o;
    if (argc < 2)
        die("usage: workbook_mutants run|list --setup <build>/grading --solutions <dir> [--out <dir>] [--topic T] "
            "[--mutant ID] [--sample N --seed S] [--allow F] [-j N] [--timeout s] [--build-timeout s]");
    o.command = argv[1];
    if (o.command != "run" && o.command != "list") die("unknown command '" + o.command + "' (run or list)");
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) die(a + " needs a value");
            return argv[++i];
        };
        auto number = [&](double lo) {
            const std::string v = value();
            char* end = nullptr;
            const double x = std::strtod(v.c_str(), &end);
            if (*end || !(x >= lo))
                die(a + " needs a number >= " + std::to_string(static_cast<int>(lo)) + ", not '" + v + "'");
            return x;
        };
        if (a == "--setup")
            o.setup = value();
        else if (a == "--solutions")
            o.solutions = value();
        else if (a == "--out")
            o.out = value();
        else if (a == "--allow")
            o.allow = value();
        else if (a == "--topic")
            o.topics.push_back(value());
        else if (a == "--mutant")
            o.ids.push_back(value());
        else if (a == "--sample")
            o.sample = static_cast<int>(number(1));
        else if (a == "--seed")
            o.seed = static_cast<unsigned>(number(0));
        else if (a == "-j")
            o.jobs = static_cast<int>(number(1));
        else if (a == "--timeout")
            o.timeout = number(1);
        else if (a == "--build-timeout")
            o.build_timeout = number(1);
        else
            die("unknown option '" + a + "'");
    }
    if (o.setup.empty() || o.solutions.empty()) die("--setup and --solutions are required");
    if (o.command == "run" && o.out.empty()) die("run needs --out <folder>");
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    if (o.command == "list") {
        for (const auto& m : generate(o))
            std::printf("%s\t%s\t%s\t%d\t%s\t%s\n", m.id.c_str(), m.function.c_str(), m.op.c_str(), m.line,
                        m.before.c_str(), m.after.c_str());
        return 0;
    }
    return run(o);
}
