// grading_class: the class of 30 submissions that the cluster, Gradescope and similarity tests
// grade, and the checks of what they write.
//
//   grading_class make --setup <build>/grading --out <submissions> --expect <expected.tsv> [--size 30|10]
//   grading_class check --setup <build>/grading --class <submissions> --expect <expected.tsv>
//                       --grades <out-folder> [--size <at least>]
//   grading_class schema <results.json> [--score <s>] [--max-score <m>]
//
// make writes the class for the topic rotation: copies of the reference that the similarity
// report must list (verbatim, in both layouts, renamed, disguised, reordered, copied again, half
// copied), a copy between two students, three honest solutions written by hand from the
// contracts (tests/grading/tests/similarity/), untouched stubs, missing files, broken builds, wrong
// answers and crashes; expected.tsv says what each must get. The copies are made here from
// solutions/rotation.cpp by plain text edits, independently of the report's own tokenizer.
// check reads the report (and, with --grades, the results, class.csv and the LMS files) and
// says what does not hold; it also prints every honest and planted score, listed or not.
// schema checks one results.json against Gradescope's format.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "grading.hpp"

using namespace grading;

namespace {

const std::string kTopic = "rotation";

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool has_word(const std::string& text, const std::string& word) {
    for (std::size_t p = text.find(word); p != std::string::npos; p = text.find(word, p + 1))
        if ((p == 0 || !word_char(text[p - 1])) &&
            (p + word.size() >= text.size() || !word_char(text[p + word.size()])))
            return true;
    return false;
}

// ---- text edits that disguise a copy --------------------------------------------------------

std::string strip_comments(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '"') {  // a string literal, kept whole
            const std::size_t start = i;
            for (++i; i < s.size() && s[i] != '"'; ++i) i += s[i] == '\\';
            out += s.substr(start, i - start + 1);
        } else if (s.compare(i, 2, "//") == 0) {
            while (i < s.size() && s[i] != '\n') ++i;
            out += '\n';
        } else if (s.compare(i, 2, "/*") == 0) {
            const std::size_t end = s.find("*/", i + 2);
            i = end == std::string::npos ? s.size() : end + 1;
        } else {
            out += s[i];
        }
    }
    return out;
}

// Names the file declares (parameters, variables), found by their types: what a copier renames.
std::set<std::string> declared(const std::string& s, const std::set<std::string>& keep) {
    static const std::vector<std::string> types = {"Mat3", "Vec3", "double",    "bool",
                                                   "int",  "auto", "AxisAngle", "Index"};
    std::set<std::string> names;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!word_char(s[i]) || (i > 0 && word_char(s[i - 1]))) continue;
        std::size_t e = i;
        while (e < s.size() && word_char(s[e])) ++e;
        const std::string word = s.substr(i, e - i);
        std::size_t n = e;
        while (n < s.size() && (s[n] == ' ' || s[n] == '&' || s[n] == '*')) ++n;
        const bool after_type = std::find(types.begin(), types.end(), word) != types.end() && n > e;
        if (after_type && n < s.size() && word_char(s[n]) && !std::isdigit(static_cast<unsigned char>(s[n]))) {
            std::size_t m = n;
            while (m < s.size() && word_char(s[m])) ++m;
            const std::string name = s.substr(n, m - n);
            if (!keep.count(name) && name != "const") names.insert(name);
        }
        i = e - 1;
    }
    // The second name of "const double c = ..., s = ...".
    for (std::size_t p = s.find(", "); p != std::string::npos; p = s.find(", ", p + 1)) {
        std::size_t m = p + 2;
        while (m < s.size() && word_char(s[m])) ++m;
        if (m > p + 2 && s.compare(m, 3, " = ") == 0 && !keep.count(s.substr(p + 2, m - p - 2)))
            names.insert(s.substr(p + 2, m - p - 2));
    }
    return names;
}

