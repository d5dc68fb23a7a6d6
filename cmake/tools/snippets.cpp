// Keeps the prose of the book honest about the code and the numbers it quotes.
//
//   snippets --check        <root>        fail on a missing, stale or unused code snippet, or a
//                                         malformed value marker (see prose.hpp for both)
//   snippets --check-names  <root>        fail on prose that names code which does not exist:
//                                         `identifiers_with_underscores` and `ns::names` (not
//                                         std::, Eigen::, boost::, doctest::, gsl_), `test:`
//                                         prefixes, `paths/to/files.cpp`, and the scenes, options
//                                         and graders of the ```sh examples
//   snippets --check-numbers <root>       fail on a number of the prose that looks measured and is
//                                         neither a value marker nor tagged with what it is, on a
//                                         malformed or stale tag (see prose.hpp), and on a section
//                                         of the workbook named by number (section 5.6) that is
//                                         not a link to it
//   snippets --check-values <root> <runs.txt> [<smoke>]
//                                         fail on a value marker whose run is not declared, whose
//                                         committed report (<root>/figures/...) is missing, made
//                                         with other options, lacks the key or marks it as not
//                                         measured, or whose text differs from that report; with
//                                         <smoke> (the test suite's reports, <scene>.json), also
//                                         on a key the scenes as built no longer report
//   snippets --update       <root> [<runs.txt>]
//                                         rewrite the quoted code from the sources and, with
//                                         <runs.txt>, the quoted values from the committed reports
//   snippets --diff         <root> <runs.txt> <tree>
//                                         compare every value marker with its run's report in
//                                         <tree> (a build's figures): per chapter, how many agree
//                                         with the committed text, and each one that does not
//
// The committed prose carries the values of the committed reports, which the target
// update-figures copies, with the figures, from a `cmake/workbook run`; the rendered book shows
// the values of its own run. Run times change from run to run and round-off from machine to
// machine, so a fresh run may differ from the text: --diff lists where.
#include <algorithm>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "prose.hpp"

namespace fs = std::filesystem;
using prose::rel;

namespace {

// ------------------------------------------------------------------ code snippets and values

enum class Mode { check, check_values, update, diff };

// Checks (or refreshes) the quoted code and the value markers of every prose file.
//   runs:  the declared runs (check_values, update with values, diff)
//   smoke: the test suite's reports (check_values; may be null)
//   tree:  a build's figures (diff)
class ProseChecker {
public:
    ProseChecker(const fs::path& root, Mode mode, const prose::Runs* runs, const fs::path* smoke, const fs::path* tree)
        : root_(root),
          mode_(mode),
          runs_(runs),
          smoke_(smoke),
          tree_files_(prose::scan_tree(root)),
          snippets_(prose::collect_snippets(root, tree_files_.sources, problems_)),
          committed_(root / "figures") {
        if (tree) other_.emplace(*tree);
        for (const auto& p : tree_files_.sources)  // a scene is chapters/*/<scene>.cpp
            if (rel(p, root).rfind("chapters/", 0) == 0 && p.extension() == ".cpp") scenes_.insert(p.stem().string());
    }

    int run() {
        for (const auto& p : tree_files_.prose)
            if (fs::exists(p)) file(p);
        if (mode_ == Mode::check)
            for (const auto& [name, s] : snippets_)
                if (!s.used)
                    problems_.push_back(s.file + ":" + std::to_string(s.line) + ": snippet '" + name +
                                        "' is not quoted anywhere in the prose");
        if (mode_ == Mode::diff)
            print_diff();
        else
            print_summary();
        for (const auto& p : problems_) std::cout << "  " << p << "\n";
        return problems_.empty() ? 0 : 1;
    }

private:
    struct Tally {
        int values = 0, same = 0, differ = 0, missing = 0;
    };

