// Renders the book: the chapters' README.md files, the contents, the errata and the hints, as
// HTML pages that work offline (pandoc, math as MathML, no script).
//
//   book --render <root> --runs <runs.txt> [--figures <dir>] --out <dir> [--pandoc <exe>]
//        [--label <text>] [--strict] --contents <contents.json>
//   book --check-structure <root> --contents <contents.json>
//   book --check-figures <root> <folder>...
//
// --contents: the table of contents, chapters/README.md, as CMake read it (cmake/contents.cmake
// writes <build>/contents.json): its chapters are the book's, in that order.
// --render: Pages: index.html (the contents),
// NN_slug.html per chapter, errata.html, hints.html, workbook.html (the top README), any
// other .md the pages link to, and code/<path>.html for each source file they link to.
// A value marker shows the value of its run (run=..., declared in <runs.txt>) from the report
// that run wrote into --figures (the folder of a `cmake/workbook run`, see prose.hpp), else
// from the committed report in <root>/figures (the same run's options, refreshed by the target
// update-figures; shown so, in its own style); never from a run with other options. Without
// either, the committed text stays, marked as not measured (--strict: an error). A value the
// run marks as not measured (null, -1, "not measured") is an error naming the key. Figures
// come from --figures, else from <root>/figures, and are copied next to the pages. Every link is mapped to its page,
// and must exist, fragment and all. Writes <out>/pages.txt for the browser test: file, kind, title per line.
//
// --check-figures: no source writes gnuplot's Symbol-font escape for a Greek letter, and every
// SVG under the folders names a font that has every character of its text (fontconfig).
//
// --check-structure: chapters/notation.md exists and the contents and Chapter 1 link it. Every
// chapter is a lesson: it has, in this order, the sections "## Before you start", "## Learning
// objectives" (3-6 bullets, then a line starting "**Time:**"), "## Worked example", "## Exercises"
// (naming the exercises/ file and at least one exercise marked "(derivation)"), "## Check your
// work" (with `cmake/workbook check` and a scene command), "## Key points" (3-5 bullets: the
// objectives restated as facts), "## Going further" and, last, "## Checking [P]": a pointer of
// at most 3 lines to the chapter's own checking.md (which exists), where checking [P] and the
// chapter's errata live; and at least three <details> blocks whose <summary> starts with
// "Predict:", each naming a command to run. Every row of chapters/errata.md names a chapter and
// gives numbers.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <deque>
#include <iostream>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "prose.hpp"

namespace fs = std::filesystem;
using prose::rel;

namespace {

std::string html_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

struct Output {
    int status;
    std::string text;
};

Output run(const std::string& command) {
    Output o{0, ""};
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return {-1, "cannot run: " + command};
    std::array<char, 4096> buf{};
    while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) o.text.append(buf.data(), n);
    const int status = pclose(pipe);
    o.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return o;
}

// The first "# Heading" of a markdown file, without markdown.
std::string first_heading(const fs::path& md) {
    bool in_fence = false;
    for (const auto& l : prose::read_lines(md)) {
        if (prose::is_fence(l)) in_fence = !in_fence;
        if (in_fence || l.rfind("# ", 0) != 0) continue;
        std::string t;
        for (char c : l.substr(2))
            if (c != '*' && c != '`' && c != '_') t += c;
        return t;
    }
    return md.stem().string();
}

// The table of contents as CMake read it from chapters/README.md (cmake/contents.cmake):
// <build>/contents.json, named by --contents.
fs::path contents_file;

// The chapters' folders, in the order of the table of contents.
std::vector<std::string> chapter_list(const fs::path& /*root*/) {
    if (contents_file.empty())
        throw std::runtime_error(
            "--contents <build>/contents.json is required (CMake writes it from chapters/README.md)");
    std::vector<std::string> out;
    const auto contents = prose::read_json(contents_file);
    for (const auto& c : contents.at("chapters")) out.push_back(c.at("folder").get<std::string>());
    return out;
}

// ------------------------------------------------------------------------------ structure

// What the lesson checks look for in a chapter's page, gathered in one pass over its lines
// (code blocks skipped, except that a Predict block or Check your work may name a command there).
class LessonScan {
public:
    std::vector<std::string> h2s;  // every "## " heading, in order
    int bullets = 0;               // of Learning objectives, before **Time:**
    bool time_line = false, derivation = false, names_file = false, check_cmd = false, scene_cmd = false;
    int predicts = 0, predicts_with_command = 0;  // <details> blocks whose summary starts "Predict:"
    int key_points = 0;                           // bullets of Key points
    int checking_lines = 0;                       // non-blank lines of Checking [P] and after it
    bool checking_link = false;                   // Checking [P] links checking.md

    void line(const std::string& l) {
        const std::string section = h2s.empty() ? "" : h2s.back();
        // A Predict block must name what to run: a shell block or a build/... command in it.
        if (in_predict_ && (l.find("build/") != std::string::npos || l.find("cmake/workbook") != std::string::npos))
            predict_command_ = true;
        if (section == "Check your work") {
            if (l.find("cmake/workbook check") != std::string::npos) check_cmd = true;
            if (l.find("scenes/") != std::string::npos) scene_cmd = true;
        }
        if (prose::is_fence(l)) in_fence_ = !in_fence_;
        if (in_fence_) return;
        if (l.rfind("## ", 0) == 0) {
            h2s.push_back(l.substr(3));
            return;
        }
        details(l);
        if (section == "Learning objectives") {
            if (!time_line && (l.rfind("* ", 0) == 0 || l.rfind("- ", 0) == 0)) ++bullets;
            if (l.rfind("**Time:**", 0) == 0) time_line = true;
        }
        if (section == "Key points" && (l.rfind("* ", 0) == 0 || l.rfind("- ", 0) == 0)) ++key_points;
        if (std::find(h2s.begin(), h2s.end(), "Checking [P]") != h2s.end() &&
            l.find_first_not_of(" \t") != std::string::npos) {
            ++checking_lines;
            if (l.find("](checking.md") != std::string::npos) checking_link = true;
        }
        if (section == "Exercises") {
            if (l.find("(derivation)") != std::string::npos) derivation = true;
            if (l.find("exercises/") != std::string::npos) names_file = true;
        }
    }

private:
    // <details><summary>Predict: ...</summary> ... </details>, counted with whether it names a command.
    void details(const std::string& l) {
        if (l.find("<details") != std::string::npos) in_details_ = true;
        if (in_details_ && l.find("<summary>") != std::string::npos) {
            const std::size_t at = l.find("<summary>") + 9;
            if (l.compare(at, 8, "Predict:") == 0 || l.compare(at, 10, "**Predict:") == 0) {
                in_predict_ = true;
                predict_command_ = false;
                ++predicts;
            }
        }
        if (l.find("</details>") != std::string::npos) {
            if (in_predict_ && predict_command_) ++predicts_with_command;
            in_details_ = in_predict_ = false;
        }
    }

    bool in_fence_ = false, in_details_ = false, in_predict_ = false, predict_command_ = false;
};

