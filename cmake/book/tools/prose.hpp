// What the book's tools share (snippets.cpp checks the prose, book.cpp renders it):
// reading files, the code snippets of the sources, the value markers of the prose, the runs
// of the scenes that produce the values, and the JSON reports they are read from.
//
// A code snippet, in a source file (exercises/rigid/*.hpp, chapters/**/*.cpp|hpp, tests/*):
//     // snippet: NAME
//     ...code...
//     // end snippet
// and where the prose quotes it (README.md, chapters/**/*.md, exercises/hints.md):
//     <!-- snippet: NAME -->
//     ```cpp
//     ...code, filled in by `snippets --update`...
//     ```
//     <!-- end snippet -->
//
// A value, inline in the prose, read from the JSON report of one run of a scene:
//     <!-- value: SCENE.KEY[.KEY|[ROW]|[COLUMN=X]]... run=RUN [fmt=F] [scale=S] -->TEXT<!-- end value -->
// RUN names the run whose options the prose describes: `default` is the scene as
// `cmake/workbook run` runs it (its ARGS in the chapter's CMakeLists.txt); any other name is a
// run declared there with workbook_scene_run() (e.g. work_precision's `full_sweep`). The test
// suite's light runs (SMOKE_ARGS) are never quoted. KEY paths: `pure_rotation.error`,
// `pure_rotation.axis[2]`, `omega_finite_difference.by_stencil[order=8].best_error` (a
// kit::Report table: the row whose column `order` is 8, then its column `best_error`);
// `by_stencil[0].best_h` picks row 0. F is a printf format for one number (%.2g, %.3e, %.0f, %d)
// or sciN: N significant digits as 8.2×10⁻¹² (readable on GitHub and in the book alike). S
// multiplies first (1e9: s -> ns). Markers inside code (fenced blocks, `code spans`) are text.
// With tol=T the TEXT is a number typed by hand (a worked example done on paper, a value in a
// table): --update never rewrites it, and every check fails when it is further than T, relative,
// from the run's value, so a hand value can never drift from what the run computes.
//
// Every other number in the prose that looks measured (one in scientific notation whose mantissa
// is not 1, as 3.6e-13, 3.6×10⁻¹³ or 3.6\times10^{-13}; a decimal with four or more significant
// digits, as 0.2122) says what it is, with a tag in front of it:
//     <!--exact-->0.7071    exact, or worked by hand from exact inputs
//     <!--input-->2.5e-3    an input, an option or a tolerance the reader can set
//     <!--const-->2.2e-16   a constant (of the machine, of nature, of a library)
//     <!--P-->0.2122        quoted from [P]
//     <!--once-->129.5      measured once by hand, as the sentence says where (the manuals only,
//                           never a chapter)
// A tag covers the next number; <!--P:3--> the next three, in the same paragraph (a tag with
// numbers left at a blank line is stale). Numbers in code, in value markers and in link targets
// are not prose.
//
// Where a run's report is: <tree>/<chapter>/<scene>.json for the default run and
// <tree>/<chapter>/<run>/<scene>.json for a named one, next to the figures that run drew. The
// committed tree is <root>/figures (refreshed only by the target update-figures); a build's
// own tree is <build>/figures. Every report carries "run": {"name": ..., "args": [...]}, written
// by cmake/run_scenes.cmake, and is only read for a marker whose run it is. TEXT is the value
// of the committed report (snippets --update writes it); the rendered book shows its own run's.
// A value the scene marks as not measured (null, -1, "not measured") is an error, never shown.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace prose {

namespace fs = std::filesystem;

