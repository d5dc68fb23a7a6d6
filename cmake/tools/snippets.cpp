// Keeps the code in the prose identical to the code in the sources.
//
//   snippets --check  <workbook root>   fail on a missing, stale or unused snippet
//   snippets --update <workbook root>   rewrite the quoted code from the sources
//
// In a source file (exercises/rigid/*.hpp, chapters/**/*.cpp|hpp, tests/*.cpp|hpp):
//     // snippet: NAME
//     ...code...
//     // end snippet
// In the prose (README.md, chapters/**/*.md, exercises/hints.md):
//     <!-- snippet: NAME -->
//     ```cpp
//     ...code, filled in by --update...
//     ```
//     <!-- end snippet -->
// solutions/ is never scanned: the prose must not give away the exercises.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Snippet {
    std::string file, text;
    int line = 0;
    bool used = false;
};

std::vector<std::string> read_lines(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

std::string rel(const fs::path& p, const fs::path& root) { return fs::relative(p, root).generic_string(); }

// Remove the indentation common to all non-blank lines.
std::string dedent(const std::vector<std::string>& lines) {
    std::size_t common = std::string::npos;
    for (const auto& l : lines)
        if (l.find_first_not_of(" \t") != std::string::npos) common = std::min(common, l.find_first_not_of(" \t"));
    std::string out;
    for (const auto& l : lines) out += (l.size() > common ? l.substr(common) : std::string()) + "\n";
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 || (std::string(argv[1]) != "--check" && std::string(argv[1]) != "--update")) {
        std::cerr << "usage: snippets --check|--update <workbook root>\n";
        return 2;
    }
    const bool update = std::string(argv[1]) == "--update";
    const fs::path root = fs::absolute(argv[2]);
    std::vector<std::string> problems;

    // 1. Collect the named regions of the sources.
    std::vector<fs::path> sources, prose;
    for (const char* dir : {"exercises", "chapters", "tests", "cmake"}) {
        if (!fs::exists(root / dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
            const auto ext = e.path().extension();
            if (ext == ".hpp" || ext == ".cpp") sources.push_back(e.path());
            if (ext == ".md") prose.push_back(e.path());
        }
    }
    prose.push_back(root / "README.md");
    std::sort(sources.begin(), sources.end());
    std::sort(prose.begin(), prose.end());

    const std::regex begin_marker(R"(^\s*// snippet: ([A-Za-z0-9_]+)\s*$)");
    const std::regex end_marker(R"(^\s*// end snippet\s*$)");
    std::map<std::string, Snippet> snippets;
    for (const auto& p : sources) {
        if (p == fs::path(__FILE__)) continue;
        const auto lines = read_lines(p);
        std::string open;
        int open_line = 0;
        std::vector<std::string> body;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            std::smatch m;
            if (std::regex_match(lines[i], m, begin_marker)) {
                if (!open.empty()) problems.push_back(rel(p, root) + ":" + std::to_string(i + 1) + ": snippet '" + m[1].str() + "' opens inside '" + open + "'");
                open = m[1];
                open_line = static_cast<int>(i + 1);
                body.clear();
            } else if (std::regex_match(lines[i], end_marker)) {
                if (open.empty()) {
                    problems.push_back(rel(p, root) + ":" + std::to_string(i + 1) + ": 'end snippet' without a snippet");
                    continue;
                }
                if (snippets.count(open))
                    problems.push_back(rel(p, root) + ":" + std::to_string(open_line) + ": snippet '" + open + "' is also defined in " + snippets[open].file);
                snippets[open] = Snippet{rel(p, root), dedent(body), open_line, false};
                open.clear();
            } else if (!open.empty()) {
                body.push_back(lines[i]);
            }
        }
        if (!open.empty()) problems.push_back(rel(p, root) + ":" + std::to_string(open_line) + ": snippet '" + open + "' is never closed");
    }

    // 2. Check (or refresh) every quotation in the prose.
    const std::regex use_marker(R"(^<!-- snippet: ([A-Za-z0-9_]+) -->\s*$)");
    const std::regex use_end(R"(^<!-- end snippet -->\s*$)");
    int quoted = 0, stale = 0;
    for (const auto& p : prose) {
        if (!fs::exists(p)) continue;
        const auto lines = read_lines(p);
        std::vector<std::string> out;
        bool changed = false;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            std::smatch m;
            out.push_back(lines[i]);
            if (!std::regex_match(lines[i], m, use_marker)) continue;
            const std::string name = m[1];
            const std::string where = rel(p, root) + ":" + std::to_string(i + 1);
            std::size_t j = i + 1;
            while (j < lines.size() && !std::regex_match(lines[j], use_end)) ++j;
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
                else problems.push_back(where + ": snippet '" + name + "' differs from " + s->second.file + ":" + std::to_string(s->second.line) + " (run: cmake --build <build> --target update-snippets)");
            }
            std::istringstream w(update ? wanted : current);
            for (std::string l; std::getline(w, l);) out.push_back(l);
            out.push_back(lines[j]);
            i = j;
        }
        if (update && changed) {
            std::ofstream o(p);
            for (const auto& l : out) o << l << "\n";
            std::cout << "updated " << rel(p, root) << "\n";
        }
    }
    for (const auto& [name, s] : snippets)
        if (!s.used) problems.push_back(s.file + ":" + std::to_string(s.line) + ": snippet '" + name + "' is not quoted anywhere in the prose");

    std::cout << snippets.size() << " snippets in the sources, " << quoted << " quotations in the prose";
    if (update) std::cout << ", " << stale << " refreshed";
    std::cout << "\n";
    if (!problems.empty()) {
        for (const auto& p : problems) std::cout << "  " << p << "\n";
        return 1;
    }
    return 0;
}