    // One prose file: its value markers and its quotations, rewritten in place by --update.
    void file(const fs::path& p) {
        const auto lines = prose::read_lines(p);
        std::vector<std::string> out;
        bool changed = false, in_fence = false;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string where = rel(p, root_) + ":" + std::to_string(i + 1);
            if (prose::is_fence(lines[i])) in_fence = !in_fence;
            if (in_fence || prose::is_fence(lines[i])) {
                out.push_back(lines[i]);
                continue;
            }
            std::string line = lines[i];
            auto markers = prose::find_value_markers(line);
            for (auto v = markers.rbegin(); v != markers.rend(); ++v) changed |= value(*v, rel(p, root_), where, line);
            out.push_back(line);
            std::smatch m;
            if (std::regex_match(lines[i], m, prose::snippet_use_marker()))
                i = quote(m[1], lines, i, where, out, changed);
        }
        if (mode_ == Mode::update && changed) {
            std::string text;
            for (const auto& l : out) text += l + "\n";
            prose::write_text(p, text);
            std::cout << "updated " << rel(p, root_) << "\n";
        }
    }

    // One value marker: checked against its run's committed report (refreshed by --update), or
    // compared with another build's report (--diff). Returns whether `line` changed.
    bool value(const prose::ValueMarker& v, const std::string& file, const std::string& where, std::string& line) {
        ++n_values_;
        const std::string at = where + ": value '" + v.path + "'";
        if (!v.error.empty()) return problem(at + ": " + v.error);
        const std::string scene = v.scene();
        if (!scenes_.count(scene))
            return problem(at + ": there is no scene '" + scene + "' (chapters/*/" + scene + ".cpp)");
        if (!runs_) return false;
        const prose::RunDecl* d = runs_->find(scene, v.run);
        if (!d)
            return problem(at + ": the scene " + scene + " has no run '" + v.run +
                           "' (declared: " + runs_->names(scene) + ")");
        try {
            if (mode_ == Mode::diff) return diff(v, *d, file, at);
            if (mode_ == Mode::check_values) still_reported(v, scene, at);
            const prose::Json* r = committed_.report(*d);
            const std::string report = rel(prose::report_path(root_ / "figures", *d), root_);
            if (!r)
                return problem(at + ": no committed report " + report +
                               " (run cmake/workbook run, then the target update-figures)");
            if (v.tol >= 0) {  // typed by hand: checked, never rewritten
                const std::string off = prose::hand_value_problem(v, *r);
                return off.empty() ? false : problem(at + ": " + off + " in its committed report " + report);
            }
            const std::string text = prose::resolve(v, *r);
            if (text == v.text) return false;
            if (mode_ != Mode::update)
                return problem(at + ": the text says '" + v.text + "', its committed report " + report + " says '" +
                               text + "' (run the target update-snippets)");
            line.replace(v.text_begin, v.text_end - v.text_begin, text);
            ++refreshed_;
            return true;
        } catch (const std::exception& e) {
            return problem(at + ": " + e.what());
        }
    }

    // --diff: the marker's text against the report of the same run in the other tree.
    bool diff(const prose::ValueMarker& v, const prose::RunDecl& d, const std::string& file, const std::string& at) {
        auto& t = tally_[file];
        ++t.values;
        const prose::Json* r = other_->report(d);
        if (!r) {
            ++t.missing;
            differences_.push_back(at + " (" + v.run + "): no report in " + other_->tree().string());
            return false;
        }
        const std::string text = prose::resolve(v, *r);
        if (v.tol >= 0 ? prose::hand_value_problem(v, *r).empty() : text == v.text) {
            ++t.same;
        } else {
            ++t.differ;
            differences_.push_back(at + " (" + v.run + "): text " + v.text + ", this run " + text);
        }
        return false;
    }

    // --check-values with the test suite's reports: the scene as built still reports the key.
    void still_reported(const prose::ValueMarker& v, const std::string& scene, const std::string& at) {
        const prose::Json* s = smoke_report(scene);
        if (!s) return;
        try {
            prose::lookup(*s, v.path.substr(v.path.find_first_of(".[")));
        } catch (const std::exception& e) {
            problem(at + ": the scene as built no longer reports it (its test run: " + e.what() + ")");
        }
    }

    // A smoke report: <smoke>/<scene>.json, read once.
    const prose::Json* smoke_report(const std::string& scene) {
        if (!smoke_) return nullptr;
        auto it = smoke_reports_.find(scene);
        if (it != smoke_reports_.end()) return it->second.get();
        std::unique_ptr<prose::Json> j;
        const fs::path p = *smoke_ / (scene + ".json");
        if (fs::exists(p)) j = std::make_unique<prose::Json>(prose::read_json(p));
        return (smoke_reports_[scene] = std::move(j)).get();
    }