// Each required section present and in order, opening with Before you start, Learning objectives.
void check_lesson_order(const std::vector<std::string>& h2s, const std::string& name,
                        std::vector<std::string>& problems) {
    const std::vector<std::string> required = {"Before you start", "Learning objectives", "Worked example",
                                               "Exercises",        "Check your work",     "Key points",
                                               "Going further",    "Checking [P]"};
    std::size_t at = 0;
    for (const auto& h : required) {
        const auto it = std::find(h2s.begin(), h2s.end(), h);
        if (it == h2s.end()) {
            problems.push_back(name + ": has no '## " + h + "' section");
            continue;
        }
        const auto pos = static_cast<std::size_t>(it - h2s.begin());
        if (pos < at)
            problems.push_back(name + ": '## " + h +
                               "' comes too early (the order is: Before you start, "
                               "Learning objectives, ..., Worked example, ..., Exercises, Check your work, "
                               "Key points, Going further, Checking [P])");
        at = std::max(at, pos);
    }
    if (!h2s.empty() && std::find(h2s.begin(), h2s.end(), "Checking [P]") != h2s.end() && h2s.back() != "Checking [P]")
        problems.push_back(name + ": '## " + h2s.back() +
                           "' comes after '## Checking [P]', which is the page's last section (its errata and "
                           "checks of [P] belong on checking.md)");
    if (h2s.empty() || h2s.front() != "Before you start")
        problems.push_back(name + ": its first section is not '## Before you start'");
    else if (h2s.size() < 2 || h2s[1] != "Learning objectives")
        problems.push_back(name + ": '## Learning objectives' does not follow '## Before you start'");
}

// The lesson checks of one chapter (see --check-structure above); appends to problems.
void check_lesson(const fs::path& md, const std::string& name, std::vector<std::string>& problems) {
    LessonScan s;
    for (const auto& l : prose::read_lines(md)) s.line(l);
    check_lesson_order(s.h2s, name, problems);
    if (s.bullets < 3 || s.bullets > 6)
        problems.push_back(name + ": its Learning objectives have " + std::to_string(s.bullets) +
                           " bullets; 3 to 6, please");
    if (!s.time_line) problems.push_back(name + ": its Learning objectives have no line starting '**Time:**'");
    if (s.predicts < 3)
        problems.push_back(name + ": has " + std::to_string(s.predicts) +
                           " <details> blocks whose <summary> starts with 'Predict:'; a chapter needs at least 3");
    if (s.predicts_with_command < s.predicts)
        problems.push_back(name + ": " + std::to_string(s.predicts - s.predicts_with_command) +
                           " of its Predict: blocks name no command to run (a build/... or cmake/workbook line)");
    if (!s.derivation) problems.push_back(name + ": its Exercises list no exercise marked '(derivation)'");
    if (s.key_points < 3 || s.key_points > 5)
        problems.push_back(name + ": its Key points have " + std::to_string(s.key_points) + " bullets; 3 to 5, please");
    if (s.checking_lines > 3)
        problems.push_back(name + ": its Checking [P] has " + std::to_string(s.checking_lines) +
                           " lines; keep at most 3 there, a pointer to checking.md, and the checks on that page");
    if (!s.checking_link) problems.push_back(name + ": its Checking [P] does not link checking.md");
    if (!fs::exists(md.parent_path() / "checking.md"))
        problems.push_back(name + ": the chapter has no checking.md (its own page for checking [P] and the errata)");
    if (!s.names_file)
        problems.push_back(name + ": its Exercises do not say where to work (no exercises/... file named)");
    if (!s.check_cmd) problems.push_back(name + ": its Check your work does not use 'cmake/workbook check'");
    if (!s.scene_cmd) problems.push_back(name + ": its Check your work names no scene command (build/.../scenes/...)");
}

// Whether a line of the file links to `target` (a Markdown link "](target...").
bool links_to(const fs::path& file, const std::string& target) {
    for (const auto& l : prose::read_lines(file))
        if (l.find("](" + target) != std::string::npos) return true;
    return false;
}

// The notation page: its own page of the book, linked from the contents.
void check_notation(const fs::path& root, std::vector<std::string>& problems) {
    if (!fs::exists(root / "chapters" / "notation.md"))
        problems.push_back("chapters/notation.md: missing (the notation page of the book)");
    if (!links_to(root / "chapters" / "README.md", "notation.md"))
        problems.push_back("chapters/README.md: does not link the notation page (notation.md)");
}

// One chapter's page: a title, the lesson checks, and (Chapter 1) a link to the notation page.
void check_chapter(const fs::path& root, const std::string& ch, std::vector<std::string>& problems) {
    const fs::path md = root / "chapters" / ch / "README.md";
    const std::string name = "chapters/" + ch + "/README.md";
    if (!fs::exists(md)) {
        problems.push_back(name + ": missing (chapters/README.md links it)");
        return;
    }
    if (std::stoi(ch.substr(0, 2)) == 1 && !links_to(md, "../notation.md"))
        problems.push_back(name + ": does not link the notation page (../notation.md)");
    bool title = false;
    for (const auto& l : prose::read_lines(md))
        if (l.rfind("# ", 0) == 0) title = true;
    if (!title) problems.push_back(name + ": no '# Chapter N. Title' heading");
    check_lesson(md, name, problems);
}

// The cells of a Markdown table row, split at each | that is not escaped (\|), as GitHub does
// (even in `code`), trimmed.
std::vector<std::string> table_cells(const std::string& l) {
    std::vector<std::string> cells;
    const std::string body = l.substr(1, l.size() - 1 - (l.back() == '|' ? 1 : 0));
    std::string c;
    for (std::size_t k = 0; k <= body.size(); ++k) {
        if (k == body.size() || (body[k] == '|' && (k == 0 || body[k - 1] != '\\'))) {
            c.erase(0, c.find_first_not_of(' '));
            c.erase(c.find_last_not_of(' ') + 1);
            cells.push_back(c);
            c.clear();
        } else {
            c += body[k];
        }
    }
    return cells;
}

// One errata row: chapter, place in [P], what [P] prints, what the workbook uses, the numbers.
void check_errata_row(const std::vector<std::string>& cells, const std::string& where,
                      const std::vector<std::string>& chapters, std::vector<std::string>& problems) {
    if (cells.size() != 5) {
        problems.push_back(where + ": an errata row has " + std::to_string(cells.size()) +
                           " cells; it needs 5 (chapter, where in [P], printed, corrected or qualified, evidence)");
        return;
    }
    // A chapter's number is the NN of its folder NN_slug, as in the contents.
    static const std::regex chapter_cell(R"(^\[?([0-9]+)\]?.*)");
    std::smatch m;
    bool known = false;
    std::string numbers;
    for (const auto& ch : chapters) {
        const std::string n = std::to_string(std::stoul(ch.substr(0, 2)));
        numbers += (numbers.empty() ? "" : ", ") + n;
        if (std::regex_match(cells[0], m, chapter_cell) && m[1].str() == n) known = true;
    }
    if (!known)
        problems.push_back(where + ": the first cell must name a chapter of the contents (" + numbers + "), not '" +
                           cells[0] + "'");
    for (std::size_t c = 1; c < 5; ++c)
        if (cells[c].empty()) problems.push_back(where + ": an errata row with an empty cell " + std::to_string(c + 1));
    if (cells[4].find_first_of("0123456789") == std::string::npos)
        problems.push_back(where + ": the evidence of an erratum gives numbers; this one has none");
}