inline std::vector<std::string> read_lines(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

inline std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A JSON file (nlohmann-json), its objects in the order written; a syntax error names the file.
inline nlohmann::ordered_json read_json(const fs::path& p) {
    try {
        return nlohmann::ordered_json::parse(read_text(p));
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(p.string() + ": " + e.what());
    }
}

inline void write_text(const fs::path& p, const std::string& text) {
    if (p.has_parent_path()) fs::create_directories(p.parent_path());
    std::ofstream out(p, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + p.string());
}

inline std::string rel(const fs::path& p, const fs::path& root) { return fs::relative(p, root).generic_string(); }

// ------------------------------------------------------------------------------ code

// For each character of a line: is it inside a `code span`? For the lines the document tree has
// only as text (raw HTML blocks, see book/markdown.hpp) and the markers' own grammar below.
inline std::vector<bool> code_span_mask(const std::string& line) {
    std::vector<bool> mask(line.size(), false);
    std::size_t i = 0;
    while (i < line.size()) {
        if (line[i] != '`') {
            ++i;
            continue;
        }
        std::size_t n = 0;
        while (i + n < line.size() && line[i + n] == '`') ++n;
        const std::string ticks(n, '`');
        std::size_t close = line.find(ticks, i + n);
        while (close != std::string::npos && close + n < line.size() && line[close + n] == '`')
            close = line.find(ticks, close + n + 1);
        if (close == std::string::npos) {
            i += n;
            continue;
        }
        for (std::size_t k = i; k < close + n; ++k) mask[k] = true;
        i = close + n;
    }
    return mask;
}

// ------------------------------------------------------------------------------ snippets

struct Snippet {
    std::string name, file, text;  // file relative to the root; text dedented
    int line = 0;                  // of the `// snippet:` line
    bool used = false;
};

// Remove the indentation common to all non-blank lines.
inline std::string dedent(const std::vector<std::string>& lines) {
    std::size_t common = std::string::npos;
    for (const auto& l : lines)
        if (l.find_first_not_of(" \t") != std::string::npos) common = std::min(common, l.find_first_not_of(" \t"));
    std::string out;
    for (const auto& l : lines) out += (l.size() > common ? l.substr(common) : std::string()) + "\n";
    return out;
}

// The files a workbook's prose and code live in. solutions/ is never scanned: the prose
// must not give away the exercises.
struct Tree {
    std::vector<fs::path> sources;  // *.hpp, *.cpp
    std::vector<fs::path> prose;    // *.md
};

inline Tree scan_tree(const fs::path& root) {
    Tree t;
    for (const char* dir : {"exercises", "chapters", "tests", "cmake"}) {
        if (!fs::exists(root / dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
            const auto ext = e.path().extension();
            if (ext == ".hpp" || ext == ".cpp") t.sources.push_back(e.path());
            if (ext == ".md") t.prose.push_back(e.path());
        }
    }
    t.prose.push_back(root / "README.md");
    std::sort(t.sources.begin(), t.sources.end());
    std::sort(t.prose.begin(), t.prose.end());
    return t;
}

// Collects the named regions of the sources; problems go to `problems`. The tools' own
// sources (cmake/book/tools/) talk about the markers and are skipped.
inline std::map<std::string, Snippet> collect_snippets(const fs::path& root, const std::vector<fs::path>& sources,
                                                       std::vector<std::string>& problems) {
    const std::regex begin_marker(R"(^\s*// snippet: ([A-Za-z0-9_]+)\s*$)");
    const std::regex end_marker(R"(^\s*// end snippet\s*$)");
    std::map<std::string, Snippet> snippets;
    for (const auto& p : sources) {
        if (rel(p, root).rfind("cmake/book/tools/", 0) == 0) continue;
        const auto lines = read_lines(p);
        std::string open;
        int open_line = 0;
        std::vector<std::string> body;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            std::smatch m;
            const std::string where = rel(p, root) + ":" + std::to_string(i + 1);
            if (std::regex_match(lines[i], m, begin_marker)) {
                if (!open.empty())
                    problems.push_back(where + ": snippet '" + m[1].str() + "' opens inside '" + open + "'");
                open = m[1];
                open_line = static_cast<int>(i + 1);
                body.clear();
            } else if (std::regex_match(lines[i], end_marker)) {
                if (open.empty()) {
                    problems.push_back(where + ": 'end snippet' without a snippet");
                    continue;
                }
                if (snippets.count(open))
                    problems.push_back(rel(p, root) + ":" + std::to_string(open_line) + ": snippet '" + open +
                                       "' is also defined in " + snippets[open].file);
                snippets[open] = Snippet{open, rel(p, root), dedent(body), open_line, false};
                open.clear();
            } else if (!open.empty()) {
                body.push_back(lines[i]);
            }
        }
        if (!open.empty())
            problems.push_back(rel(p, root) + ":" + std::to_string(open_line) + ": snippet '" + open +
                               "' is never closed");
    }
    return snippets;
}

// ------------------------------------------------------------------------------ JSON

// The scenes' reports (kit::Report::write_json), read with nlohmann-json, objects in order.
using Json = nlohmann::ordered_json;

// ------------------------------------------------------------------------------ values

struct ValueMarker {
    std::size_t begin = 0, end = 0;  // the whole marker in the line: [begin, end)
    std::size_t text_begin = 0, text_end = 0;
    std::string path, run, fmt = "%.3g", text;
    double scale = 1;
    double tol = -1;    // tol=T: TEXT is typed by hand and checked, |TEXT - value| <= T |value|
    std::string error;  // a malformed marker says why

    std::string scene() const { return path.substr(0, path.find_first_of(".[")); }
};

// The value markers of one line (outside code spans).
inline std::vector<ValueMarker> find_value_markers(const std::string& line) {
    static const std::regex open_re(R"(<!-- value: ([^ ]+)((?: [a-z]+=[^ ]+)*) -->)");
    static const std::string close = "<!-- end value -->";
    std::vector<ValueMarker> out;
    const auto mask = code_span_mask(line);
    auto it = std::sregex_iterator(line.begin(), line.end(), open_re);
    for (; it != std::sregex_iterator(); ++it) {
        const auto& m = *it;
        const auto pos = static_cast<std::size_t>(m.position(0));
        if (mask[pos]) continue;
        ValueMarker v;
        v.begin = pos;
        v.path = m[1];
        v.text_begin = pos + static_cast<std::size_t>(m.length(0));
        const auto close_pos = line.find(close, v.text_begin);
        if (close_pos == std::string::npos) {
            v.error = "'<!-- value: " + v.path + " ... -->' has no '" + close + "' on the same line";
            v.end = v.text_begin;
            v.text_end = v.text_begin;
            out.push_back(v);
            continue;
        }
        v.text_end = close_pos;
        v.end = close_pos + close.size();
        v.text = line.substr(v.text_begin, v.text_end - v.text_begin);
        std::istringstream opts(m[2].str());
        for (std::string opt; opts >> opt;) {
            const auto eq = opt.find('=');
            const std::string key = opt.substr(0, eq), val = opt.substr(eq + 1);
            if (key == "fmt") {
                static const std::regex ok(R"(%[-+ 0#]*[0-9]*(\.[0-9]+)?[eEfFgGd]|sci[1-9])");
                if (!std::regex_match(val, ok))
                    v.error =
                        "fmt=" + val + ": use a printf format for one number (%.2g, %.3e, %.0f, %d) or sci1..sci9";
                v.fmt = val;
            } else if (key == "scale") {
                char* end = nullptr;
                v.scale = std::strtod(val.c_str(), &end);
                if (end == val.c_str() || *end != '\0' || !std::isfinite(v.scale))
                    v.error = "scale=" + val + ": not a number";
            } else if (key == "run") {
                static const std::regex ok(R"([a-z][a-z0-9_]*)");
                if (!std::regex_match(val, ok)) v.error = "run=" + val + ": a run's name is lower case, digits and _";
                v.run = val;
            } else if (key == "tol") {
                char* end = nullptr;
                v.tol = std::strtod(val.c_str(), &end);
                if (end == val.c_str() || *end != '\0' || !(v.tol >= 0 && v.tol < 1))
                    v.error = "tol=" + val + ": a relative tolerance, from 0 to below 1";
            } else {
                v.error = "unknown option '" + key + "' (known: run, fmt, scale, tol)";
            }
        }
        if (v.error.empty() && v.run.empty())
            v.error =
                "states no run: add run=default (the scene as cmake/workbook run runs it) or the name of a run "
                "declared with workbook_scene_run()";
        out.push_back(v);
    }
    return out;
}

// 8.2×10⁻¹² with `digits` significant digits.
inline std::string sci(double x, int digits) {
    if (x == 0) return "0";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*e", digits - 1, x);
    std::string s = buf;
    const auto e = s.find('e');
    const std::string mantissa = s.substr(0, e);
    const int exponent = std::stoi(s.substr(e + 1));
    if (exponent == 0) return mantissa;
    static const char* sup[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string power = exponent < 0 ? "⁻" : "";
    for (char c : std::to_string(std::abs(exponent))) power += sup[c - '0'];
    if (mantissa == "1" || mantissa == "-1") return (mantissa == "-1" ? "-" : "") + std::string("10") + power;
    return mantissa + "×10" + power;
}

inline std::string format_number(double x, const std::string& fmt) {
    if (fmt.rfind("sci", 0) == 0) return sci(x, fmt[3] - '0');
    char buf[128];
    if (fmt.back() == 'd')
        std::snprintf(buf, sizeof buf, (fmt.substr(0, fmt.size() - 1) + "lld").c_str(),
                      static_cast<long long>(std::llround(x)));
    else
        std::snprintf(buf, sizeof buf, fmt.c_str(), x);
    return buf;
}

// ------------------------------------------------------------------------------ runs

// One run of a scene, as CMake declares it (<build>/runs.txt, one per line:
// scene|chapter|run|arg|arg...).
struct RunDecl {
    std::string scene, chapter, run;
    std::vector<std::string> args;
};

class Runs {
public:
    Runs() = default;
    explicit Runs(const fs::path& file) {
        if (!fs::exists(file))
            throw std::runtime_error(file.string() + ": no list of runs (configure the build first)");
        for (const auto& line : read_lines(file)) {
            if (line.empty()) continue;
            std::vector<std::string> parts;
            std::string part;
            std::istringstream in(line);
            while (std::getline(in, part, '|')) parts.push_back(part);
            if (parts.size() < 3) throw std::runtime_error(file.string() + ": bad line '" + line + "'");
            RunDecl d{parts[0], parts[1], parts[2], {parts.begin() + 3, parts.end()}};
            decls_[{d.scene, d.run}] = d;
        }
    }
    const RunDecl* find(const std::string& scene, const std::string& run) const {
        const auto it = decls_.find({scene, run});
        return it == decls_.end() ? nullptr : &it->second;
    }
    bool has_scene(const std::string& scene) const {
        for (const auto& [k, d] : decls_)
            if (k.first == scene) return true;
        return false;
    }
    std::string names(const std::string& scene) const {
        std::string out;
        for (const auto& [k, d] : decls_)
            if (k.first == scene) out += (out.empty() ? "" : ", ") + k.second;
        return out.empty() ? "none" : out;
    }

private:
    std::map<std::pair<std::string, std::string>, RunDecl> decls_;
};

// Where a run keeps its figures and its report, inside a tree of figures.
inline fs::path run_folder(const fs::path& tree, const RunDecl& d) {
    return d.run == "default" ? tree / d.chapter : tree / d.chapter / d.run;
}
inline fs::path report_path(const fs::path& tree, const RunDecl& d) {
    return run_folder(tree, d) / (d.scene + ".json");
}

inline std::string join_args(const std::vector<std::string>& args) {
    std::string out;
    for (const auto& a : args) out += (out.empty() ? "" : " ") + a;
    return out.empty() ? "(no options)" : out;
}

// ------------------------------------------------------------------------------ reports

// The reports of one tree of figures, read once each.
class Reports {
public:
    explicit Reports(fs::path tree) : tree_(std::move(tree)) {}
    const fs::path& tree() const { return tree_; }

    // The report of the run `d` in this tree, or nullptr when there is none. Throws when the
    // file is there but is not that run's report (made with other options, or unreadable).
    const Json* report(const RunDecl& d) {
        const fs::path p = report_path(tree_, d);
        auto it = cache_.find(p.string());
        if (it != cache_.end()) return it->second.get();
        std::unique_ptr<Json> j;
        if (fs::exists(p)) {
            j = std::make_unique<Json>(read_json(p));
            const Json* run = j->is_object() && j->contains("run") ? &(*j)["run"] : nullptr;
            const bool ok = run && run->is_object() && run->contains("name") && (*run)["name"].is_string() &&
                            run->contains("args") && (*run)["args"].is_array();
            if (!ok)
                throw std::runtime_error(p.string() +
                                         ": no \"run\" record (name, args): not written by cmake/run_scenes.cmake");
            const auto name = (*run)["name"].get<std::string>();
            std::vector<std::string> a;
            for (const auto& x : (*run)["args"]) a.push_back(x.is_string() ? x.get<std::string>() : x.dump());
            if (name != d.run || a != d.args)
                throw std::runtime_error(p.string() + " comes from the run '" + name + "' with " + join_args(a) +
                                         ", but the run '" + d.run + "' of " + d.scene + " is declared with " +
                                         join_args(d.args) + " (run it again)");
        }
        return (cache_[p.string()] = std::move(j)).get();
    }

private:
    fs::path tree_;
    std::map<std::string, std::unique_ptr<Json>> cache_;
};

// A walk down a report along a key path: `node` the place reached, `row_columns` the columns of
// the table when `node` is one of its rows, `at` the path so far (for the messages).
struct ReportWalk {
    const Json* node;
    const Json* row_columns = nullptr;
    std::string at;

    static const Json* field(const Json* n, const char* key) {
        return n->is_object() && n->contains(key) ? &(*n)[key] : nullptr;
    }
    static bool is_table(const Json* n) { return field(n, "columns") && field(n, "rows"); }
    static std::size_t column(const Json* cols, const std::string& name) {
        std::size_t c = 0;
        while (c < cols->size() && !((*cols)[c].is_string() && (*cols)[c].get<std::string>() == name)) ++c;
        return c;
    }

    // .key: a field, or the cell of a table row.
    void key(const std::string& key) {
        if (row_columns) {
            const std::size_t c = column(row_columns, key);
            if (c >= row_columns->size() || !node->is_array() || c >= node->size())
                throw std::runtime_error(at + " has no column '" + key + "'");
            node = &(*node)[c];
            row_columns = nullptr;
        } else if (node->is_object()) {
            const Json* next = field(node, key.c_str());
            if (!next) {
                std::string known;
                for (const auto& f : node->items()) known += (known.empty() ? "" : ", ") + f.key();
                throw std::runtime_error(at + " has no key '" + key + "' (it has: " + known + ")");
            }
            node = next;
        } else {
            throw std::runtime_error(at + " is not an object, so it has no key '" + key + "'");
        }
    }

    // [i]: an item of a list, or row i of a table.
    void item(const std::string& index) {
        const std::size_t i = std::stoul(index);
        const Json* cols = is_table(node) ? field(node, "columns") : nullptr;
        const Json* list = cols ? field(node, "rows") : node;
        if (row_columns || !list->is_array() || i >= list->size())
            throw std::runtime_error(at + " has no item [" + index + "]");
        node = &(*list)[i];
        row_columns = cols;
    }

    // [column=x]: the row of a table whose column equals x.
    void row(const std::string& name, const std::string& wanted) {
        if (row_columns || !is_table(node))
            throw std::runtime_error(at + " is not a table (columns and rows), so it has no row [" + name + "=" +
                                     wanted + "]");
        const Json* cols = field(node, "columns");
        const std::size_t c = column(cols, name);
        if (c == cols->size()) throw std::runtime_error(at + " has no column '" + name + "'");
        char* end = nullptr;
        const double x = std::strtod(wanted.c_str(), &end);
        const Json* found = nullptr;
        for (const auto& r : *field(node, "rows"))
            if (r.is_array() && c < r.size() && r[c].is_number() && r[c].get<double>() == x) found = &r;
        if (!found || *end != '\0') throw std::runtime_error(at + " has no row with " + name + " = " + wanted);
        node = found;
        row_columns = cols;
    }
};

// Follows `path` (the part after the scene name) into a report. Throws saying what is missing.
inline const Json& lookup(const Json& report, const std::string& path) {
    static const std::regex step(R"(^\.([A-Za-z_][A-Za-z0-9_]*)|^\[([0-9]+)\]|^\[([A-Za-z_][A-Za-z0-9_]*)=([^\]]+)\])");
    ReportWalk walk{&report, nullptr, "the report"};
    std::string rest = path, done;
    while (!rest.empty()) {
        std::smatch m;
        if (!std::regex_search(rest, m, step)) throw std::runtime_error("cannot read the key path at '" + rest + "'");
        walk.at = done.empty() ? "the report" : "'" + done + "'";
        if (m[1].matched)
            walk.key(m[1]);
        else if (m[2].matched)
            walk.item(m[2]);
        else
            walk.row(m[3], m[4]);
        done += m[0].str();
        rest = m.suffix();
    }
    if (walk.row_columns) throw std::runtime_error("'" + done + "' is a whole table row: name a column, e.g. '.x'");
    return *walk.node;
}

// The text a marker shows for its value in `report`. Throws saying what is missing, or that
// the run did not measure it: null (not finite), the number -1 (the scenes' mark for "not
// measured" or "none") or a word that says so.
inline std::string resolve(const ValueMarker& v, const Json& report) {
    const auto dot = v.path.find_first_of(".[");
    if (dot == std::string::npos || v.path[dot] != '.')
        throw std::runtime_error("'" + v.path + "': name a scene and a key, e.g. pure_rotation.error");
    const Json& x = lookup(report, v.path.substr(dot));
    const std::string run = "the run '" + v.run + "'";
    if (x.is_null()) throw std::runtime_error("'" + v.path + "' is null in " + run + ": not finite, or not measured");
    if (x.is_number()) {
        const double number = x.get<double>();
        if (number == -1)
            throw std::runtime_error("'" + v.path + "' is -1 in " + run +
                                     ", the scenes' mark for a value not measured");
        return format_number(v.scale * number, v.fmt);
    }
    if (x.is_string() && v.scale == 1) {
        static const std::regex placeholder(R"(\s*(not measured|not run|none|n/a|—|-|)\s*)", std::regex::icase);
        const auto text = x.get<std::string>();
        if (std::regex_match(text, placeholder))
            throw std::runtime_error("'" + v.path + "' is \"" + text + "\" in " + run + ": not measured");
        return text;
    }
    throw std::runtime_error("'" + v.path + "' is not a number");
}

// ------------------------------------------------------------------------------ numbers

// A number of the prose that looks measured (see the top of this file): where it is on its line.
struct ProseNumber {
    std::size_t begin = 0, end = 0;
    std::string text;
};

// The significant digits of a decimal mantissa: 0.002120 has 4.
inline int significant_digits(const std::string& mantissa) {
    std::string d;
    for (char c : mantissa)
        if (c != '.') d += c;
    const auto first = d.find_first_not_of('0');
    return first == std::string::npos ? 0 : static_cast<int>(d.size() - first);
}

// The numbers of `line` that look measured, outside the characters `skip` marks (code spans,
// markers, comments, link targets). A number inside a word (rk4, x1.5) or a dotted version
// (3.20.1) is not one.
inline std::vector<ProseNumber> measured_numbers(const std::string& line, const std::vector<bool>& skip) {
    static const std::regex number(
        R"((\d+(?:\.\d+)?|\.\d+)((?:[eE][-+]?\d+)|(?:(?:\s|\\,|\\;|\\!)*(?:\\times|×|\\cdot|·)(?:\s|\\,|\\;|\\!)*)"
        R"(10(?:\^\{?(?:-|−)?\d+\}?|(?:⁻|⁺)?(?:⁰|¹|²|³|⁴|⁵|⁶|⁷|⁸|⁹)+)))?)");
    const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    std::vector<ProseNumber> out;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), number); it != std::sregex_iterator(); ++it) {
        const auto b = static_cast<std::size_t>(it->position(0)), e = b + static_cast<std::size_t>(it->length(0));
        if (skip[b]) continue;
        if (b > 0 && (word(line[b - 1]) || line[b - 1] == '.')) continue;
        if (e < line.size() && (word(line[e]) || (line[e] == '.' && e + 1 < line.size() &&
                                                  std::isdigit(static_cast<unsigned char>(line[e + 1])))))
            continue;
        const std::string mantissa = (*it)[1];
        const bool scientific = (*it)[2].matched;
        const bool measured = scientific ? mantissa != "1" && mantissa != "1.0"
                                         : mantissa.find('.') != std::string::npos && significant_digits(mantissa) >= 4;
        if (measured) out.push_back({b, e, it->str()});
    }
    return out;
}