// Renames whole words, except members and qualified names (after ".", "->" or "::").
std::string rename(const std::string& s, const std::map<std::string, std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        if (!word_char(s[i]) || (i > 0 && word_char(s[i - 1]))) {
            out += s[i++];
            continue;
        }
        std::size_t e = i;
        while (e < s.size() && word_char(s[e])) ++e;
        const std::string word = s.substr(i, e - i);
        const bool member =
            (i > 0 && s[i - 1] == '.') || (i > 1 && (s.compare(i - 2, 2, "::") == 0 || s.compare(i - 2, 2, "->") == 0));
        const auto it = names.find(word);
        out += (it != names.end() && !member) ? it->second : word;
        i = e;
    }
    return out;
}

std::map<std::string, std::string> new_names(const std::string& s, const std::set<std::string>& keep, int seed) {
    static const std::vector<std::string> pool = {
        "tmp", "val", "res", "out", "mat", "vec", "ang", "len", "idx", "cv", "sv", "m1", "m2", "p1", "p2", "x1", "x2",
        "y1",  "y2",  "k1",  "k2",  "t1",  "t2",  "g1",  "h1",  "e1",  "e2", "u1", "w1", "z1", "z2", "q7", "r7", "s7"};
    std::map<std::string, std::string> names;
    std::size_t k = static_cast<std::size_t>(seed) * 7;
    for (const auto& name : declared(s, keep)) {
        std::string fresh;
        do fresh = pool[k % pool.size()] + (k >= pool.size() ? std::to_string(k / pool.size()) : "");
        while (++k, has_word(s, fresh));
        names[name] = fresh;
    }
    return names;
}

// Allman braces, tabs for indentation, no spaces around "=" or after ",".
std::string reformat(const std::string& s) {
    std::string out;
    int depth = 0;
    for (std::string line : split(s, '\n')) {
        line = replace_all(replace_all(trim(line), " = ", "="), ", ", ",");
        if (line.empty()) continue;
        const bool opens = line.size() > 1 && line.back() == '{' && line[0] != '#';
        if (opens) line = trim(line.substr(0, line.size() - 1));
        if (!line.empty() && line[0] == '}') --depth;
        out += std::string(static_cast<std::size_t>(std::max(depth, 0)), '\t') + line + "\n";
        if (opens) out += std::string(static_cast<std::size_t>(std::max(depth, 0)), '\t') + "{\n";
        depth += static_cast<int>(std::count(line.begin(), line.end(), '{')) -
                 static_cast<int>(std::count(line.begin(), line.end(), '}')) + (opens ? 1 : 0) +
                 (!line.empty() && line[0] == '}' ? 1 : 0);
    }
    return out;
}

// std::cos becomes cos under "using namespace std;"; 0.5 becomes 0.5e0 and 1e-9 becomes 1.0e-9.
std::string respell(const std::string& s) {
    std::string text = replace_all(s, "std::", "");
    const std::size_t last_include = text.rfind("#include");
    const std::size_t line_end = text.find('\n', last_include);
    if (last_include != std::string::npos && line_end != std::string::npos)
        text.insert(line_end + 1, "using namespace std;\n");
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        if (!std::isdigit(static_cast<unsigned char>(text[i])) ||
            (i > 0 && (word_char(text[i - 1]) || text[i - 1] == '.'))) {
            out += text[i++];
            continue;
        }
        std::size_t e = i;
        while (e < text.size() &&
               (word_char(text[e]) || text[e] == '.' || ((text[e] == '-' || text[e] == '+') && (text[e - 1] == 'e'))))
            ++e;
        std::string number = text.substr(i, e - i);
        if (number.find('.') != std::string::npos && number.find('e') == std::string::npos)
            number += "e0";
        else if (number.find('e') != std::string::npos && number.find('.') == std::string::npos)
            number.insert(number.find('e'), ".0");
        out += number;
        i = e;
    }
    return out;
}