// The errata list's table rows; returns how many rows it checked.
int check_errata(const fs::path& root, const std::vector<std::string>& chapters, std::vector<std::string>& problems) {
    const fs::path errata = root / "chapters" / "errata.md";
    if (!fs::exists(errata)) return 0;
    int rows = 0, line_no = 0;
    bool in_table = false;
    for (const auto& l : prose::read_lines(errata)) {
        ++line_no;
        if (l.rfind("|", 0) != 0) {
            in_table = false;
            continue;
        }
        if (!in_table) {  // the header row, then the |---| row
            in_table = true;
            continue;
        }
        if (l.find("---") != std::string::npos && l.find_first_not_of("|-: ") == std::string::npos) continue;
        ++rows;
        check_errata_row(table_cells(l), "chapters/errata.md:" + std::to_string(line_no), chapters, problems);
    }
    return rows;
}

int check_structure(const fs::path& root) {
    std::vector<std::string> problems;
    const auto chapters = chapter_list(root);
    check_notation(root, problems);
    for (const auto& ch : chapters) check_chapter(root, ch, problems);
    const int rows = check_errata(root, chapters, problems);
    std::cout << chapters.size()
              << " chapters checked as lessons (objectives, worked example, predictions, a derivation, Check your "
                 "work, Key points, Going further, Checking [P] on its own page); the notation page; "
              << rows << " rows of chapters/errata.md checked\n";
    for (const auto& p : problems) std::cout << "  " << p << "\n";
    return problems.empty() ? 0 : 1;
}

// ------------------------------------------------------------------------------ figures

// The code points above ASCII in a UTF-8 text.
std::set<unsigned> non_ascii(const std::string& text) {
    std::set<unsigned> out;
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            ++i;
            continue;
        }
        const int n = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : 1;
        unsigned cp = c & (n == 3 ? 0x07 : n == 2 ? 0x0F : 0x1F);
        for (int k = 1; k <= n && i + k < text.size(); ++k)
            cp = (cp << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
        out.insert(cp);
        i += static_cast<std::size_t>(n) + 1;
    }
    return out;
}

// Greek and mathematical signs in the figures: the sources must write them as UTF-8, never with
// gnuplot's PostScript Symbol-font escape (a browser shows that as Latin letters: "W" for Ω),
// and every SVG must name, as the first of its font families, a font installed here that has
// every character its text uses (asked of fontconfig: fc-list). The checking tools themselves
// (cmake/tools/, cmake/book/) name the escape, and are not scanned.
// gnuplot's Symbol-font escape ({/Symbol w} for Ω), in the sources that draw figures. Returns how
// many sources it read.
int check_escapes(const fs::path& root, const std::string& escape, std::vector<std::string>& problems) {
    int sources = 0;
    for (const char* dir : {"chapters", "exercises", "tests", "figures", "cmake"}) {
        if (!fs::exists(root / dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
            if (!e.is_regular_file()) continue;
            const std::string r = rel(e.path(), root), ext = e.path().extension().string();
            if (r.rfind("cmake/tools/", 0) == 0 || r.rfind("cmake/book/", 0) == 0) continue;
            if (ext != ".cpp" && ext != ".hpp" && ext != ".gp" && ext != ".cmake" && ext != ".txt") continue;
            ++sources;
            const auto lines = prose::read_lines(e.path());
            for (std::size_t i = 0; i < lines.size(); ++i)
                if (lines[i].find(escape) != std::string::npos)
                    problems.push_back(
                        r + ":" + std::to_string(i + 1) + ": gnuplot's " + escape +
                        " ...} escape: write the letter in UTF-8 (Ω, α, ε), which every figure's font has");
        }
    }
    return sources;
}

// The text of an SVG's <text> elements, without their inner tags.
std::string svg_text(const std::string& svg) {
    static const std::regex text_element(R"(<text\b[^>]*>([\s\S]*?)</text>)");
    static const std::regex tag(R"(<[^>]*>)");
    std::string text;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text_element); it != std::sregex_iterator(); ++it)
        text += std::regex_replace((*it)[1].str(), tag, "") + "\n";
    return text;
}

// The first family of each font-family attribute of an SVG.
std::set<std::string> svg_families(const std::string& svg) {
    static const std::regex family_attr(R"#(font-family\s*=\s*["']([^"']*)["'])#");
    std::set<std::string> families;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), family_attr); it != std::sregex_iterator(); ++it) {
        std::string f = (*it)[1].str();
        f = f.substr(0, f.find(','));
        f.erase(0, f.find_first_not_of(" '\""));
        f.erase(f.find_last_not_of(" '\"") + 1);
        families.insert(f);
    }
    if (families.empty()) families.insert("(none named)");
    return families;
}

// Whether an installed font of a family has every character of a set, by fc-list, asked once per
// family and set.
class Fonts {
public:
    // False when fc-list itself is missing (a problem then says so).
    bool has(const std::string& family, const std::string& charset, bool& answered) {
        const std::string key = family + "|" + charset;
        answered = true;
        if (!covered_.count(key)) {
            if (!have_fc_) have_fc_ = run("fc-list --version").status == 0;
            if (!*have_fc_) return answered = false;
            const Output o =
                run("fc-list " + shell_quote(":family=" + family + (charset.empty() ? "" : ":charset=" + charset)) +
                    " family");
            covered_[key] = o.status == 0 && o.text.find_first_not_of(" \n") != std::string::npos;
        }
        return covered_[key];
    }

private:
    std::map<std::string, bool> covered_;  // "family|charset" -> fc-list says yes
    std::optional<bool> have_fc_;
};

// One SVG: no Symbol-font escape in its text, no text in the font Symbol, and every font it
// names installed with every character of its text. False when the fonts cannot be checked.
bool check_svg(const fs::path& path, const std::string& escape, Fonts& fonts, std::vector<std::string>& problems) {
    const std::string svg = prose::read_text(path), name = path.string();
    const std::string text = svg_text(svg);
    if (text.find(escape) != std::string::npos)
        problems.push_back(name + ": its text has gnuplot's " + escape + " ...} escape");
    std::string charset;
    for (unsigned c : non_ascii(text)) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "%x", c);
        charset += (charset.empty() ? "" : " ") + std::string(hex);
    }
    for (const auto& f : svg_families(svg)) {
        if (f == "Symbol") {  // where gnuplot's escape puts its letters: browsers show them as Latin ones
            problems.push_back(name + ": text in the font 'Symbol', as gnuplot's " + escape +
                               " ...} escape writes it (a browser shows Latin letters: W for Ω)");
            continue;
        }
        bool answered = false;
        const bool has = fonts.has(f, charset, answered);
        if (!answered) {
            problems.push_back("fc-list is not installed (Debian: fontconfig): cannot check the fonts of the figures");
            return false;
        }
        if (!has)
            problems.push_back(name + ": its text" + (charset.empty() ? "" : " uses U+" + charset + " and") +
                               " is in the font '" + f + "', which is not installed here" +
                               (charset.empty() ? "" : " with those characters") +
                               " (the figures use DejaVu Sans: Debian fonts-dejavu-core)");
    }
    return true;
}

