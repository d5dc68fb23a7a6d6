// Keeps the prose of the book honest about the code and the numbers it quotes.
//
//   snippets --check        <root>        fail on a missing, stale or unused code snippet, or a
//                                         malformed value marker (see prose.hpp for both)
//   snippets --check-names  <root>        fail on prose that names code which does not exist:
//                                         `identifiers_with_underscores` and `ns::names` (not
//                                         std::, Eigen::, boost::, doctest::, gsl_), `test:`
//                                         prefixes, `paths/to/files.cpp`, and the scenes, options
//                                         and graders of the ```sh examples
//   snippets --check-values <root> <dir>  fail on a value marker whose key the scenes'
//                                         reports in <dir> (<scene>.json) do not have
//   snippets --update       <root> [dir]  rewrite the quoted code from the sources and, with
//                                         <dir>, the quoted values from the reports
//
// The committed prose carries the values of the last `--update`; the rendered book (book.cpp)
// always shows the values of its own build. So a value is "stale" only when its key no longer
// exists: run times change from run to run, and round-off errors from machine to machine.
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

// Checks (or refreshes) the quoted code and the value markers of every prose file.
int snippets_and_values(const fs::path& root, bool update, const fs::path* values_dir, bool check_values) {
    std::vector<std::string> problems;
    const auto tree = prose::scan_tree(root);
    auto snippets = prose::collect_snippets(root, tree.sources, problems);
    std::optional<prose::Values> values;
    if (values_dir) values.emplace(*values_dir);

    std::set<std::string> scenes;  // a scene is chapters/*/<scene>.cpp
    for (const auto& p : tree.sources)
        if (rel(p, root).rfind("chapters/", 0) == 0 && p.extension() == ".cpp") scenes.insert(p.stem().string());

    int quoted = 0, stale = 0, n_values = 0, refreshed = 0, unmeasured = 0;
    for (const auto& p : tree.prose) {
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
                const std::string scene = v->path.substr(0, v->path.find_first_of(".["));
                if (!scenes.count(scene)) {
                    problems.push_back(at + ": there is no scene '" + scene + "' (chapters/*/" + scene + ".cpp)");
                    continue;
                }
                if (!values) continue;
                try {
                    const auto text = prose::resolve(*v, *values);
                    if (!text) {
                        ++unmeasured;
                        if (check_values) problems.push_back(at + ": no report " + (values->dir() / (scene + ".json")).string());
                        continue;
                    }
                    if (update && *text != v->text) {
                        line.replace(v->text_begin, v->text_end - v->text_begin, *text);
                        ++refreshed;
                        changed = true;
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
                else
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
    for (const auto& [name, s] : snippets)
        if (!s.used) problems.push_back(s.file + ":" + std::to_string(s.line) + ": snippet '" + name + "' is not quoted anywhere in the prose");

    std::cout << snippets.size() << " snippets in the sources, " << quoted << " quotations in the prose";
    if (update) std::cout << ", " << stale << " refreshed";
    std::cout << "; " << n_values << " value markers";
    if (values) {
        std::cout << " (reports in " << values->dir().string() << ")";
        if (update) std::cout << ", " << refreshed << " refreshed";
        if (unmeasured) std::cout << ", " << unmeasured << " without a report (left as they were)";
    } else if (update) {
        std::cout << " (not refreshed: no report folder given)";
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
            if (ext == ".md" || ext == ".svg" || ext == ".png") continue;
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
                        // The scene's own source, and the headers of its chapter folder (a
                        // chapter may declare shared options in a common header).
                        std::string text = prose::read_text(src->second);
                        for (const auto& e : fs::directory_iterator(fs::path(src->second).parent_path()))
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
                // table row about chapters/; `rigid/rotation.hpp` as it is #included).
                std::vector<fs::path> bases{root, dir};
                for (const auto& e : fs::directory_iterator(root))
                    if (e.is_directory()) bases.push_back(e.path());
                bases.push_back(root / "chapters" / "kit");
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
    std::cerr << "usage: snippets --check <root> | --check-names <root> | --check-values <root> <reports>\n"
                 "                | --update <root> [<reports>]\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) return usage();
    const std::string mode = argv[1];
    const fs::path root = fs::absolute(argv[2]);
    try {
        if (mode == "--check" && argc == 3) return snippets_and_values(root, false, nullptr, false);
        if (mode == "--check-names" && argc == 3) return check_names(root);
        if (mode == "--check-values" && argc == 4) {
            const fs::path dir = fs::absolute(argv[3]);
            return snippets_and_values(root, false, &dir, true);
        }
        if (mode == "--update" && (argc == 3 || argc == 4)) {
            fs::path dir = argc == 4 ? fs::absolute(argv[3]) : fs::path();
            const bool have = argc == 4 && fs::is_directory(dir);
            if (argc == 4 && !have) std::cout << "no scene reports in " << dir.string() << " yet (run: cmake/workbook run): values left as they are\n";
            return snippets_and_values(root, true, have ? &dir : nullptr, false);
        }
    } catch (const std::exception& e) {
        std::cerr << "snippets: " << e.what() << "\n";
        return 1;
    }
    return usage();
}