// Where the definition of the function `name` starts (its line) and ends (after its "}").
std::pair<std::size_t, std::size_t> definition(const std::string& s, const std::string& name) {
    for (std::size_t p = s.find(" " + name + "("); p != std::string::npos; p = s.find(" " + name + "(", p + 1)) {
        const std::size_t start = s.rfind('\n', p) + 1;
        if (!std::isalpha(static_cast<unsigned char>(s[start]))) continue;  // not at the start of a line
        const std::size_t open = s.find('{', p), semicolon = s.find(';', p);
        if (open == std::string::npos || semicolon < open) continue;  // a declaration
        int depth = 0;
        for (std::size_t i = open; i < s.size(); ++i) {
            depth += s[i] == '{' ? 1 : s[i] == '}' ? -1 : 0;
            if (depth == 0) return {start, i + 1};
        }
    }
    return {std::string::npos, std::string::npos};
}

// The exercise functions in the reverse of their order in the file.
std::string reorder(const std::string& s, const std::vector<std::string>& exercises) {
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    for (const auto& e : exercises)
        if (const auto d = definition(s, e); d.first != std::string::npos) spans.push_back(d);
    std::sort(spans.begin(), spans.end());
    if (spans.empty()) return s;
    std::string out = s.substr(0, spans.front().first);
    for (auto it = spans.rbegin(); it != spans.rend(); ++it)
        out += s.substr(it->first, it->second - it->first) + "\n\n";
    return out + s.substr(spans.back().second);
}

// The stub with the reference's definitions of the first `count` exercises (and its includes).
std::string half_copy(const std::string& reference, const std::string& stub, const std::vector<std::string>& exercises,
                      std::size_t count) {
    std::string out = stub;
    for (std::size_t k = 0; k < count && k < exercises.size(); ++k) {
        const auto from = definition(reference, exercises[k]), to = definition(out, exercises[k]);
        if (from.first == std::string::npos || to.first == std::string::npos) continue;
        out.replace(to.first, to.second - to.first, reference.substr(from.first, from.second - from.first));
    }
    std::string includes;
    for (const auto& line : split(reference, '\n'))
        if (starts_with(line, "#include") && out.find(line) == std::string::npos) includes += line + "\n";
    return includes + out;
}

// ---- the class --------------------------------------------------------------------------------

struct Member {
    std::string name, expect;  // expect: "reference", another member's name, or "none"
    std::string text;          // rotation.cpp ("" for none)
    bool flat = false;         // rotation.cpp directly in the folder, not in exercises/
    double score = -1;         // the rotation score it must get (-1: not checked)
    std::string extra;         // another file it holds: "name:content"
};

std::vector<Member> planted(const std::string& reference, const std::string& stub,
                            const std::vector<std::string>& exercises, double full) {
    const std::set<std::string> keep(exercises.begin(), exercises.end());
    const std::string renamed = rename(reference, new_names(reference, keep, 1));
    const std::string disguised = respell(reformat(strip_comments(renamed)));
    const std::string again = rename(disguised, new_names(disguised, keep, 3));
    const std::size_t half = exercises.size() / 2;
    return {
        {"planted_exact", "reference", reference, false, full, ""},
        {"planted_flat", "reference", reference, true, full, ""},
        {"planted_renamed", "reference", renamed, false, full, ""},
        {"planted_disguised", "reference", disguised, false, full, ""},
        {"planted_reordered", "reference", reorder(renamed, exercises), false, full, ""},
        {"planted_copy_of_copy", "reference", again, true, full, ""},
        {"planted_half", "reference", half_copy(reference, stub, exercises, half), false, static_cast<double>(half),
         ""},
    };
}