int check_figures(const fs::path& root, const std::vector<fs::path>& trees) {
    std::vector<std::string> problems;
    const std::string escape = std::string("{/Sym") + "bol";
    const int sources = check_escapes(root, escape, problems);
    int svgs = 0;
    Fonts fonts;
    for (const auto& tree : trees) {
        if (!fs::exists(tree)) continue;
        for (const auto& e : fs::recursive_directory_iterator(tree)) {
            if (!e.is_regular_file() || e.path().extension() != ".svg") continue;
            ++svgs;
            if (!check_svg(e.path(), escape, fonts, problems)) {
                for (const auto& p : problems) std::cout << "  " << p << "\n";
                return 1;
            }
        }
    }
    std::cout << sources << " sources checked for the Symbol-font escape; " << svgs
              << " SVG figures checked for fonts that have their characters\n";
    for (const auto& p : problems) std::cout << "  " << p << "\n";
    return problems.empty() ? 0 : 1;
}

// ------------------------------------------------------------------------------ rendering

struct Page {
    std::string file;   // in the book: "01_pure_rotations.html", "code/exercises/rotation.cpp.html"
    fs::path source;    // the markdown or source file it comes from (absolute)
    std::string kind;   // contents | chapter | page | code
    std::string title;  // for <title> and the navigation
    int chapter = 0;    // 1.. for chapters
};

class Book {
public:
    Book(fs::path root, const fs::path& runs, fs::path figures, fs::path out, std::string pandoc, std::string label,
         bool strict)
        : root_(std::move(root)),
          runs_(runs),
          figures_(std::move(figures)),
          this_run_(figures_),
          committed_(root_ / "figures"),
          out_(std::move(out)),
          pandoc_(std::move(pandoc)),
          label_(std::move(label)),
          strict_(strict) {}

    int render();

private:
    std::string page_for(const fs::path& target);  // "" when not a page (yet)
    std::string map_link(const Page& page, const std::string& url, std::vector<std::string>& problems);
    std::string preprocess(const Page& page);
    std::string figure_html(const Page& page, const std::smatch& image, int figure);
    std::string value_html(const prose::ValueMarker& v);
    std::string hand_value_html(const prose::ValueMarker& v, const prose::Json* report);
    std::string numbers_html(std::string line, const std::string& where);
    std::string motion_html(const Page& page, const std::string& path, const std::string& fallback, int motion);
    std::string motion_block(const Page& page, const std::vector<std::string>& lines, std::size_t& i,
                             const std::string& path, int motion, const std::string& where);
    std::string rewrite_links(const Page& page, const std::string& html);
    void render_markdown(const Page& page, const Page* prev, const Page* next);
    void render_code(const Page& page);
    std::string pandoc_command(const Page& page, const fs::path& in, const fs::path& out, const std::string& from);
    std::size_t plan_pages(int& chapters);  // returns how many pages are in reading order
    void prepare_out();
    void render_pages(std::size_t reading_order);
    void check_fragments();
    void copy_viewer();
    int summary(int chapters);

    fs::path root_;
    prose::Runs runs_;
    fs::path figures_;
    prose::Reports this_run_, committed_;
    fs::path out_;
    std::string pandoc_, label_, book_title_;
    bool strict_;
    std::vector<Page> pages_;
    std::map<std::string, std::size_t> by_source_;  // repo path -> index in pages_
    std::map<std::string, prose::Snippet> snippets_;
    std::vector<std::string> problems_, notes_;
    std::vector<std::tuple<std::string, std::string, std::string, std::string>> fragments_;  // page, link, target, id
    std::vector<std::string> index_lines(const std::vector<std::string>& contents);
    bool own_run() const { return fs::weakly_canonical(figures_) != fs::weakly_canonical(root_ / "figures"); }
    int values_shown_ = 0, values_committed_ = 0, values_unmeasured_ = 0, figures_copied_ = 0;
    int page_values_ = 0, page_committed_ = 0, page_unmeasured_ = 0, page_motions_ = 0, motions_ = 0;
    std::map<std::string, int> unmeasured_by_scene_;  // runs without a report: values shown as committed
    std::map<std::string, int> committed_by_scene_;   // runs this build did not make: committed reports
};

// Path of `from` relative to the folder of the book page `page` ("" or "../").
std::string up_to_root(const std::string& page_file) {
    std::string up;
    for (char c : page_file)
        if (c == '/') up += "../";
    return up;
}

std::string Book::page_for(const fs::path& target) {
    const std::string key = rel(target, root_);
    const auto it = by_source_.find(key);
    if (it != by_source_.end()) return pages_[it->second].file;
    const auto ext = target.extension().string();
    const std::string name = target.filename().string();
    if (ext == ".md") {  // another page of prose: render it too
        std::string file = key.substr(0, key.size() - 3);
        std::replace(file.begin(), file.end(), '/', '-');
        pages_.push_back({file + ".html", target, "page", first_heading(target), 0});
    } else if (ext == ".hpp" || ext == ".cpp" || ext == ".h" || ext == ".cmake" || ext == ".gp" || ext == ".sh" ||
               name == "CMakeLists.txt" || key == "cmake/workbook" || key == ".ci/run") {
        pages_.push_back({"code/" + key + ".html", target, "code", key, 0});
    } else {
        return "";
    }
    by_source_[key] = pages_.size() - 1;
    return pages_.back().file;
}

// Maps a link of the prose (relative to its markdown file) to the book.
std::string Book::map_link(const Page& page, const std::string& url, std::vector<std::string>& problems) {
    if (!url.empty() && url[0] == '#') {  // an anchor of this page
        if (url.size() > 1) fragments_.emplace_back(page.file, url, page.file, url.substr(1));
        return url;
    }
    if (url.empty() || url.rfind("http://", 0) == 0 || url.rfind("https://", 0) == 0 || url.rfind("mailto:", 0) == 0 ||
        url.rfind("data:", 0) == 0)
        return url;
    const auto hash = url.find('#');
    const std::string path = url.substr(0, hash), fragment = hash == std::string::npos ? "" : url.substr(hash + 1);
    const fs::path target = (page.source.parent_path() / path).lexically_normal();
    const std::string key = rel(target, root_);
    const std::string up = up_to_root(page.file);
    if (key.rfind("..", 0) == 0) {
        problems.push_back("links outside the workbook: " + url);
        return url;
    }
    // A figure: from the build's figures, else the committed ones; copied next to the pages.
    if (key.rfind("figures/", 0) == 0 && fs::path(key).extension() != ".gp") {
        const fs::path built = figures_ / key.substr(8), committed = root_ / key;
        const fs::path from = fs::exists(built) ? built : committed;
        if (!fs::exists(from)) {
            problems.push_back("the figure " + key + " does not exist (run: cmake/workbook run)");
            return url;
        }
        if (from != built) notes_.push_back(key + ": not drawn by this build, the committed figure is shown");
        fs::create_directories((out_ / key).parent_path());
        fs::copy_file(from, out_ / key, fs::copy_options::overwrite_existing);
        ++figures_copied_;
        return up + key;
    }
    if (!fs::exists(target)) {
        problems.push_back("broken link: " + url + " (" + key + " does not exist)");
        return url;
    }
    if (fs::is_directory(target)) {
        problems.push_back("links to the folder " + key + "/: link a file in it instead");
        return url;
    }
    std::string file = page_for(target);
    if (file.empty()) {  // any other file: copied as it is
        file = "files/" + key;
        fs::create_directories((out_ / file).parent_path());
        fs::copy_file(target, out_ / file, fs::copy_options::overwrite_existing);
    }
    if (!fragment.empty()) fragments_.emplace_back(page.file, url, file, fragment);
    return up + file + (fragment.empty() ? "" : "#" + fragment);
}