    // A quotation of the code snippet `name` (whole lines, from line i to its end marker): checked
    // against the source, or rewritten by --update. Returns the index of the end marker's line.
    std::size_t quote(const std::string& name, const std::vector<std::string>& lines, std::size_t i,
                      const std::string& where, std::vector<std::string>& out, bool& changed) {
        std::size_t j = i + 1;
        while (j < lines.size() && !std::regex_match(lines[j], prose::snippet_use_end())) ++j;
        if (j == lines.size()) {
            problem(where + ": '<!-- snippet: " + name + " -->' has no '<!-- end snippet -->'");
            return i;
        }
        std::string current;
        for (std::size_t k = i + 1; k < j; ++k) current += lines[k] + "\n";
        const auto s = snippets_.find(name);
        if (s == snippets_.end()) {
            problem(where + ": no source defines snippet '" + name + "' (code removed or renamed?)");
            for (std::size_t k = i + 1; k <= j; ++k) out.push_back(lines[k]);
            return j;
        }
        s->second.used = true;
        ++quoted_;
        const std::string wanted = "```cpp\n" + s->second.text + "```\n";
        const bool update = mode_ == Mode::update;
        if (current != wanted) {
            ++stale_;
            if (update)
                changed = true;
            else if (mode_ == Mode::check)
                problem(where + ": snippet '" + name + "' differs from " + s->second.file + ":" +
                        std::to_string(s->second.line) + " (run: cmake --build <build> --target update-snippets)");
        }
        std::istringstream w(update ? wanted : current);
        for (std::string l; std::getline(w, l);) out.push_back(l);
        out.push_back(lines[j]);
        return j;
    }

    bool problem(const std::string& what) {
        problems_.push_back(what);
        return false;
    }

    void print_diff() const {
        Tally all;
        std::cout << "The value markers against the reports in " << other_->tree().string() << ":\n";
        for (const auto& [file, t] : tally_) {
            std::cout << "  " << file << ": " << t.values << " values, " << t.same << " as in the text, " << t.differ
                      << " different, " << t.missing << " without a report\n";
            all.values += t.values, all.same += t.same, all.differ += t.differ, all.missing += t.missing;
        }
        std::cout << "  all: " << all.values << " values, " << all.same << " as in the text, " << all.differ
                  << " different, " << all.missing << " without a report\n";
        for (const auto& d : differences_) std::cout << "  " << d << "\n";
    }

    void print_summary() const {
        const bool update = mode_ == Mode::update;
        std::cout << snippets_.size() << " snippets in the sources, " << quoted_ << " quotations in the prose";
        if (update) std::cout << ", " << stale_ << " refreshed";
        std::cout << "; " << n_values_ << " value markers";
        if (runs_) {
            std::cout << " (committed reports in " << (root_ / "figures").string() << ")";
            if (update) std::cout << ", " << refreshed_ << " refreshed";
        } else if (update) {
            std::cout << " (not refreshed: no list of runs given)";
        }
        std::cout << "\n";
    }

    fs::path root_;
    Mode mode_;
    const prose::Runs* runs_;
    const fs::path* smoke_;
    std::vector<std::string> problems_;
    prose::Tree tree_files_;
    std::map<std::string, prose::Snippet> snippets_;
    prose::Reports committed_;
    std::optional<prose::Reports> other_;
    std::set<std::string> scenes_;
    std::map<std::string, std::unique_ptr<prose::Json>> smoke_reports_;
    int quoted_ = 0, stale_ = 0, n_values_ = 0, refreshed_ = 0;
    std::map<std::string, Tally> tally_;  // diff: per prose file
    std::vector<std::string> differences_;
};

int snippets_and_values(const fs::path& root, Mode mode, const prose::Runs* runs, const fs::path* smoke,
                        const fs::path* tree) {
    return ProseChecker(root, mode, runs, smoke, tree).run();
}

// ------------------------------------------------------------------ numbers in the prose

// Every number of the prose that looks measured is a value marker or carries a tag that says
// what it is (prose.hpp). Per file: each untagged one, each tag that is malformed or covers
// numbers that are not there, and `once` (measured once, by hand) in a chapter.
class NumberLint {
public:
    explicit NumberLint(const fs::path& root) : root_(root) {}