std::vector<Member> others(const Setup& setup, const std::string& stub, const std::vector<std::string>& exercises,
                           double full) {
    const std::string dir = setup.root + "/tests/grading/tests/similarity/";
    const std::set<std::string> keep(exercises.begin(), exercises.end());
    const std::string classmate = read_file(dir + "classmate.cpp");
    const std::string broken = replace_all(stub, "{ todo(\"hat\"); }", "{ todo(\"hat\") }");  // no semicolon
    const std::string wrong = replace_all(stub, "{ todo(\"hat\"); }", "{ return Mat3::Zero(); }");
    // Three ways to crash, so that the three are not copies of one another.
    const std::vector<std::string> crash = {
        replace_all(stub, "{ todo(\"hat\"); }", "{ volatile int* p = nullptr; *p = 1; return Mat3::Zero(); }"),
        replace_all(stub, "{ todo(\"hat\"); }", "{ std::abort(); }"),
        replace_all(stub, "{ todo(\"hat\"); }", "{ return hat(2 * w); }")};
    std::vector<Member> m = {
        {"pair_original", "pair_copy", classmate, false, -1, ""},
        {"pair_copy", "pair_original",
         respell(reformat(strip_comments(rename(classmate, new_names(classmate, keep, 5))))), true, -1, ""},
        {"honest_levi_civita", "none", read_file(dir + "honest_levi_civita.cpp"), false, full, ""},
        {"honest_eigen_geometry", "none", read_file(dir + "honest_eigen_geometry.cpp"), true, full, ""},
        {"honest_rodrigues", "none", read_file(dir + "honest_rodrigues.cpp"), false, full, ""},
    };
    for (int k = 1; k <= 6; ++k)
        m.push_back({"stubs_" + std::to_string(k), "none", stub, k % 2 == 0, 0, k == 3 ? "README.md:my notes\n" : ""});
    m.push_back({"missing_empty", "none", "", false, 0, ""});
    m.push_back({"missing_misnamed", "none", "", false, 0, "Rotation.cpp:" + stub});
    m.push_back({"missing_readme_only", "none", "", true, 0, "README.md:I could not finish.\n"});
    for (int k = 1; k <= 3; ++k) {
        m.push_back({"broken_build_" + std::to_string(k), "none", broken, k == 2, 0, ""});
        m.push_back({"wrong_hat_" + std::to_string(k), "none", wrong, k == 3, 0, ""});
        m.push_back({"crash_hat_" + std::to_string(k), "none", crash[static_cast<std::size_t>(k - 1)], k == 1, 0, ""});
    }
    return m;
}

struct Args {
    std::string setup, out, expect, class_dir, grades, file;
    double score = -1, max_score = -1;
    int size = 30;  // make: the class of 30, or 10 of it; check: at least this many submissions
};

// The options of every command (make, check and schema each take them all).
void command_options(CLI::App& app, Args& a) {
    for (const auto& [name, value] : {std::pair{"--setup", &a.setup},
                                      {"--out", &a.out},
                                      {"--expect", &a.expect},
                                      {"--class", &a.class_dir},
                                      {"--grades", &a.grades}})
        app.add_option(name, *value);
    app.add_option("--score", a.score);
    app.add_option("--max-score", a.max_score);
    app.add_option("--size", a.size);
    app.add_option("file", a.file);  // schema: the results.json to check
}

const Topic* find_topic(const Setup& setup) {
    for (const auto& t : setup.topics)
        if (t.name == kTopic) return &t;
    return nullptr;
}