// The markdown pandoc sees: snippets named after their source, values of this build, and
// figures with numbered captions.
// A figure: numbered in its chapter, with its caption; one this build should have drawn but did
// not shows the committed one, and says so.
std::string Book::figure_html(const Page& page, const std::smatch& m, int figure) {
    const std::string number =
        page.chapter ? std::to_string(page.chapter) + "." + std::to_string(figure) : std::to_string(figure);
    const std::string key = rel((page.source.parent_path() / m[2].str()).lexically_normal(), root_);
    std::string whose;
    if (key.rfind("figures/", 0) == 0 && own_run() && !fs::exists(figures_ / key.substr(8)))
        whose = " <em>(The committed figure: this build has not drawn it.)</em>";
    return "<figure id=\"figure-" + number + "\">\n<img src=\"" + html_escape(m[2]) + "\" alt=\"" + html_escape(m[1]) +
           "\">\n<figcaption><strong>Figure " + number + ".</strong> " + html_escape(m[1]) + whose +
           "</figcaption>\n</figure>\n";
}

// A motion for the viewer (cmake/book/motion_viewer.js): the JSON a scene wrote with --motion FILE,
// from this build's figures, else the committed ones (like a figure), put into the page with its
// caption (the scene, its parameters, its error) and its still picture for a reader without
// WebGL (the image line that follows the marker in the prose; GitHub shows only that).
std::string Book::motion_html(const Page& page, const std::string& path, const std::string& fallback, int motion) {
    const std::string number =
        page.chapter ? std::to_string(page.chapter) + "." + std::to_string(motion) : std::to_string(motion);
    const std::string key = rel((page.source.parent_path() / path).lexically_normal(), root_);
    if (key.rfind("figures/", 0) != 0 || fs::path(key).extension() != ".json")
        throw std::runtime_error("a motion is a scene's JSON under figures/, not " + key);
    const fs::path built = figures_ / key.substr(8), committed = root_ / key;
    const fs::path from = fs::exists(built) ? built : committed;
    if (!fs::exists(from)) throw std::runtime_error("the motion " + key + " does not exist (run: cmake/workbook run)");
    if (from != built) notes_.push_back(key + ": not written by this build, the committed motion is shown");
    const auto data = prose::read_json(from);
    for (const char* field : {"scene", "title", "parameters", "error", "error_measure", "t", "R", "body"})
        if (!data.contains(field)) throw std::runtime_error("the motion " + key + " has no '" + field + "'");
    if (!data["error"].is_number() || !std::isfinite(data["error"].get<double>()))
        throw std::runtime_error("the motion " + key + " reports no error (not measured)");
    std::string json = data.dump();  // a script's text ends at "</": write it "<\/"
    for (std::size_t p = 0; (p = json.find("</", p)) != std::string::npos; p += 3) json.replace(p, 2, "<\\/");
    ++page_motions_, ++motions_;
    std::string html = "<figure class=\"motion\" id=\"motion-" + number + "\">\n";
    if (!fallback.empty())
        html += "<img class=\"motion-fallback\" src=\"" + html_escape(fallback) + "\" alt=\"" +
                html_escape(data["title"].get<std::string>()) + "\">\n";
    html += "<script type=\"application/json\" class=\"motion-data\">" + json + "</script>\n";
    html += "<figcaption><strong>Motion " + number + ".</strong> " + html_escape(data["title"].get<std::string>()) +
            ". Scene <code>" + html_escape(data["scene"].get<std::string>()) +
            "</code>: " + html_escape(data["parameters"].get<std::string>()) + "; error " +
            html_escape(prose::sci(data["error"].get<double>(), 2)) + " (" +
            html_escape(data["error_measure"].get<std::string>()) + ").";
    if (from != built) html += " <em>(The committed motion: this build has not written it.)</em>";
    return html + "</figcaption>\n</figure>\n";
}

// A motion marker at lines[i], and the image line after it (the GIF that GitHub shows), which it
// takes as the viewer's still picture.
std::string Book::motion_block(const Page& page, const std::vector<std::string>& lines, std::size_t& i,
                               const std::string& path, int motion, const std::string& where) {
    static const std::regex image(R"(^!\[([^\]]*)\]\(([^)\s]+)\)\s*$)");
    std::smatch m;
    std::string fallback;
    if (i + 1 < lines.size() && std::regex_match(lines[i + 1], m, image)) fallback = m[2], ++i;
    try {
        return motion_html(page, path, fallback, motion);
    } catch (const std::exception& e) {
        problems_.push_back(where + ": " + e.what());
        return "";
    }
}

// A value, from this build's report of its run, else from the committed report of the same run,
// else the text committed with the prose, marked as not measured. Throws what is wrong.
std::string Book::value_html(const prose::ValueMarker& v) {
    const std::string scene = v.scene(), run_key = scene + " (run " + v.run + ")";
    std::string shown;
    const prose::RunDecl* d = runs_.find(scene, v.run);
    if (!d)
        throw std::runtime_error("the scene " + scene + " has no run '" + v.run + "' (declared: " + runs_.names(scene) +
                                 ")");
    // This build's own report of the run; a report made with other options is never read.
    const prose::Json* report = nullptr;
    if (own_run()) {
        try {
            report = this_run_.report(*d);
        } catch (const std::exception& e) {
            notes_.push_back(e.what());
        }
    }
    ++page_values_;
    if (v.tol >= 0) return hand_value_html(v, report ? report : committed_.report(*d));
    if (report) {
        ++values_shown_;
        shown = "<span class=\"value\" title=\"" + html_escape(v.path) + ", run " + v.run +
                ", measured by this build\">" + html_escape(prose::resolve(v, *report)) + "</span>";
    } else if (const prose::Json* c = committed_.report(*d)) {
        const std::string text = prose::resolve(v, *c);
        if (own_run()) {
            ++values_committed_, ++page_committed_;
            ++committed_by_scene_[run_key];
            shown = "<span class=\"value committed\" title=\"" + html_escape(v.path) + ", run " + v.run +
                    ": not run by this build; from the committed report of the same run\">" + html_escape(text) +
                    "</span>";
        } else {
            ++values_shown_;
            shown = "<span class=\"value\" title=\"" + html_escape(v.path) + ", run " + v.run +
                    ", from the committed report\">" + html_escape(text) + "</span>";
        }
    } else {
        ++values_unmeasured_;
        ++page_unmeasured_;
        ++unmeasured_by_scene_[run_key];
        shown = "<span class=\"value unmeasured\" title=\"" + html_escape(v.path) + ", run " + v.run +
                ": no report of this run; the text committed with the prose\">" + v.text + "</span>";
    }
    return shown;
}