// A tag that says what the next numbers are: <!--exact-->, <!--P:3-->, ...
struct NumberTag {
    std::size_t begin = 0, end = 0;
    std::string kind;
    int count = 1;
    std::string error;
};

inline const std::vector<std::string>& number_kinds() {
    static const std::vector<std::string> kinds{"exact", "input", "const", "P", "once"};
    return kinds;
}

// The tags of one line: every comment that is one word, with an optional :count.
inline std::vector<NumberTag> find_number_tags(const std::string& line) {
    static const std::regex tag(R"(<!--\s*([A-Za-z]+)(?::([0-9]+))?\s*-->)");
    const auto& kinds = number_kinds();
    std::vector<NumberTag> out;
    const auto mask = code_span_mask(line);
    for (auto it = std::sregex_iterator(line.begin(), line.end(), tag); it != std::sregex_iterator(); ++it) {
        NumberTag t;
        t.begin = static_cast<std::size_t>(it->position(0));
        if (mask[t.begin]) continue;
        t.end = t.begin + static_cast<std::size_t>(it->length(0));
        t.kind = (*it)[1];
        if ((*it)[2].matched) t.count = std::stoi((*it)[2]);
        if (std::find(kinds.begin(), kinds.end(), t.kind) == kinds.end())
            t.error = "'" + it->str() + "' is no kind of number (exact, input, const, P, once)";
        else if (t.count < 1)
            t.error = "'" + it->str() + "' covers no number";
        out.push_back(t);
    }
    return out;
}