int make(const Args& a) {
    Setup setup;
    if (const auto problem = load_setup(a.setup, setup); !problem.empty())
        return std::fprintf(stderr, "grading_class: %s\n", problem.c_str()), 2;
    const Topic* topic = find_topic(setup);
    if (!topic || a.out.empty() || a.expect.empty())
        return std::fprintf(stderr, "grading_class make: needs --out, --expect and the rotation topic\n"), 2;
    std::vector<std::string> exercises;
    double full = 0;
    for (const auto& e : topic->exercises) exercises.push_back(e.name), full += e.points;
    const std::string reference = read_file(setup.root + "/solutions/" + kTopic + ".cpp");
    const std::string stub = read_file(pristine_stub(setup, kTopic));
    std::vector<Member> members = planted(reference, stub, exercises, full);
    for (auto& m : others(setup, stub, exercises, full)) members.push_back(m);
    if (a.size == 10) {  // a smaller class, one of each kind that matters to the report
        static const std::set<std::string> ten = {
            "planted_exact",      "planted_disguised",     "planted_half",     "pair_original", "pair_copy",
            "honest_levi_civita", "honest_eigen_geometry", "honest_rodrigues", "stubs_2",       "broken_build_1"};
        members.erase(
            std::remove_if(members.begin(), members.end(), [](const Member& m) { return !ten.count(m.name); }),
            members.end());
    } else if (a.size != 30) {
        return std::fprintf(stderr, "grading_class make: --size is 30 (the class) or 10 (a part of it)\n"), 2;
    }
    remove_tree(a.out);
    std::string expected = "# student\texpect\tscore (written by grading_class make)\n";
    for (const auto& m : members) {
        const std::string folder = a.out + "/" + m.name + (m.flat ? "" : "/exercises");
        make_dirs(folder);
        if (!m.text.empty()) write_file(folder + "/" + kTopic + ".cpp", m.text);
        if (!m.extra.empty())
            write_file(folder + "/" + m.extra.substr(0, m.extra.find(':')), m.extra.substr(m.extra.find(':') + 1));
        expected += m.name + "\t" + m.expect + "\t" + format_number(m.score) + "\n";
    }
    write_file(a.expect, expected);
    std::printf("grading_class: %zu submissions for %s in %s\n", members.size(), kTopic.c_str(), a.out.c_str());
    return 0;
}

// ---- Gradescope's results.json ------------------------------------------------------------------

bool one_of(const nlohmann::json& v, const std::set<std::string>& allowed) {
    return v.is_string() && allowed.count(v.get<std::string>()) > 0;
}

// The problems of one test entry, in Gradescope's autograder format.
void test_problems(const nlohmann::json& t, std::size_t k, std::vector<std::string>& problems, double& sum) {
    static const std::set<std::string> keys = {"score",       "max_score",  "status",    "name",
                                               "name_format", "number",     "output",    "output_format",
                                               "tags",        "visibility", "extra_data"};
    static const std::set<std::string> visibility = {"hidden", "after_due_date", "after_published", "visible"};
    const std::string at = "tests[" + std::to_string(k) + "]";
    if (!t.is_object()) return problems.push_back(at + " is not an object");
    for (const auto& [key, value] : t.items())
        if (!keys.count(key)) problems.push_back(at + " has a key Gradescope does not know: " + key);
    if (!t.contains("name") || !t["name"].is_string() || t["name"].get<std::string>().empty())
        problems.push_back(at + ": no name");
    if (!t.contains("output") || !t["output"].is_string()) problems.push_back(at + ": no output");
    if (!t.contains("visibility") || !one_of(t["visibility"], visibility)) problems.push_back(at + ": bad visibility");
    if (!t.contains("status") || !one_of(t["status"], {"passed", "failed"})) problems.push_back(at + ": bad status");
    if (t.contains("tags") && !t["tags"].is_array()) problems.push_back(at + ": tags is not a list");
    if (!t.contains("score") || !t["score"].is_number() || !t.contains("max_score") || !t["max_score"].is_number())
        return problems.push_back(at + ": score and max_score must be numbers");
    const double score = t["score"].get<double>(), max_score = t["max_score"].get<double>();
    const bool passed = t.value("status", "") == "passed";
    if (!(max_score > 0) || !(score >= 0) || score > max_score)
        problems.push_back(at + ": score out of [0, max_score]");
    if (passed != (score == max_score) || (!passed && score != 0))
        problems.push_back(at + ": status " + t.value("status", "") + " with score " + format_number(score));
    sum += score;
}