// A value typed by hand (tol=): its own text, checked against the report the book reads.
std::string Book::hand_value_html(const prose::ValueMarker& v, const prose::Json* report) {
    if (!report) throw std::runtime_error("a hand value with no report of its run to check it against");
    const std::string off = prose::hand_value_problem(v, *report);
    if (!off.empty()) throw std::runtime_error(off);
    ++values_shown_;
    prose::ValueMarker exact = v;
    exact.fmt = "%.6g";
    return "<span class=\"value hand\" title=\"" + html_escape(v.path) + ", run " + v.run +
           ": typed by hand; the run gives " + html_escape(prose::resolve(exact, *report)) + "\">" + v.text + "</span>";
}

std::string Book::preprocess(const Page& page) {
    auto lines = prose::read_lines(page.source);
    page_values_ = page_committed_ = page_unmeasured_ = page_motions_ = 0;
    if (page.kind == "contents") lines = index_lines(lines);
    const std::regex image(R"(^!\[([^\]]*)\]\(([^)\s]+)\)\s*$)");
    const std::regex motion_marker(R"(^<!-- motion: (\S+) -->\s*$)");
    std::string md;
    bool in_fence = false;
    int figure = 0, motion = 0;
    const std::string where0 = rel(page.source, root_);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        std::string line = lines[i];
        const std::string where = where0 + ":" + std::to_string(i + 1);
        if (prose::is_fence(line)) in_fence = !in_fence;
        if (in_fence || prose::is_fence(line)) {
            md += line + "\n";
            continue;
        }
        std::smatch m;
        if (std::regex_match(line, m, prose::snippet_use_marker())) {
            const auto s = snippets_.find(m[1]);
            if (s == snippets_.end()) {
                problems_.push_back(where + ": no source defines snippet '" + m[1].str() + "'");
                continue;
            }
            const std::string link = fs::relative(root_ / s->second.file, page.source.parent_path()).generic_string();
            md += "<p class=\"snippet-source\">From <a href=\"" + link + "#src-" + std::to_string(s->second.line + 1) +
                  "\"><code>" + html_escape(s->second.file) + "</code></a></p>\n\n";
            continue;
        }
        if (std::regex_match(line, prose::snippet_use_end())) continue;
        if (std::regex_match(line, m, motion_marker)) {
            md += motion_block(page, lines, i, m[1], ++motion, where);
            continue;
        }
        if (std::regex_match(line, m, image)) {
            md += figure_html(page, m, ++figure);
            continue;
        }
        md += numbers_html(line, where) + "\n";
    }
    return md;
}

// One line of prose with its numbers as the reader sees them: each value marker replaced by its
// value (problems noted), and the number tags (<!--exact--> ...) dropped: they are for the check of
// numbers, and at the start of a line pandoc would take one for an HTML block and leave the line's
// math as text.
std::string Book::numbers_html(std::string line, const std::string& where) {
    const auto tags = prose::find_number_tags(line);
    for (auto t = tags.rbegin(); t != tags.rend(); ++t) line.erase(t->begin, t->end - t->begin);
    auto markers = prose::find_value_markers(line);
    for (auto v = markers.rbegin(); v != markers.rend(); ++v) {
        if (!v->error.empty()) {
            problems_.push_back(where + ": value '" + v->path + "': " + v->error);
            continue;
        }
        try {
            line.replace(v->begin, v->end - v->begin, value_html(*v));
        } catch (const std::exception& e) {
            problems_.push_back(where + ": value '" + v->path + "': " + e.what());
        }
    }
    return line;
}

// The contents page opens the book: its title, the first paragraph of the top README (what
// the book is about), a pointer to how to use it, then chapters/README.md under "Contents".
std::vector<std::string> Book::index_lines(const std::vector<std::string>& contents) {
    std::vector<std::string> out{"# " + book_title_, ""};
    const auto top = prose::read_lines(root_ / "README.md");
    std::size_t i = 0;
    while (i < top.size() && top[i].rfind("# ", 0) != 0) ++i;
    ++i;
    while (i < top.size() && top[i].empty()) ++i;
    const std::regex link(R"(\[([^\]]*)\]\([^)]*\))");  // its links point elsewhere: keep their words
    std::string lead;
    for (; i < top.size() && !top[i].empty() && top[i].rfind("#", 0) != 0; ++i)
        lead += std::regex_replace(top[i], link, "$1") + "\n";
    if (!lead.empty()) out.push_back("<div class=\"lead\">\n\n" + lead + "\n</div>\n");
    out.push_back(
        "New here? [Using the workbook](../README.md) has the two commands that build, run and test it, "
        "and how students, self-learners and instructors work with it.");
    out.push_back("");
    bool title_done = false;
    for (const auto& l : contents) {
        if (!title_done && l.rfind("# ", 0) == 0) {
            out.push_back("#" + l);  // "# Contents" becomes a section of the opening page
            title_done = true;
        } else {
            out.push_back(l);
        }
    }
    return out;
}

// MathML that browsers draw better: pandoc writes the dot and double dot accents (\dot R,
// \ddot R) as combining characters, which Chromium places badly; the spacing accents sit right.
std::string better_accents(std::string html) {
    const std::pair<std::string, std::string> swaps[] = {
        {"<mo accent=\"true\">\u0307</mo>", "<mo accent=\"true\">\u02D9</mo>"},
        {"<mo accent=\"true\">\u0308</mo>", "<mo accent=\"true\">\u00A8</mo>"},
    };
    for (const auto& [from, to] : swaps) {
        std::string out;
        std::size_t last = 0;
        for (std::size_t p; (p = html.find(from, last)) != std::string::npos; last = p + from.size())
            out += html.substr(last, p - last) + to;
        html = out + html.substr(last);
    }
    return html;
}

