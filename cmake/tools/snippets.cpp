// Keeps the prose of the book honest about the code and the numbers it quotes.
//
//   snippets --check        <root>        fail on a missing, stale or unused code snippet, or a
//                                         malformed value marker (see prose.hpp for both)
//   snippets --check-names  <root>        fail on prose that names code which does not exist:
//                                         `identifiers_with_underscores` and `ns::names` (not
//                                         std::, Eigen::, boost::, doctest::, gsl_), `test:`
//                                         prefixes, `paths/to/files.cpp`, and the scenes, options
//                                         and graders of the ```sh examples
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
int snippets_and_values(const fs::path& root, Mode mode, const prose::Runs* runs, const fs::path* smoke,
                        const fs::path* tree) {
    const bool update = mode == Mode::update;
    std::vector<std::string> problems;
    const auto tree_files = prose::scan_tree(root);
    auto snippets = prose::collect_snippets(root, tree_files.sources, problems);
    prose::Reports committed(root / "figures");
    std::optional<prose::Reports> other;
    if (tree) other.emplace(*tree);

    std::set<std::string> scenes;  // a scene is chapters/*/<scene>.cpp
    for (const auto& p : tree_files.sources)
        if (rel(p, root).rfind("chapters/", 0) == 0 && p.extension() == ".cpp") scenes.insert(p.stem().string());

    // A smoke report: <smoke>/<scene>.json, read once.
    std::map<std::string, std::unique_ptr<prose::Json>> smoke_reports;
    auto smoke_report = [&](const std::string& scene) -> const prose::Json* {
        if (!smoke) return nullptr;
        auto it = smoke_reports.find(scene);
        if (it != smoke_reports.end()) return it->second.get();
        std::unique_ptr<prose::Json> j;
        const fs::path p = *smoke / (scene + ".json");
        if (fs::exists(p)) j = std::make_unique<prose::Json>(prose::read_json(p));
        return (smoke_reports[scene] = std::move(j)).get();
    };

    int quoted = 0, stale = 0, n_values = 0, refreshed = 0;
    struct Tally {
        int values = 0, same = 0, differ = 0, missing = 0;
    };
    std::map<std::string, Tally> tally;  // diff: per prose file
    std::vector<std::string> differences;
    for (const auto& p : tree_files.prose) {
        if (!fs::exists(p)) continue;
        const auto lines = prose::read_lines(p);
        std::vector<std::string> out;
        bool changed = false, in_fence = false;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            std::smatch m;
            const std::string where = rel(p, root) + ":" + std::to_string(i + 1);
            if (prose::is_fence(lines[i])) in_fence = !in_fence;
            if (in_fence || prose::is_fence(lines[i])) {
                out.push_back(lines[i]);
                continue;
            }
            // Value markers, inline.
            std::string line = lines[i];
            auto markers = prose::find_value_markers(line);
            for (auto v = markers.rbegin(); v != markers.rend(); ++v) {
                ++n_values;
                const std::string at = where + ": value '" + v->path + "'";
                if (!v->error.empty()) {
                    problems.push_back(at + ": " + v->error);
                    continue;
                }
                const std::string scene = v->scene();
                if (!scenes.count(scene)) {
                    problems.push_back(at + ": there is no scene '" + scene + "' (chapters/*/" + scene + ".cpp)");
                    continue;
                }
                if (!runs) continue;
                const prose::RunDecl* d = runs->find(scene, v->run);
                if (!d) {
                    problems.push_back(at + ": the scene " + scene + " has no run '" + v->run + "' (declared: " +
                                       runs->names(scene) + ")");
                    continue;
                }
                try {
                    if (mode == Mode::diff) {
                        auto& t = tally[rel(p, root)];
                        ++t.values;
                        const prose::Json* r = other->report(*d);
                        if (!r) {
                            ++t.missing;
                            differences.push_back(at + " (" + v->run + "): no report in " + other->tree().string());
                            continue;
                        }
                        const std::string text = prose::resolve(*v, *r);
                        if (text == v->text) {
                            ++t.same;
                        } else {
                            ++t.differ;
                            differences.push_back(at + " (" + v->run + "): text " + v->text + ", this run " + text);
                        }
                        continue;
                    }
                    if (mode == Mode::check_values) {
                        if (const prose::Json* s = smoke_report(scene)) {
                            try {
                                prose::lookup(*s, v->path.substr(v->path.find_first_of(".[")));
                            } catch (const std::exception& e) {
                                problems.push_back(at + ": the scene as built no longer reports it (its test run: " +
                                                   e.what() + ")");
                            }
                        }
                    }
                    const prose::Json* r = committed.report(*d);
                    if (!r) {
                        problems.push_back(at + ": no committed report " + rel(prose::report_path(root / "figures", *d), root) +
                                           " (run cmake/workbook run, then the target update-figures)");
                        continue;
                    }
                    const std::string text = prose::resolve(*v, *r);
                    if (text == v->text) continue;
                    if (update) {
                        line.replace(v->text_begin, v->text_end - v->text_begin, text);
                        ++refreshed;
                        changed = true;
                    } else {
                        problems.push_back(at + ": the text says '" + v->text + "', its committed report " +
                                           rel(prose::report_path(root / "figures", *d), root) + " says '" + text +
                                           "' (run the target update-snippets)");
                    }
                } catch (const std::exception& e) {
                    problems.push_back(at + ": " + e.what());
                }
            }
            out.push_back(line);
            // A quotation of a code snippet: whole lines.
            if (!std::regex_match(lines[i], m, prose::snippet_use_marker())) continue;
            const std::string name = m[1];
            std::size_t j = i + 1;
            while (j < lines.size() && !std::regex_match(lines[j], prose::snippet_use_end())) ++j;
            if (j == lines.size()) {
                problems.push_back(where + ": '<!-- snippet: " + name + " -->' has no '<!-- end snippet -->'");
                continue;
            }
            std::string current;
            for (std::size_t k = i + 1; k < j; ++k) current += lines[k] + "\n";
            const auto s = snippets.find(name);
            if (s == snippets.end()) {
                problems.push_back(where + ": no source defines snippet '" + name + "' (code removed or renamed?)");
                for (std::size_t k = i + 1; k <= j; ++k) out.push_back(lines[k]);
                i = j;
                continue;
            }
            s->second.used = true;
            ++quoted;
            const std::string wanted = "```cpp\n" + s->second.text + "```\n";
            if (current != wanted) {
                ++stale;
                if (update) changed = true;
                else if (mode == Mode::check)
                    problems.push_back(where + ": snippet '" + name + "' differs from " + s->second.file + ":" +
                                       std::to_string(s->second.line) +
                                       " (run: cmake --build <build> --target update-snippets)");
            }
            std::istringstream w(update ? wanted : current);
            for (std::string l; std::getline(w, l);) out.push_back(l);
            out.push_back(lines[j]);
            i = j;
        }
        if (update && changed) {
            std::string text;
            for (const auto& l : out) text += l + "\n";
            prose::write_text(p, text);
            std::cout << "updated " << rel(p, root) << "\n";
        }
    }
    if (mode == Mode::check)
        for (const auto& [name, s] : snippets)
            if (!s.used) problems.push_back(s.file + ":" + std::to_string(s.line) + ": snippet '" + name + "' is not quoted anywhere in the prose");

    if (mode == Mode::diff) {
        Tally all;
        std::cout << "The value markers against the reports in " << tree->string() << ":\n";
        for (const auto& [file, t] : tally) {
            std::cout << "  " << file << ": " << t.values << " values, " << t.same << " as in the text, " << t.differ
                      << " different, " << t.missing << " without a report\n";
            all.values += t.values, all.same += t.same, all.differ += t.differ, all.missing += t.missing;
        }
        std::cout << "  all: " << all.values << " values, " << all.same << " as in the text, " << all.differ
                  << " different, " << all.missing << " without a report\n";
        for (const auto& d : differences) std::cout << "  " << d << "\n";
        for (const auto& p : problems) std::cout << "  " << p << "\n";
        return problems.empty() ? 0 : 1;
    }
    std::cout << snippets.size() << " snippets in the sources, " << quoted << " quotations in the prose";
    if (update) std::cout << ", " << stale << " refreshed";
    std::cout << "; " << n_values << " value markers";
    if (runs) {
        std::cout << " (committed reports in " << (root / "figures").string() << ")";
        if (update) std::cout << ", " << refreshed << " refreshed";
    } else if (update) {
        std::cout << " (not refreshed: no list of runs given)";
    }
    std::cout << "\n";
    for (const auto& p : problems) std::cout << "  " << p << "\n";
    return problems.empty() ? 0 : 1;
}