std::vector<std::string> schema_problems(const std::string& path, double want_score, double want_max) {
    static const std::set<std::string> keys = {
        "score",      "execution_time",    "output",     "output_format", "test_output_format", "test_name_format",
        "visibility", "stdout_visibility", "extra_data", "tests",         "leaderboard"};
    static const std::set<std::string> visibility = {"hidden", "after_due_date", "after_published", "visible"};
    bool ok = false;
    const nlohmann::json j = nlohmann::json::parse(read_file(path, &ok), nullptr, false);
    if (!ok) return {path + ": missing"};
    if (!j.is_object()) return {path + ": not a JSON object"};
    std::vector<std::string> problems;
    for (const auto& [key, value] : j.items())
        if (!keys.count(key)) problems.push_back("a key Gradescope does not know: " + key);
    if (!j.contains("score") || !j["score"].is_number()) problems.push_back("no score");
    if (!j.contains("output") || !j["output"].is_string()) problems.push_back("no output");
    for (const char* v : {"visibility", "stdout_visibility"})
        if (j.contains(v) && !one_of(j[v], visibility)) problems.push_back(std::string("bad ") + v);
    if (!j.contains("tests") || !j["tests"].is_array()) return problems.push_back("no tests list"), problems;
    double sum = 0, max_sum = 0;
    for (std::size_t k = 0; k < j["tests"].size(); ++k) {
        test_problems(j["tests"][k], k, problems, sum);
        max_sum += j["tests"][k].value("max_score", 0.0);
    }
    const double score = j.value("score", -1.0);
    if (std::abs(sum - score) > 1e-9)
        problems.push_back("the tests' scores add up to " + format_number(sum) + ", not to the score " +
                           format_number(score));
    if (want_score >= 0 && std::abs(score - want_score) > 1e-9)
        problems.push_back("score " + format_number(score) + ", expected " + format_number(want_score));
    if (want_max >= 0 && std::abs(max_sum - want_max) > 1e-9)
        problems.push_back("max_score adds up to " + format_number(max_sum) + ", expected " + format_number(want_max));
    return problems;
}

int schema(const Args& a) {
    const auto problems = schema_problems(a.file, a.score, a.max_score);
    for (const auto& p : problems) std::printf("%s: %s\n", a.file.c_str(), p.c_str());
    if (problems.empty())
        std::printf("%s: a valid Gradescope results.json%s\n", a.file.c_str(),
                    a.score >= 0 ? (", score " + format_number(a.score)).c_str() : "");
    return problems.empty() ? 0 : 1;
}

// ---- checking a graded class ------------------------------------------------------------------------

struct Expected {
    std::string name, expect;
    double score = -1;
};

std::vector<Expected> read_expected(const std::string& path) {
    std::vector<Expected> out;
    for (const auto& line : split(read_file(path), '\n')) {
        const auto f = split(line, '\t');
        if (line.empty() || line[0] == '#' || f.size() < 3) continue;
        out.push_back({f[0], f[1], std::stod(f[2])});
    }
    return out;
}

std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
            fields.back() += '"', ++i;
        else if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            fields.emplace_back();
        else
            fields.back() += c;
    }
    return fields;
}

// What similarity.csv lists: per submission, the exercises listed with the reference, and the
// number of exercises per pair of submissions.
struct Listing {
    std::map<std::string, std::set<std::string>> reference;
    std::map<std::pair<std::string, std::string>, int> pairs;
    std::set<std::string> mentioned;
};

Listing read_listing(const std::string& path, std::vector<std::string>& problems) {
    Listing l;
    bool ok = false;
    const auto lines = split(read_file(path, &ok), '\n');
    if (!ok || lines.empty() || !starts_with(lines[0], "topic,exercise,submission,matches,score"))
        return problems.push_back(path + " is missing or has no header"), l;
    for (std::size_t k = 1; k < lines.size(); ++k) {
        if (lines[k].empty()) continue;
        const auto f = csv_fields(lines[k]);
        if (f.size() != 12) {
            problems.push_back(path + ":" + std::to_string(k + 1) + ": " + std::to_string(f.size()) +
                               " fields, not 12");
            continue;
        }
        l.mentioned.insert(f[2]);
        if (starts_with(f[3], "solutions/")) {
            l.reference[f[2]].insert(f[1]);
        } else {
            l.mentioned.insert(f[3]);
            ++l.pairs[{std::min(f[2], f[3]), std::max(f[2], f[3])}];
        }
    }
    return l;
}