    int run() {
        for (const auto& p : prose::scan_tree(root_).prose)
            if (fs::exists(p)) file(p);
        std::cout << "Numbers that look measured in " << files_ << " pages of prose: " << markers_ << " value markers ("
                  << hand_ << " of them typed by hand and checked), " << tagged_ << " tagged (";
        for (const auto& k : prose::number_kinds()) std::cout << (k == "exact" ? "" : ", ") << k << " " << kinds_[k];
        std::cout << "), " << problems_.size() << " problems\n";
        for (const auto& p : problems_) std::cout << "  " << p << "\n";
        return problems_.empty() ? 0 : 1;
    }

private:
    struct Pending {
        std::string kind, where;
        int left = 0;
    };

    void file(const fs::path& p) {
        ++files_;
        const std::string name = rel(p, root_);
        const bool manual = name.rfind("chapters/", 0) != 0 && name.rfind("exercises/", 0) != 0;
        bool in_fence = false, in_comment = false;
        Pending pending;
        const auto lines = prose::read_lines(p);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string where = name + ":" + std::to_string(i + 1);
            const std::string& line = lines[i];
            if (prose::is_fence(line)) in_fence = !in_fence;
            if (in_fence || prose::is_fence(line)) continue;
            if (line.find_first_not_of(" \t") == std::string::npos) {
                stale(pending);
                continue;
            }
            auto skip = masked(line, in_comment);
            sections(line, skip, where);
            struct Event {
                std::size_t at;
                const prose::NumberTag* tag;
                const prose::ProseNumber* number;
            };
            std::vector<Event> events;
            const auto tags = prose::find_number_tags(line);
            for (const auto& t : tags) events.push_back({t.begin, &t, nullptr});
            const auto numbers = prose::measured_numbers(line, skip);
            for (const auto& n : numbers) events.push_back({n.begin, nullptr, &n});
            std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.at < b.at; });
            for (const Event& e : events) {
                if (e.tag)
                    open_tag(*e.tag, where, manual, pending);
                else if (pending.left > 0)
                    --pending.left, ++tagged_, ++kinds_[pending.kind];
                else
                    problems_.push_back(where + ": " + e.number->text +
                                        " looks measured: make it a value marker, or tag it "
                                        "(<!--exact-->, <!--input-->, <!--const-->, <!--P-->)");
            }
        }
        stale(pending);
    }

    // Characters that are not prose: code spans, HTML comments (tags included; also one that
    // runs on from an earlier line), value markers (counted here) and link targets.
    std::vector<bool> masked(const std::string& line, bool& in_comment) {
        auto skip = prose::code_span_mask(line);
        std::size_t from = 0;
        if (in_comment) {
            const auto close = line.find("-->");
            from = close == std::string::npos ? line.size() : close + 3;
            std::fill(skip.begin(), skip.begin() + static_cast<std::ptrdiff_t>(from), true);
            in_comment = close == std::string::npos;
        }
        for (const auto& v : prose::find_value_markers(line)) {
            ++markers_;
            if (v.tol >= 0) ++hand_;
            std::fill(skip.begin() + static_cast<std::ptrdiff_t>(v.begin),
                      skip.begin() + static_cast<std::ptrdiff_t>(v.end), true);
        }
        for (std::size_t open; !in_comment && (open = line.find("<!--", from)) != std::string::npos;) {
            if (skip[open]) {
                from = open + 4;
                continue;
            }
            const auto close = line.find("-->", open + 4);
            const std::size_t end = close == std::string::npos ? line.size() : close + 3;
            std::fill(skip.begin() + static_cast<std::ptrdiff_t>(open), skip.begin() + static_cast<std::ptrdiff_t>(end),
                      true);
            in_comment = close == std::string::npos;
            from = end;
        }
        static const std::regex target(R"(\]\([^)]*\))");
        for (auto it = std::sregex_iterator(line.begin(), line.end(), target); it != std::sregex_iterator(); ++it)
            std::fill(skip.begin() + it->position(0), skip.begin() + it->position(0) + it->length(0), true);
        return skip;
    }

    // A section of the workbook named by its number (section 5.6, sections 6.1-6.3, §6.2; [P]'s
    // sections have no subsections) is the text of a link, which the book's render checks leads
    // to a real heading: a number alone would dangle when the sections move.
    void sections(const std::string& line, const std::vector<bool>& skip, const std::string& where) {
        static const std::regex link(R"(\[((?:[^\[\]]|\[[^\]]*\])*)\]\([^)]*\))");
        static const std::regex section(R"((?:[Ss]ections?|§)\s*[0-9]+\.[0-9]+)");
        static const std::regex number(R"(([0-9]+)\.([0-9]+))");
        std::vector<bool> in_link(line.size(), false);
        for (auto it = std::sregex_iterator(line.begin(), line.end(), link); it != std::sregex_iterator(); ++it) {
            std::fill(in_link.begin() + it->position(1), in_link.begin() + it->position(1) + it->length(1), true);
            // The heading it leads to has the number it names: #56-... for section 5.6.
            const std::string text = (*it)[1], whole = it->str();
            std::smatch m, n;
            if (!std::regex_search(text, m, section)) continue;
            const std::string ref = m.str();
            std::regex_search(ref, n, number);
            const std::string want = "#" + n[1].str() + n[2].str() + "-";
            if (whole.find(want) == std::string::npos)
                problems_.push_back(where + ": the link '" + whole + "' names " + ref +
                                    " but does not lead to its heading (#" + n[1].str() + n[2].str() + "-...)");
        }
        for (auto it = std::sregex_iterator(line.begin(), line.end(), section); it != std::sregex_iterator(); ++it) {
            const auto at = static_cast<std::size_t>(it->position(0));
            if (!skip[at] && !in_link[at])
                problems_.push_back(where + ": '" + it->str() + "' is not a link: write [" + it->str() +
                                    "](page.md#its-heading), which the "
                                    "book's render checks");
        }
    }

    void open_tag(const prose::NumberTag& t, const std::string& where, bool manual, Pending& pending) {
        stale(pending);
        if (!t.error.empty()) {
            problems_.push_back(where + ": " + t.error);
            return;
        }
        if (t.kind == "once" && !manual) {
            problems_.push_back(where +
                                ": <!--once--> (measured once, by hand) belongs in the manuals, never in a "
                                "chapter: make the number a value marker");
            return;
        }
        pending = {t.kind, where, t.count};
    }

    void stale(Pending& pending) {
        if (pending.left > 0)
            problems_.push_back(pending.where + ": the tag <!--" + pending.kind + "--> has " +
                                std::to_string(pending.left) +
                                " number(s) left to cover in its paragraph, and there are none (a stale tag)");
        pending = {};
    }

    fs::path root_;
    std::vector<std::string> problems_;
    std::map<std::string, int> kinds_;
    int files_ = 0, markers_ = 0, hand_ = 0, tagged_ = 0;
};

