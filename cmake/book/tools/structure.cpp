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
//
// Each page is read as pandoc parses it (markdown.hpp): headings, lists, links, tables and the
// raw HTML of the <details> blocks are nodes of its document tree, not lines.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "book.hpp"
#include "markdown.hpp"
#include "prose.hpp"

namespace book {

namespace {

// What the lesson checks look for in a chapter's page, gathered in one pass over the blocks of
// its document tree (pandoc's): its level-2 headings, the bullets of two sections, the
// <details> blocks (raw HTML in the tree), and what the text, code included, names.
class LessonScan {
public:
    std::vector<std::string> h2s;  // every "## " heading, in order
    int bullets = 0;               // of Learning objectives, before **Time:**
    bool title = false, time_line = false, derivation = false, names_file = false, check_cmd = false, scene_cmd = false;
    int predicts = 0, predicts_with_command = 0;  // <details> blocks whose summary starts "Predict:"
    int key_points = 0;                           // bullets of Key points
    int checking_line = 0;                        // the line of the heading Checking [P]
    int headings_after = 0;                       // headings after it
    bool checking_link = false;                   // Checking [P] links checking.md

    void block(const md::Json& b) {
        if (md::is(b, "Header")) {
            const int level = b["c"][0].get<int>();
            if (level == 1) title = true;
            if (checking_line) ++headings_after;
            if (level != 2) return;
            h2s.push_back(md::text(b["c"][2]));
            if (h2s.back() == "Checking [P]") checking_line = md::line(b);
            return;
        }
        const std::string section = h2s.empty() ? "" : h2s.back();
        const std::string all = md::text(b, true);
        const auto names = [&](const char* what) { return all.find(what) != std::string::npos; };
        // A Predict block must name what to run: a shell block or a build/... command in it.
        if (in_predict_ && (names("build/") || names("cmake/workbook"))) predict_command_ = true;
        details(b);
        if (section == "Learning objectives") {
            if (!time_line && md::is(b, "BulletList")) bullets += static_cast<int>(b["c"].size());
            if (md::is(b, "Para") && !b["c"].empty() && md::is(b["c"][0], "Strong") &&
                md::text(b["c"][0]["c"]) == "Time:")
                time_line = true;
        }
        if (section == "Key points" && md::is(b, "BulletList")) key_points += static_cast<int>(b["c"].size());
        if (checking_line)
            md::walk(b, [&](const md::Json& n) {
                if (md::is(n, "Link") && n["c"][2][0].get<std::string>().rfind("checking.md", 0) == 0)
                    checking_link = true;
                return true;
            });
        if (section == "Exercises") derivation |= names("(derivation)"), names_file |= names("exercises/");
        if (section == "Check your work") check_cmd |= names("cmake/workbook check"), scene_cmd |= names("scenes/");
    }

private:
    // <details><summary>Predict: ...</summary> ... </details> (raw HTML in the tree), counted with
    // whether it names a command.
    void details(const md::Json& b) {
        std::string html;
        md::walk(b, [&](const md::Json& n) {
            html += md::raw_html(n);
            return true;
        });
        if (html.find("<details") != std::string::npos) in_details_ = true;
        if (in_details_ && html.find("<summary>") != std::string::npos) {
            const std::size_t at = html.find("<summary>") + 9;
            if (html.compare(at, 8, "Predict:") == 0 || html.compare(at, 10, "**Predict:") == 0) {
                in_predict_ = true;
                predict_command_ = false;
                ++predicts;
            }
        }
        if (html.find("</details>") != std::string::npos) {
            if (in_predict_ && predict_command_) ++predicts_with_command;
            in_details_ = in_predict_ = false;
        }
    }