// The number a hand value's text states: 0.212157, -3.6e-13, 3.6×10⁻¹³, −0.5.
inline std::optional<double> parse_number(std::string text) {
    static const std::vector<std::pair<std::string, std::string>> swaps{
        {"−", "-"}, {"×10", "e"}, {"⁻", "-"}, {"⁺", ""},  {"⁰", "0"}, {"¹", "1"}, {"²", "2"},
        {"³", "3"}, {"⁴", "4"},   {"⁵", "5"}, {"⁶", "6"}, {"⁷", "7"}, {"⁸", "8"}, {"⁹", "9"}};
    for (const auto& [from, to] : swaps)
        for (std::size_t at; (at = text.find(from)) != std::string::npos;) text.replace(at, from.size(), to);
    if (text.rfind("10", 0) == 0 && text.size() > 2 && text[2] == '-') text = "1e" + text.substr(2);
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(x)) return std::nullopt;
    return x;
}

// A hand value (tol=) against the run's `report`: empty when it is within its tolerance, else
// what differs. Throws as resolve() does.
inline std::string hand_value_problem(const ValueMarker& v, const Json& report) {
    ValueMarker exact = v;
    exact.fmt = "%.17g";
    const double run = std::strtod(resolve(exact, report).c_str(), nullptr);
    const auto typed = parse_number(v.text);
    if (!typed) return "the hand value '" + v.text + "' is not a number";
    const double gap = std::abs(*typed - run), allowed = v.tol * std::abs(run);
    if (gap <= allowed) return "";
    char buf[200];
    std::snprintf(buf, sizeof buf, "the hand value %s is %.2g from the run's %.10g (relative %.2g, tol=%g)",
                  v.text.c_str(), gap, run, run != 0 ? gap / std::abs(run) : gap, v.tol);
    return buf;
}

}  // namespace prose
