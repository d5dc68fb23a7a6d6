// snippets --check-names: the prose names only code that exists (identifiers, paths, test names,
// the scenes and options of its shell examples). The code spans and ```sh blocks are the nodes
// of each page's tree as pandoc parses it (markdown.hpp); regular expressions read what is in
// them (C++ names, paths, command lines), which is not Markdown.
#include <algorithm>
#include <functional>
#include <iostream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "markdown.hpp"
#include "prose.hpp"
#include "snippets.hpp"

namespace snippets {

namespace {

using prose::rel;

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
                continue;                                                          // outputs, not code
            if (rel(e.path(), root).rfind("cmake/book/tools/", 0) == 0) continue;  // the tools talk about markers
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
    // One page, read as pandoc parses it (markdown.hpp): its code spans and its ```sh blocks.
    void file(const fs::path& p) {
        const md::Page page = md::read_page(p);
        const std::string name = rel(p, root_);
        const auto where = [&](int line) { return name + ":" + std::to_string(line); };
        md::walk(page.blocks, [&](const md::Json& n) {
            const std::string& t = md::type(n);
            if (t == "Code") code_span(n["c"][1].get<std::string>(), where(md::line(n)), p.parent_path());
            if (t == "CodeBlock" && !n["c"][0][1].empty() && (n["c"][0][1][0] == "sh" || n["c"][0][1][0] == "bash")) {
                std::istringstream lines(n["c"][1].get<std::string>());
                int at = md::line(n);  // the fence's line
                for (std::string l; std::getline(lines, l);) command(l, where(++at));
            }
            if (t == "RawBlock") raw_block(n, where, p.parent_path());
            return true;
        });
    }

    // A block of raw HTML (a line that starts with a comment or a tag): the tree has its source
    // text only, where a `code span` is read as GitHub shows it there.
    void raw_block(const md::Json& n, const std::function<std::string(int)>& where, const fs::path& dir) {
        static const std::regex span(R"(`([^`]+)`)");
        std::istringstream lines(n["c"][1].get<std::string>());
        int at = md::line(n);
        for (std::string l; std::getline(lines, l); ++at)
            for (auto it = std::sregex_iterator(l.begin(), l.end(), span); it != std::sregex_iterator(); ++it)
                code_span((*it)[1], where(at), dir);
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

}  // namespace

int check_names(const fs::path& root) { return NameChecker(root).run(); }

}  // namespace snippets