    bool in_details_ = false, in_predict_ = false, predict_command_ = false;
};

// The non-blank source lines from `from` (1-based) to the end of the page.
int lines_after(const md::Page& page, int from) {
    int n = 0;
    for (std::size_t i = static_cast<std::size_t>(from); i < page.lines.size(); ++i)
        if (page.lines[i].find_first_not_of(" \t") != std::string::npos) ++n;
    return n;
}

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

// The lesson checks of one chapter (see the top of this file); appends to problems.
void check_lesson(const md::Page& page, const std::string& name, std::vector<std::string>& problems) {
    LessonScan s;
    for (const auto& b : page.blocks) s.block(b);
    const int checking_lines = s.checking_line ? lines_after(page, s.checking_line) - s.headings_after : 0;
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
    if (!s.title) problems.push_back(name + ": no '# Chapter N. Title' heading");
    if (!s.derivation) problems.push_back(name + ": its Exercises list no exercise marked '(derivation)'");
    if (s.key_points < 3 || s.key_points > 5)
        problems.push_back(name + ": its Key points have " + std::to_string(s.key_points) + " bullets; 3 to 5, please");
    if (checking_lines > 3)
        problems.push_back(name + ": its Checking [P] has " + std::to_string(checking_lines) +
                           " lines; keep at most 3 there, a pointer to checking.md, and the checks on that page");
    if (!s.checking_link) problems.push_back(name + ": its Checking [P] does not link checking.md");
    if (!fs::exists(page.file.parent_path() / "checking.md"))
        problems.push_back(name + ": the chapter has no checking.md (its own page for checking [P] and the errata)");
    if (!s.names_file)
        problems.push_back(name + ": its Exercises do not say where to work (no exercises/... file named)");
    if (!s.check_cmd) problems.push_back(name + ": its Check your work does not use 'cmake/workbook check'");
    if (!s.scene_cmd) problems.push_back(name + ": its Check your work names no scene command (build/.../scenes/...)");
}

// Whether the page has a link whose target starts with `target`.
bool links_to(const md::Page& page, const std::string& target) {
    bool found = false;
    md::walk(page.blocks, [&](const md::Json& n) {
        if (md::is(n, "Link") && n["c"][2][0].get<std::string>().rfind(target, 0) == 0) found = true;
        return !found;
    });
    return found;
}

// The notation page: its own page of the book, linked from the contents.
void check_notation(const fs::path& root, std::vector<std::string>& problems) {
    if (!fs::exists(root / "chapters" / "notation.md"))
        problems.push_back("chapters/notation.md: missing (the notation page of the book)");
    if (!fs::exists(root / "chapters" / "README.md") ||
        !links_to(md::read_page(root / "chapters" / "README.md"), "notation.md"))
        problems.push_back("chapters/README.md: does not link the notation page (notation.md)");
}

// One chapter's page: a title, the lesson checks, and (Chapter 1) a link to the notation page.
void check_chapter(const fs::path& root, const std::string& ch, std::vector<std::string>& problems) {
    const fs::path file = root / "chapters" / ch / "README.md";
    const std::string name = "chapters/" + ch + "/README.md";
    if (!fs::exists(file)) {
        problems.push_back(name + ": missing (chapters/README.md links it)");
        return;
    }
    const md::Page page = md::read_page(file);
    if (std::stoi(ch.substr(0, 2)) == 1 && !links_to(page, "../notation.md"))
        problems.push_back(name + ": does not link the notation page (../notation.md)");
    check_lesson(page, name, problems);
}

// How many cells a table row's source line has: pandoc pads a short row with empty cells, so the
// tree cannot tell a missing cell from an empty one. Split at each | that is not escaped (\|),
// as GitHub does (even in `code`).
std::size_t cells_written(const std::string& l) {
    if (l.empty() || l[0] != '|') return 0;
    std::vector<std::string> cells;
    const std::string body = l.substr(1, l.size() - 1 - (l.back() == '|' ? 1 : 0));
    std::string c;
    for (std::size_t k = 0; k <= body.size(); ++k) {
        if (k == body.size() || (body[k] == '|' && (k == 0 || body[k - 1] != '\\'))) {
            cells.push_back(c);
            c.clear();
        } else {
            c += body[k];
        }
    }
    return cells.size();
}

// One errata row: chapter, place in [P], what [P] prints, what the workbook uses, the numbers.
void check_errata_row(const std::vector<std::string>& cells, std::size_t written, const std::string& where,
                      const std::vector<std::string>& chapters, std::vector<std::string>& problems) {
    if (written != 5 || cells.size() != 5) {
        problems.push_back(where + ": an errata row has " + std::to_string(written) +
                           " cells; it needs 5 (chapter, where in [P], printed, corrected or qualified, evidence)");
        return;
    }
    // A chapter's number is the NN of its folder NN_slug, as in the contents.
    const std::string first = cells[0].substr(0, cells[0].find_first_not_of("0123456789"));
    bool known = false;
    std::string numbers;
    for (const auto& ch : chapters) {
        const std::string n = std::to_string(std::stoul(ch.substr(0, 2)));
        numbers += (numbers.empty() ? "" : ", ") + n;
        if (!first.empty() && std::to_string(std::stoul(first)) == n) known = true;
    }
    if (!known)
        problems.push_back(where + ": the first cell must name a chapter of the contents (" + numbers + "), not '" +
                           cells[0] + "'");
    for (std::size_t c = 1; c < 5; ++c)
        if (cells[c].empty()) problems.push_back(where + ": an errata row with an empty cell " + std::to_string(c + 1));
    if (cells[4].find_first_of("0123456789") == std::string::npos)
        problems.push_back(where + ": the evidence of an erratum gives numbers; this one has none");
}

// The text of each cell of a table row ([attr, cells]) and the row's line.
std::vector<std::string> row_cells(const md::Json& row, int& line) {
    std::vector<std::string> cells;
    for (const auto& cell : row[1]) {  // [attr, alignment, rows, columns, blocks]
        std::string t = md::text(cell[4]);
        t.erase(0, t.find_first_not_of(" \n"));
        t.erase(t.find_last_not_of(" \n") + 1);
        cells.push_back(t);
        md::walk(cell[4], [&](const md::Json& n) {
            line = std::max(line, md::line(n));
            return true;
        });
    }
    return cells;
}

// The errata list's table rows (the body rows of its tables); returns how many rows it checked.
int check_errata(const fs::path& root, const std::vector<std::string>& chapters, std::vector<std::string>& problems) {
    const fs::path errata = root / "chapters" / "errata.md";
    if (!fs::exists(errata)) return 0;
    const md::Page page = md::read_page(errata);
    int rows = 0;
    md::walk(page.blocks, [&](const md::Json& table) {
        if (!md::is(table, "Table")) return true;
        for (const auto& body : table["c"][4])  // [attr, row head columns, head rows, rows]
            for (const auto& row : body[3]) {
                int line = 0;
                const auto cells = row_cells(row, line);
                const std::size_t written = line > 0 && static_cast<std::size_t>(line) <= page.lines.size()
                                                ? cells_written(page.lines[line - 1])
                                                : cells.size();
                ++rows;
                check_errata_row(cells, written, "chapters/errata.md:" + std::to_string(line), chapters, problems);
            }
        return false;
    });
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