// ------------------------------------------------------------------ names of code in the prose

struct Corpus {
    std::set<std::string> words;                     // every identifier in the code
    std::set<std::string> test_prefixes;             // "hat" of TEST_CASE("hat: ...")
    std::map<std::string, fs::path> scene_sources;   // scene name -> its .cpp
};

Corpus read_corpus(const fs::path& root) {
    Corpus c;
    std::vector<fs::path> files;
    for (const char* dir : {"exercises", "chapters", "tests", "cmake", "figures", ".ci"}) {
        if (!fs::exists(root / dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
            if (!e.is_regular_file()) continue;
            const auto ext = e.path().extension().string();
            if (ext == ".md" || ext == ".svg" || ext == ".png" || ext == ".json" || ext == ".csv") continue;  // outputs, not code
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
            for (auto it = std::sregex_iterator(text.begin(), text.end(), test_case); it != std::sregex_iterator(); ++it)
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

int check_names(const fs::path& root) {
    const auto tree = prose::scan_tree(root);
    const Corpus corpus = read_corpus(root);
    std::vector<std::string> problems;
    const std::regex identifier(R"([A-Za-z_][A-Za-z0-9_]*(::[A-Za-z_][A-Za-z0-9_]*)*)");
    const std::regex path_like(R"([A-Za-z0-9_.][A-Za-z0-9_./-]*/[A-Za-z0-9_./-]*)");
    const std::regex source_ext(R"(.*\.(cpp|hpp|md|cmake|gp|txt|json|svg|png)$)");
    const std::regex span(R"(`([^`]+)`)");
    const std::regex scene_cmd(R"(build/[^/ ]+/scenes/([A-Za-z0-9_]+)((?: +[^ ]+)*))");
    const std::regex grader_cmd(R"(build/[^/ ]+/graders/grade_([A-Za-z0-9_]+))");
    const std::set<std::string> common_options = {"help", "json", "out", "no-figure", "budget", "list-options"};
    int names = 0, commands = 0;

    for (const auto& p : tree.prose) {
        if (!fs::exists(p)) continue;
        const auto lines = prose::read_lines(p);
        const fs::path dir = p.parent_path();
        bool in_fence = false;
        std::string fence_lang;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string& line = lines[i];
            const std::string where = rel(p, root) + ":" + std::to_string(i + 1);
            if (prose::is_fence(line)) {
                in_fence = !in_fence;
                fence_lang = in_fence ? line.substr(line.find_first_not_of(" `~")) : "";
                continue;
            }
            if (in_fence) {
                if (fence_lang != "sh" && fence_lang != "bash") continue;
                std::smatch m;
                if (std::regex_search(line, m, scene_cmd)) {
                    ++commands;
                    const auto src = corpus.scene_sources.find(m[1]);
                    if (src == corpus.scene_sources.end()) {
                        problems.push_back(where + ": runs the scene '" + m[1].str() + "', but no chapters/*/" + m[1].str() + ".cpp exists");
                    } else {
                        // The scene's own source, and the headers of its chapter folder and of
                        // the scene kit (a chapter may declare shared options in a common
                        // header; the body's moments --A --B --C are declared in kit/body.hpp).
                        std::string text = prose::read_text(src->second);
                        std::error_code ignored;  // a tree without chapters/kit (the book's self-test)
                        for (const auto& dir : {fs::path(src->second).parent_path(), root / "chapters" / "kit"})
                            for (const auto& e : fs::directory_iterator(dir, fs::directory_options::none, ignored))
                                if (e.path().extension() == ".hpp") text += prose::read_text(e.path());
                        std::istringstream args(m[2].str());
                        for (std::string a; args >> a;) {
                            if (a.rfind("--", 0) != 0) continue;
                            const std::string opt = a.substr(2, a.find('=') == std::string::npos ? std::string::npos : a.find('=') - 2);
                            if (!common_options.count(opt) && text.find("\"" + opt + "\"") == std::string::npos)
                                problems.push_back(where + ": the scene " + m[1].str() + " has no option --" + opt);
                        }
                    }
                }
                if (std::regex_search(line, m, grader_cmd)) {
                    ++commands;
                    if (!fs::exists(root / "tests" / (m[1].str() + "_test.cpp")))
                        problems.push_back(where + ": runs grade_" + m[1].str() + ", but tests/" + m[1].str() + "_test.cpp does not exist");
                }
                continue;
            }
            for (auto it = std::sregex_iterator(line.begin(), line.end(), span); it != std::sregex_iterator(); ++it) {
                std::string t = (*it)[1];
                while (!t.empty() && t.back() == ' ') t.pop_back();
                while (!t.empty() && t.front() == ' ') t.erase(0, 1);
                const bool prefix = !t.empty() && t.back() == ':';
                if (prefix) t.pop_back();
                if (t.size() > 2 && t.compare(t.size() - 2, 2, "()") == 0) t.resize(t.size() - 2);
                if (std::regex_match(t, identifier)) {
                    if (prefix) {
                        ++names;
                        if (!corpus.test_prefixes.count(t))
                            problems.push_back(where + ": no grader's test name starts with '" + t + ":'");
                    } else if (is_library_name(t)) {
                        continue;  // std::, Eigen::, GSL's gsl_...: not this workbook's code
                    } else if (t.find('_') != std::string::npos || t.find("::") != std::string::npos) {
                        ++names;
                        const std::string last = t.substr(t.rfind(':') == std::string::npos ? 0 : t.rfind(':') + 1);
                        if (!corpus.words.count(last))
                            problems.push_back(where + ": `" + t + "` does not occur in the code (renamed or removed?)");
                    }
                    continue;
                }
                // A path in the tree; build outputs and placeholders (NN_, <x>, *) are not checked.
                if (!std::regex_match(t, path_like) || t.rfind("build/", 0) == 0 || t.find("NN") != std::string::npos)
                    continue;
                if (t.back() != '/' && !std::regex_match(t, source_ext)) continue;
                ++names;
                bool found = false;
                // Relative to the root, the prose's folder, or a top-level folder (`kit/` in a
                // table row about chapters/; `rigid/rotation.hpp` and `rigid/ode.hpp` as they are #included).
                std::vector<fs::path> bases{root, dir};
                for (const auto& e : fs::directory_iterator(root))
                    if (e.is_directory()) bases.push_back(e.path());
                bases.push_back(root / "chapters" / "kit");
                bases.push_back(root / "exercises" / "provided");
                for (const auto& base : bases) found = found || fs::exists(base / t);
                if (!found) problems.push_back(where + ": `" + t + "` does not exist");
            }
        }
    }
    std::cout << names << " names of code and " << commands << " commands in the prose checked against the sources\n";
    for (const auto& p : problems) std::cout << "  " << p << "\n";
    return problems.empty() ? 0 : 1;
}

int usage() {
    std::cerr << "usage: snippets --check <root> | --check-names <root> | --check-values <root> <runs.txt> [<smoke>]\n"
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