int check_numbers(const fs::path& root) { return NumberLint(root).run(); }

// ------------------------------------------------------------------ names of code in the prose

struct Corpus {
    std::set<std::string> words;                    // every identifier in the code
    std::set<std::string> test_prefixes;            // "hat" of TEST_CASE("hat: ...")
    std::map<std::string, fs::path> scene_sources;  // scene name -> its .cpp
};

Corpus read_corpus(const fs::path& root) {
    Corpus c;
    std::vector<fs::path> files;
    for (const char* dir : {"exercises", "chapters", "tests", "cmake", "figures", ".ci"}) {
        if (!fs::exists(root / dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
            if (!e.is_regular_file()) continue;
            const auto ext = e.path().extension().string();
            if (ext == ".md" || ext == ".svg" || ext == ".png" || ext == ".json" || ext == ".csv")
                continue;                                                     // outputs, not code
            if (rel(e.path(), root).rfind("cmake/tools/", 0) == 0) continue;  // the tools talk about markers
            files.push_back(e.path());
        }
    }
    files.push_back(root / "CMakeLists.txt");
    const std::regex word(R"([A-Za-z_][A-Za-z0-9_]*)");
    const std::regex test_case(R"(TEST_CASE\("([A-Za-z_][A-Za-z0-9_]*):)");
    for (const auto& f : files) {
        const std::string text = prose::read_text(f);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator(); ++it)
            c.words.insert(it->str());
        if (rel(f, root).rfind("tests/", 0) == 0)
            for (auto it = std::sregex_iterator(text.begin(), text.end(), test_case); it != std::sregex_iterator();
                 ++it)
                c.test_prefixes.insert((*it)[1]);
        if (rel(f, root).rfind("chapters/", 0) == 0 && f.extension() == ".cpp") c.scene_sources[f.stem().string()] = f;
    }
    return c;
}