void check_similarity(const std::vector<Expected>& members, const Listing& l, const std::vector<std::string>& exercises,
                      std::vector<std::string>& problems) {
    const std::set<std::string> exact =
        l.reference.count("planted_exact") ? l.reference.at("planted_exact") : std::set<std::string>{};
    const std::set<std::string> first_half(exercises.begin(),
                                           exercises.begin() + static_cast<long>(exercises.size() / 2));
    if (exact.empty()) problems.push_back("planted_exact, the reference itself, is listed on no exercise");
    for (const auto& m : members) {
        const auto it = l.reference.find(m.name);
        const std::set<std::string> listed = it == l.reference.end() ? std::set<std::string>{} : it->second;
        if (m.expect == "none" && l.mentioned.count(m.name)) problems.push_back(m.name + " is listed, and must not be");
        if (m.expect != "reference" && !listed.empty())
            problems.push_back(m.name + " is listed with the reference, and must not be");
        if (m.expect == "reference") {
            for (const auto& e : exact)
                if ((m.score >= 0 && m.name != "planted_half") || first_half.count(e))
                    if (!listed.count(e)) problems.push_back(m.name + " is not listed with the reference on " + e);
            if (m.name == "planted_half")
                for (const auto& e : listed)
                    if (!first_half.count(e))
                        problems.push_back("planted_half is listed on " + e + ", which it did not copy");
        } else if (m.expect != "none" && !l.pairs.count({std::min(m.name, m.expect), std::max(m.name, m.expect)})) {
            problems.push_back(m.name + " and " + m.expect + " are not listed together");
        }
    }
}

void check_lms(const std::vector<Expected>& members, const std::string& grades, std::vector<std::string>& problems) {
    const auto canvas = split(read_file(grades + "/canvas.csv"), '\n'),
               moodle = split(read_file(grades + "/moodle.csv"), '\n');
    if (canvas.size() != members.size() + 3 ||
        canvas[0] != "Student,ID,SIS User ID,SIS Login ID,Section,Grioli workbook" ||
        !starts_with(canvas[1], "Points Possible,,,,,"))
        problems.push_back("canvas.csv lacks Canvas's columns, its Points Possible row or a row per submission");
    if (moodle.size() != members.size() + 2 || moodle[0] != "Username,Grioli workbook")
        problems.push_back("moodle.csv lacks its columns or a row per submission");
    for (const auto& m : members) {
        SubmissionResult r;
        read_results_tsv(grades + "/results/" + m.name + ".tsv", r);
        const std::string score = format_number(r.score);
        if (std::find(canvas.begin(), canvas.end(), m.name + ",,," + m.name + ",," + score) == canvas.end())
            problems.push_back("canvas.csv has no row " + m.name + ",,," + m.name + ",," + score);
        if (std::find(moodle.begin(), moodle.end(), m.name + "," + score) == moodle.end())
            problems.push_back("moodle.csv has no row " + m.name + "," + score);
    }
}