std::string Book::rewrite_links(const Page& page, const std::string& html) {
    // Only the page's own content: the template's navigation is already in book terms.
    const auto begin = html.find("<main>"), end = html.rfind("</main>");
    if (begin == std::string::npos || end == std::string::npos) {
        problems_.push_back(page.file + ": the page template lost its <main>");
        return html;
    }
    const std::string body = html.substr(begin, end - begin);
    const std::regex attr(R"#(\b(href|src)="([^"]*)")#");
    std::string out;
    std::size_t last = 0;
    std::vector<std::string> problems;
    for (auto it = std::sregex_iterator(body.begin(), body.end(), attr); it != std::sregex_iterator(); ++it) {
        const auto& m = *it;
        out += body.substr(last, static_cast<std::size_t>(m.position(0)) - last);
        std::string url;  // pandoc writes & as &amp; in attributes
        const std::string raw = m[2];
        for (std::size_t k = 0; k < raw.size(); ++k) {
            url += raw[k];
            if (raw.compare(k, 5, "&amp;") == 0) k += 4;
        }
        out += m[1].str() + "=\"" + html_escape(map_link(page, url, problems)) + "\"";
        last = static_cast<std::size_t>(m.position(0) + m.length(0));
    }
    out += body.substr(last);
    for (const auto& p : problems) problems_.push_back(rel(page.source, root_) + ": " + p);
    return html.substr(0, begin) + out + html.substr(end);
}

std::string Book::pandoc_command(const Page& page, const fs::path& in, const fs::path& out, const std::string& from) {
    const std::string up = up_to_root(page.file);
    std::string cmd = shell_quote(pandoc_) + " --from=" + from + " --to=html5 --mathml --standalone" +
                      " --template=" + shell_quote((root_ / "cmake" / "book" / "page.html").string()) +
                      " --metadata=pagetitle:" + shell_quote(page.title + " | " + book_title_) +
                      " --variable=root:" + shell_quote(up) +
                      " --variable=book-title:" + shell_quote(html_escape(book_title_)) +
                      " --variable=page-kind:" + page.kind +
                      " --variable=page-id:" + shell_quote(fs::path(page.file).stem().string()) +
                      " --variable=source:" + shell_quote(html_escape(rel(page.source, root_))) +
                      (page_values_ ? " --variable=label:" + shell_quote(html_escape(label_)) : std::string()) +
                      (page_committed_ ? " --variable=committed:yes" : std::string()) +
                      (page_unmeasured_ ? " --variable=unmeasured:yes" : std::string()) +
                      (page_motions_ ? " --variable=motion:yes" : std::string());
    if (page.kind == "chapter") cmd += " --toc --toc-depth=3";
    return cmd + " --output=" + shell_quote(out.string()) + " " + shell_quote(in.string());
}

void Book::render_markdown(const Page& page, const Page* prev, const Page* next) {
    const fs::path tmp = out_ / ".work" / (page.file + ".md");
    prose::write_text(tmp, preprocess(page));
    std::string cmd = pandoc_command(page, tmp, out_ / ".work" / page.file, "gfm+tex_math_dollars+smart");
    auto nav = [&](const std::string& name, const Page* p) {
        if (p)
            cmd += " --variable=" + name + "-url:" + shell_quote(up_to_root(page.file) + p->file) +
                   " --variable=" + name + "-title:" + shell_quote(html_escape(p->title));
    };
    nav("prev", prev);
    nav("next", next);
    const Output o = run(cmd);
    if (o.status != 0) {
        problems_.push_back(rel(page.source, root_) + ": pandoc failed (" + std::to_string(o.status) + "): " + o.text);
        return;
    }
    // pandoc renders math it cannot convert to MathML as TeX, with a warning: that is an error here.
    std::istringstream warnings(o.text);
    for (std::string w; std::getline(warnings, w);)
        if (!w.empty()) problems_.push_back(rel(page.source, root_) + ": pandoc: " + w);
    prose::write_text(out_ / page.file,
                      better_accents(rewrite_links(page, prose::read_text(out_ / ".work" / page.file))));
}

void Book::render_code(const Page& page) {
    page_values_ = page_committed_ = page_unmeasured_ = page_motions_ = 0;
    const std::string text = prose::read_text(page.source);
    std::size_t longest = 2, run_len = 0;
    for (char c : text) {
        run_len = c == '`' ? run_len + 1 : 0;
        longest = std::max(longest, run_len);
    }
    const std::string fence(longest + 1, '`');
    const std::string name = page.source.filename().string(), ext = page.source.extension().string();
    std::string lang = "default";
    if (ext == ".cpp" || ext == ".hpp" || ext == ".h")
        lang = "cpp";
    else if (ext == ".cmake" || name == "CMakeLists.txt")
        lang = "cmake";
    else if (ext == ".sh" || name == "workbook" || name == "run")
        lang = "bash";
    std::string md = "# " + page.title + "\n\nThe file `" + page.title +
                     "` as it is in the workbook's repository.\n\n" + fence + " {#src ." + lang + " .numberLines}\n" +
                     text + (text.empty() || text.back() == '\n' ? "" : "\n") + fence + "\n";
    const fs::path tmp = out_ / ".work" / (page.file + ".md");
    prose::write_text(tmp, md);
    fs::create_directories((out_ / page.file).parent_path());
    const Output o = run(pandoc_command(page, tmp, out_ / page.file, "markdown-tex_math_dollars"));
    if (o.status != 0) problems_.push_back(page.title + ": pandoc failed: " + o.text);
}

// The fixed pages and the reading order: contents, chapters, errata, hints; then the top README.
std::size_t Book::plan_pages(int& chapters) {
    pages_.push_back({"index.html", root_ / "chapters" / "README.md", "contents", "Contents", 0});
    chapters = 0;
    for (const auto& ch : chapter_list(root_)) {
        const fs::path md = root_ / "chapters" / ch / "README.md";
        if (!fs::exists(md)) {
            problems_.push_back("chapters/README.md links " + ch + "/README.md, which does not exist");
            continue;
        }
        // The chapter's number is the NN of its folder, as in the contents (not its place in the list:
        // a chapter in preparation leaves a gap, and Chapter 8's figures are still 8.x).
        ++chapters;
        pages_.push_back({ch + ".html", md, "chapter", first_heading(md), std::stoi(ch.substr(0, 2))});
    }
    for (const auto& [file, src] : {std::pair<std::string, std::string>{"errata.html", "chapters/errata.md"},
                                    {"hints.html", "exercises/hints.md"}}) {
        if (fs::exists(root_ / src)) pages_.push_back({file, root_ / src, "page", first_heading(root_ / src), 0});
    }
    const std::size_t reading_order = pages_.size();
    pages_.push_back({"workbook.html", root_ / "README.md", "page", "How to use the workbook", 0});
    for (std::size_t i = 0; i < pages_.size(); ++i) by_source_[rel(pages_[i].source, root_)] = i;
    return reading_order;
}

// Starts from an empty folder, so that no page of an earlier render survives; pandoc must run.
void Book::prepare_out() {
    if (fs::exists(out_)) {
        if (!fs::is_directory(out_) || (!fs::is_empty(out_) && !fs::exists(out_ / "pages.txt")))
            throw std::runtime_error(out_.string() + " exists and is not a book rendered before: not touching it");
        fs::remove_all(out_);
    }
    fs::create_directories(out_);
    if (const Output v = run(shell_quote(pandoc_) + " --version"); v.status != 0)
        throw std::runtime_error("cannot run pandoc ('" + pandoc_ +
                                 "'): install it with sudo apt-get install pandoc, "
                                 "or run cmake/workbook, which does");
    fs::copy_file(root_ / "cmake" / "book" / "book.css", out_ / "book.css", fs::copy_options::overwrite_existing);
}

// The motion viewer of the pages that show a motion: its script, and three.js from Debian's
// libjs-three (r111), copied into the book so that it works offline.
void Book::copy_viewer() {
    if (!motions_) return;
    const fs::path three = "/usr/share/javascript/three/three.min.js";
    if (!fs::exists(three)) {
        problems_.push_back(std::to_string(motions_) + " motion(s) need three.js: " + three.string() +
                            " is missing (Debian: sudo apt-get install libjs-three; cmake/workbook installs it)");
        return;
    }
    fs::copy_file(three, out_ / "three.min.js", fs::copy_options::overwrite_existing);
    fs::copy_file(root_ / "cmake" / "book" / "motion_viewer.js", out_ / "motion_viewer.js",
                  fs::copy_options::overwrite_existing);
}

// Every page; pages found through links are appended while we go.
void Book::render_pages(std::size_t reading_order) {
    for (std::size_t i = 0; i < pages_.size(); ++i) {
        const Page page = pages_[i];
        if (page.kind == "code") {
            render_code(page);
            continue;
        }
        // Previous and next in reading order; the last page and the pages outside it lead
        // back to the contents.
        const Page* prev = i > 0 && i < reading_order ? &pages_[i - 1] : nullptr;
        const Page* next = i + 1 < reading_order ? &pages_[i + 1] : (i > 0 ? &pages_[0] : nullptr);
        const Page prev_copy = prev ? *prev : Page{}, next_copy = next ? *next : Page{};
        render_markdown(page, prev ? &prev_copy : nullptr, next ? &next_copy : nullptr);
    }
}

// Every link into a page must find its anchor there.
void Book::check_fragments() {
    std::map<std::string, std::set<std::string>> ids;
    const std::regex id_attr(R"#(\bid="([^"]+)")#");
    for (const auto& [from, url, file, id] : fragments_) {
        if (!ids.count(file)) {
            const std::string html = fs::exists(out_ / file) ? prose::read_text(out_ / file) : "";
            auto& s = ids[file];
            for (auto it = std::sregex_iterator(html.begin(), html.end(), id_attr); it != std::sregex_iterator(); ++it)
                s.insert((*it)[1]);
        }
        if (!ids[file].count(id))
            problems_.push_back(from + ": the link " + url + " names #" + id + ", which " + file + " does not have");
    }
}

// pages.txt for the browser test, and what was rendered, with every note and problem.
int Book::summary(int chapters) {
    for (const auto& [what, count] : unmeasured_by_scene_)
        (strict_ ? problems_ : notes_)
            .push_back("no report of " + what + " in " + figures_.string() +
                       " or the committed figures: " + std::to_string(count) +
                       " value(s) show the text committed with the prose, marked as not measured");
    for (const auto& [what, count] : committed_by_scene_)
        notes_.push_back("this build did not run " + what + ": " + std::to_string(count) +
                         " value(s) from its committed report (same options), marked so");
    std::string list;
    for (const auto& p : pages_) list += p.file + "\t" + p.kind + "\t" + p.title + "\n";
    prose::write_text(out_ / "pages.txt", list);
    fs::remove_all(out_ / ".work");
    std::cout << "book: " << pages_.size() << " pages (" << chapters << " chapters), " << figures_copied_
              << " figures, " << motions_ << " motions, " << values_shown_ << " values from "
              << (own_run() ? figures_.string() : "the committed reports");
    if (values_committed_) std::cout << ", " << values_committed_ << " from the committed reports";
    if (values_unmeasured_) std::cout << ", " << values_unmeasured_ << " not measured";
    std::cout << "\n      " << (out_ / "index.html").string() << "\n";
    for (const auto& note : notes_) std::cout << "  note: " << note << "\n";
    for (const auto& p : problems_) std::cout << "  " << p << "\n";
    return problems_.empty() ? 0 : 1;
}

int Book::render() {
    std::vector<std::string> problems;
    snippets_ = prose::collect_snippets(root_, prose::scan_tree(root_).sources, problems);
    for (const auto& p : problems) problems_.push_back(p);
    book_title_ = first_heading(root_ / "README.md");
    if (!label_.empty()) {
        char when[64];
        const std::time_t now = std::time(nullptr);
        std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
        label_ += ", " + std::string(when);
    }
    int chapters = 0;
    const std::size_t reading_order = plan_pages(chapters);
    prepare_out();
    render_pages(reading_order);
    check_fragments();
    copy_viewer();
    return summary(chapters);
}

int usage() {
    std::cerr << "usage: book --render <root> --runs <runs.txt> [--figures <dir>] --out <dir> [--pandoc <exe>] "
                 "[--label <text>]\n"
                 "            [--strict] --contents <contents.json>\n"
                 "       book --check-structure <root> --contents <contents.json>\n"
                 "       book --check-figures <root> <folder of SVG figures>...\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    // --contents <file>, before or after the mode: the table of contents for every mode.
    for (std::size_t i = 0; i + 1 < args.size(); ++i)
        if (args[i] == "--contents") {
            contents_file = fs::absolute(args[i + 1]);
            args.erase(args.begin() + static_cast<std::ptrdiff_t>(i),
                       args.begin() + static_cast<std::ptrdiff_t>(i) + 2);
            break;
        }
    try {
        if (args.size() == 2 && args[0] == "--check-structure") return check_structure(fs::absolute(args[1]));
        if (args.size() >= 2 && args[0] == "--check-figures") {
            std::vector<fs::path> trees;
            for (std::size_t i = 2; i < args.size(); ++i) trees.push_back(fs::absolute(args[i]));
            return check_figures(fs::absolute(args[1]), trees);
        }
        if (args.size() < 2 || args[0] != "--render") return usage();
        std::map<std::string, std::string> opt{{"--pandoc", "pandoc"}};
        bool strict = false;
        for (std::size_t i = 2; i < args.size(); ++i) {
            if (args[i] == "--strict") {
                strict = true;
            } else if (i + 1 < args.size() && (args[i] == "--runs" || args[i] == "--figures" || args[i] == "--out" ||
                                               args[i] == "--pandoc" || args[i] == "--label")) {
                opt[args[i]] = args[i + 1];
                ++i;
            } else {
                std::cerr << "book: unknown or incomplete option '" << args[i] << "'\n";
                return usage();
            }
        }
        for (const char* need : {"--runs", "--out"})
            if (!opt.count(need)) {
                std::cerr << "book: " << need << " is required\n";
                return usage();
            }
        const fs::path root = fs::absolute(args[1]);
        Book book(root, fs::absolute(opt["--runs"]),
                  opt.count("--figures") ? fs::absolute(opt["--figures"]) : root / "figures",
                  fs::absolute(opt["--out"]), opt["--pandoc"], opt["--label"], strict);
        return book.render();
    } catch (const std::exception& e) {
        std::cerr << "book: " << e.what() << "\n";
        return 1;
    }
}