bool is_library_name(const std::string& t) {
    for (const char* prefix : {"std::", "Eigen::", "boost::", "doctest::", "gsl_", "GSL_"})
        if (t.rfind(prefix, 0) == 0) return true;
    return false;
}

// Prose that names code which does not exist: identifiers and paths in `code spans`, and the
// scene and grader commands of ```sh blocks.
class NameChecker {
public:
    explicit NameChecker(const fs::path& root) : root_(root), corpus_(read_corpus(root)) {}

    int run() {
        for (const auto& p : prose::scan_tree(root_).prose)
            if (fs::exists(p)) file(p);
        std::cout << names_ << " names of code and " << commands_
                  << " commands in the prose checked against the sources\n";
        for (const auto& p : problems_) std::cout << "  " << p << "\n";
        return problems_.empty() ? 0 : 1;
    }

private:
    void file(const fs::path& p) {
        const auto lines = prose::read_lines(p);
        bool in_fence = false;
        std::string fence_lang;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string& line = lines[i];
            const std::string where = rel(p, root_) + ":" + std::to_string(i + 1);
            if (prose::is_fence(line)) {
                in_fence = !in_fence;
                fence_lang = in_fence ? line.substr(line.find_first_not_of(" `~")) : "";
            } else if (in_fence) {
                if (fence_lang == "sh" || fence_lang == "bash") command(line, where);
            } else {
                static const std::regex span(R"(`([^`]+)`)");
                for (auto it = std::sregex_iterator(line.begin(), line.end(), span); it != std::sregex_iterator(); ++it)
                    code_span((*it)[1], where, p.parent_path());
            }
        }
    }

    // A shell line: a scene run with its options, or a grader run.
    void command(const std::string& line, const std::string& where) {
        static const std::regex scene_cmd(R"(build/[^/ ]+/scenes/([A-Za-z0-9_]+)((?: +[^ ]+)*))");
        static const std::regex grader_cmd(R"(build/[^/ ]+/graders/grade_([A-Za-z0-9_]+))");
        std::smatch m;
        if (std::regex_search(line, m, scene_cmd)) {
            ++commands_;
            scene_options(m[1], m[2], where);
        }
        if (std::regex_search(line, m, grader_cmd)) {
            ++commands_;
            if (!fs::exists(root_ / "tests" / (m[1].str() + "_test.cpp")))
                problems_.push_back(where + ": runs grade_" + m[1].str() + ", but tests/" + m[1].str() +
                                    "_test.cpp does not exist");
        }
    }

    // The scene exists, and every --option given to it is one it declares: in its own source, in a
    // header of its chapter folder (a chapter may declare shared options in a common header) or of
    // the scene kit (the body's moments --A --B --C are declared in kit/body.hpp).
    void scene_options(const std::string& scene, const std::string& args_text, const std::string& where) {
        static const std::set<std::string> common = {"help", "json", "out", "no-figure", "budget", "list-options"};
        const auto src = corpus_.scene_sources.find(scene);
        if (src == corpus_.scene_sources.end()) {
            problems_.push_back(where + ": runs the scene '" + scene + "', but no chapters/*/" + scene + ".cpp exists");
            return;
        }
        std::string text = prose::read_text(src->second);
        for (const fs::path& dir : {fs::path(src->second).parent_path(), root_ / "chapters" / "kit"}) {
            if (!fs::is_directory(dir)) continue;  // a workbook without a scene kit
            for (const auto& e : fs::directory_iterator(dir))
                if (e.path().extension() == ".hpp") text += prose::read_text(e.path());
        }
        std::istringstream args(args_text);
        for (std::string a; args >> a;) {
            if (a.rfind("--", 0) != 0) continue;
            const std::string opt = a.substr(2, a.find('=') == std::string::npos ? std::string::npos : a.find('=') - 2);
            if (!common.count(opt) && text.find("\"" + opt + "\"") == std::string::npos)
                problems_.push_back(where + ": the scene " + scene + " has no option --" + opt);
        }
    }

    // `name`, `name()`, `prefix:` (a grader's test name) or `a/path`.
    void code_span(std::string t, const std::string& where, const fs::path& dir) {
        static const std::regex identifier(R"([A-Za-z_][A-Za-z0-9_]*(::[A-Za-z_][A-Za-z0-9_]*)*)");
        while (!t.empty() && t.back() == ' ') t.pop_back();
        while (!t.empty() && t.front() == ' ') t.erase(0, 1);
        const bool prefix = !t.empty() && t.back() == ':';
        if (prefix) t.pop_back();
        if (t.size() > 2 && t.compare(t.size() - 2, 2, "()") == 0) t.resize(t.size() - 2);
        if (!std::regex_match(t, identifier)) return path(t, where, dir);
        if (prefix) {
            ++names_;
            if (!corpus_.test_prefixes.count(t))
                problems_.push_back(where + ": no grader's test name starts with '" + t + ":'");
        } else if (!is_library_name(t) && (t.find('_') != std::string::npos || t.find("::") != std::string::npos)) {
            ++names_;  // std::, Eigen::, GSL's gsl_... are not this workbook's code
            const std::string last = t.substr(t.rfind(':') == std::string::npos ? 0 : t.rfind(':') + 1);
            if (!corpus_.words.count(last))
                problems_.push_back(where + ": `" + t + "` does not occur in the code (renamed or removed?)");
        }
    }

    // A path in the tree; build outputs and placeholders (NN_, <x>, *) are not checked. Relative
    // to the root, the prose's folder, or a top-level folder (`kit/` in a table row about
    // chapters/; `rigid/rotation.hpp` and `rigid/ode.hpp` as they are #included).
    void path(const std::string& t, const std::string& where, const fs::path& dir) {
        static const std::regex path_like(R"([A-Za-z0-9_.][A-Za-z0-9_./-]*/[A-Za-z0-9_./-]*)");
        static const std::regex source_ext(R"(.*\.(cpp|hpp|md|cmake|gp|txt|json|svg|png)$)");
        if (!std::regex_match(t, path_like) || t.rfind("build/", 0) == 0 || t.find("NN") != std::string::npos) return;
        if (t.back() != '/' && !std::regex_match(t, source_ext)) return;
        ++names_;
        std::vector<fs::path> bases{root_, dir, root_ / "chapters" / "kit", root_ / "exercises" / "provided"};
        for (const auto& e : fs::directory_iterator(root_))
            if (e.is_directory()) bases.push_back(e.path());
        for (const auto& base : bases)
            if (fs::exists(base / t)) return;
        problems_.push_back(where + ": `" + t + "` does not exist");
    }

    fs::path root_;
    Corpus corpus_;
    std::vector<std::string> problems_;
    int names_ = 0, commands_ = 0;
};

