// book --check-structure <root> --contents <contents.json>: chapters/notation.md exists and the
// contents and Chapter 1 link it. Every chapter is a lesson: it has, in this order, the sections
// "## Before you start", "## Learning objectives" (3-6 bullets, then a line starting "**Time:**"),
// "## Worked example", "## Exercises" (naming the exercises/ file and at least one exercise marked
// "(derivation)"), "## Check your work" (with `cmake/workbook check` and a scene command),
// "## Key points" (3-5 bullets: the objectives restated as facts), "## Going further" and, last,
// "## Checking [P]": a pointer of at most 3 lines to the chapter's own checking.md (which
// exists), where checking [P] and the chapter's errata live; and at least three <details> blocks
// whose <summary> starts with "Predict:", each naming a command to run. Every row of
// chapters/errata.md names a chapter and gives numbers.
#include <algorithm>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include "../prose.hpp"
#include "book.hpp"

namespace book {

namespace {

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

}  // namespace

int check_structure(const fs::path& root, const fs::path& contents) {
    std::vector<std::string> problems;
    const auto chapters = chapter_list(contents);
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

}  // namespace book