void check_grades(const std::vector<Expected>& members, const std::string& grades, std::vector<std::string>& problems) {
    for (const auto& m : members) {
        for (const auto& p : schema_problems(grades + "/results/" + m.name + ".json", m.score, -1))
            problems.push_back("results/" + m.name + ".json: " + p);
    }
    const std::string csv = read_file(grades + "/class.csv");
    if (static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')) != members.size() + 1)
        problems.push_back("class.csv does not have one row per submission");
    if (read_file(grades + "/similarity.md").find("# Similarity") == std::string::npos)
        problems.push_back("no similarity.md");
    check_lms(members, grades, problems);
}

// Every score of the honest and planted submissions, listed or not: the margin of the report's rules.
void print_measure(const Setup& setup, const std::vector<Expected>& members, const std::string& class_dir) {
    std::vector<ClassFiles> files;
    Options options;
    for (const auto& m : members) files.push_back({m.name, collect_files(setup, options, class_dir + "/" + m.name)});
    const std::vector<SimilarityHit> all = find_similar(setup, files, true);
    std::printf(
        "\n| Submission | Expected | Listed with the reference | Highest exercise score against the reference (file) "
        "| Listed with | Highest exercise score against another submission |\n|---|---|---:|---|---|---|\n");
    for (const auto& m : members) {
        if (m.expect == "none" && !starts_with(m.name, "honest_")) continue;
        int listed_ref = 0;
        std::map<std::string, int> listed_with;
        const SimilarityHit *ref = nullptr, *other = nullptr;
        for (const auto& h : all) {
            if (h.student != m.name && h.other != m.name) continue;
            const std::string peer = h.student == m.name ? h.other : h.student;
            if (peer.empty()) {
                listed_ref += h.listed;
                if (!ref || h.score > ref->score) ref = &h;
            } else {
                if (h.listed) ++listed_with[peer];
                if (peer != m.expect && (!other || h.score > other->score)) other = &h;
            }
        }
        std::string with;
        for (const auto& [peer, n] : listed_with)
            with += (with.empty() ? "" : ", ") + peer + " (" + std::to_string(n) + ")";
        auto describe = [&](const SimilarityHit* h) {
            if (!h) return std::string("none shared");
            const std::string peer = h->other.empty() ? "" : " with " + (h->student == m.name ? h->other : h->student);
            return format_number(h->score) + " on " + h->exercise + peer + " (" + format_number(h->file_score) + ")";
        };
        std::printf("| %s | %s | %d | %s | %s | %s |\n", m.name.c_str(), m.expect.c_str(), listed_ref,
                    describe(ref).c_str(), with.c_str(), describe(other).c_str());
    }
}

int check(const Args& a) {
    Setup setup;
    if (const auto problem = load_setup(a.setup, setup); !problem.empty())
        return std::fprintf(stderr, "grading_class: %s\n", problem.c_str()), 2;
    const Topic* topic = find_topic(setup);
    if (!topic || a.class_dir.empty() || a.expect.empty() || a.grades.empty())
        return std::fprintf(stderr, "grading_class check: needs --class, --expect, --grades and the rotation topic\n"),
               2;
    std::vector<std::string> exercises;
    for (const auto& e : topic->exercises) exercises.push_back(e.name);
    const std::vector<Expected> members = read_expected(a.expect);
    std::vector<std::string> problems;
    if (members.size() < static_cast<std::size_t>(a.size))
        problems.push_back("the class has " + std::to_string(members.size()) + " submissions, fewer than " +
                           std::to_string(a.size));
    const Listing listing = read_listing(a.grades + "/similarity.csv", problems);
    check_similarity(members, listing, exercises, problems);
    if (is_directory(a.grades + "/results")) check_grades(members, a.grades, problems);
    print_measure(setup, members, a.class_dir);
    if (!problems.empty()) {
        std::printf("\ngrading_class check FAILED:\n");
        for (const auto& p : problems) std::printf("  %s\n", p.c_str());
        return 1;
    }
    std::printf(
        "\ngrading_class check: %zu submissions; the copies are listed, the honest solutions are not%s\n",
        members.size(),
        is_directory(a.grades + "/results") ? "; every result, class.csv, canvas.csv and moodle.csv as expected" : "");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Args a;
    CLI::App app{"grading_class: the class of 30 (make), its grades checked (check), a results.json checked (schema)"};
    app.set_help_flag();
    app.require_subcommand(1);
    const std::vector<std::pair<const char*, int (*)(const Args&)>> commands = {
        {"make", make}, {"check", check}, {"schema", schema}};
    std::vector<CLI::App*> subcommands;
    for (const auto& [name, run] : commands) {
        subcommands.push_back(app.add_subcommand(name));
        command_options(*subcommands.back(), a);
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        std::fprintf(
            stderr,
            "grading_class: %s\nusage: grading_class make|check|schema ... (see tests/grading/tests/class.cpp)\n",
            e.what());
        return 2;
    }
    for (std::size_t k = 0; k < commands.size(); ++k)
        if (subcommands[k]->parsed()) return commands[k].second(a);
    return 2;
}