int check_names(const fs::path& root) { return NameChecker(root).run(); }

int usage() {
    std::cerr << "usage: snippets --check <root> | --check-names <root> | --check-numbers <root>\n"
                 "                | --check-values <root> <runs.txt> [<smoke>]\n"
                 "                | --update <root> [<runs.txt>] | --diff <root> <runs.txt> <tree>\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) return usage();
    const std::string mode = argv[1];
    const fs::path root = fs::absolute(argv[2]);
    try {
        if (mode == "--check" && argc == 3) return snippets_and_values(root, Mode::check, nullptr, nullptr, nullptr);
        if (mode == "--check-names" && argc == 3) return check_names(root);
        if (mode == "--check-numbers" && argc == 3) return check_numbers(root);
        if (mode == "--check-values" && (argc == 4 || argc == 5)) {
            const prose::Runs runs(argv[3]);
            const fs::path smoke = argc == 5 ? fs::absolute(argv[4]) : fs::path();
            return snippets_and_values(root, Mode::check_values, &runs, argc == 5 ? &smoke : nullptr, nullptr);
        }
        if (mode == "--update" && (argc == 3 || argc == 4)) {
            if (argc == 3) return snippets_and_values(root, Mode::update, nullptr, nullptr, nullptr);
            const prose::Runs runs(argv[3]);
            return snippets_and_values(root, Mode::update, &runs, nullptr, nullptr);
        }
        if (mode == "--diff" && argc == 5) {
            const prose::Runs runs(argv[3]);
            const fs::path tree = fs::absolute(argv[4]);
            return snippets_and_values(root, Mode::diff, &runs, nullptr, &tree);
        }
    } catch (const std::exception& e) {
        std::cerr << "snippets: " << e.what() << "\n";
        return 1;
    }
    return usage();
}
