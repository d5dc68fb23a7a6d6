// snippets --check-numbers: every number of the prose that looks measured says what it is, and
// every section of the workbook named by number is a link to it (see prose.hpp). Each page is
// read as pandoc parses it (markdown.hpp): its prose is the text of the tree's paragraphs,
// headings, lists and tables (math included; code, comments and link targets are not prose),
// its tags and value markers are the tree's raw HTML. Regular expressions find the numbers and
// the section numbers in that text (words, not Markdown); only a raw HTML block (a line that
// starts with a value marker is one) is read from its source lines, which is all the tree has.
#include <algorithm>
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

    // Prose text gathered from the tree between two things that are not prose (code, comments,
    // markers): its characters, the line of each, and whether each is a link's text.
    struct Text {
        std::string text;
        std::vector<int> line;
        std::vector<bool> in_link;
    };

    void file(const fs::path& p) {
        ++files_;
        page_ = md::read_page(p);
        name_ = rel(p, root_);
        manual_ = name_.rfind("chapters/", 0) != 0 && name_.rfind("exercises/", 0) != 0;
        pending_ = {};
        in_value_ = in_link_ = false;
        blocks(page_.blocks);
        flush();
        stale(pending_);
    }

    std::string where(int line) const { return name_ + ":" + std::to_string(line); }

    // A list of blocks; a tag covers numbers up to the next blank line (the end of its paragraph).
    void blocks(const md::Json& list) {
        for (const auto& b : list) {
            flush();  // a block's text is its own; a tag's count runs on to the paragraph's end
            const int at = md::line(b);
            if (at > 1 && static_cast<std::size_t>(at) <= page_.lines.size() &&
                page_.lines[static_cast<std::size_t>(at) - 2].find_first_not_of(" \t") == std::string::npos)
                stale(pending_);
            block(b);
        }
    }

    void block(const md::Json& b) {
        const std::string& t = md::type(b);
        const md::Json empty = md::Json::array();
        const md::Json& c = b.contains("c") ? b["c"] : empty;
        if (t == "Para" || t == "Plain") inlines(c);
        if (t == "Header") inlines(c[2]);
        if (t == "LineBlock")
            for (const auto& l : c) inlines(l);
        if (t == "CodeBlock" || t == "RawBlock") flush();
        if (t == "RawBlock") raw_block(b);
        if (t == "BlockQuote") blocks(c);
        if (t == "Div") blocks(c[1]);
        if (t == "BulletList" || t == "OrderedList")
            for (const auto& item : t == "BulletList" ? c : c[1]) blocks(item);
        if (t == "Table")
            md::walk(c, [&](const md::Json& n) {  // each cell's blocks, in order
                if (md::is(n, "Plain") || md::is(n, "Para")) flush(), inlines(n["c"]);
                return !(md::is(n, "Plain") || md::is(n, "Para"));
            });
    }

    void inlines(const md::Json& list) {
        for (const auto& n : list) inline_node(n);
    }

    void inline_node(const md::Json& n) {
        const std::string& t = md::type(n);
        if (in_value_) {  // a value marker's text is its run's, not prose
            if (md::raw_html(n).rfind("<!-- end value -->", 0) == 0) in_value_ = false;
            return;
        }
        if (t == "Str") add(n["c"].get<std::string>(), md::line(n));
        if (t == "Space" || t == "SoftBreak" || t == "LineBreak") add(" ", md::line(n));
        if (t == "Math") add("$" + n["c"][1].get<std::string>() + "$", md::line(n));
        if (t == "Code") flush();
        if (t == "RawInline") raw_inline(n);
        if (t == "Link") link(n);
        if (t == "Image" || t == "Span" || t == "Cite") inlines(n["c"][1]);
        if (t == "Emph" || t == "Strong" || t == "Strikeout" || t == "Underline" || t == "SmallCaps" ||
            t == "Superscript" || t == "Subscript")
            inlines(n["c"]);
        if (t == "Quoted") {
            add("\"", md::line(n));
            inlines(n["c"][1]);
            add("\"", md::line(n));
        }
        if (t == "Note") blocks(n["c"]);
    }

    void add(const std::string& s, int line) {
        text_.text += s;
        text_.line.insert(text_.line.end(), s.size(), line);
        text_.in_link.insert(text_.in_link.end(), s.size(), in_link_);
    }

    // An HTML comment inside a paragraph: a number tag, a value marker (whose text is skipped up
    // to its end), or another comment; none of it is prose.
    void raw_inline(const md::Json& n) {
        flush();
        const std::string html = md::raw_html(n);
        if (html.rfind("<!-- value:", 0) == 0) {
            ++markers_;
            if (html.find(" tol=") != std::string::npos) ++hand_;
            in_value_ = true;
            return;
        }
        for (const auto& tag : prose::find_number_tags(html)) open_tag(tag, where(md::line(n)), manual_, pending_);
    }

    // A link: a section it names by number must be the heading it leads to; its text is prose.
    void link(const md::Json& n) {
        static const std::regex section(R"((?:[Ss]ections?|§)\s*([0-9]+)\.([0-9]+))");
        const std::string text = md::text(n["c"][1]), target = n["c"][2][0].get<std::string>();
        std::smatch m;
        if (std::regex_search(text, m, section)) {
            const std::string want = "#" + m[1].str() + m[2].str() + "-";
            if (target.find(want) == std::string::npos)
                problems_.push_back(where(md::line(n)) + ": the link '[" + text + "](" + target + ")' names " +
                                    m.str() + " but does not lead to its heading (" + want + "...)");
        }
        in_link_ = true;
        inlines(n["c"][1]);
        in_link_ = false;
    }

    // The prose gathered so far: its numbers that look measured (each covered by a tag, or a
    // problem), and its sections named by number outside a link.
    void flush() {
        const Text t = std::move(text_);
        text_ = {};
        if (t.text.empty()) return;
        static const std::regex section(R"((?:[Ss]ections?|§)\s*[0-9]+\.[0-9]+)");
        for (auto it = std::sregex_iterator(t.text.begin(), t.text.end(), section); it != std::sregex_iterator(); ++it)
            if (!t.in_link[static_cast<std::size_t>(it->position(0))])
                problems_.push_back(where(t.line[static_cast<std::size_t>(it->position(0))]) + ": '" + it->str() +
                                    "' is not a link: write [" + it->str() +
                                    "](page.md#its-heading), which the book's render checks");
        for (const auto& number : prose::measured_numbers(t.text, std::vector<bool>(t.text.size(), false)))
            covered(number, where(t.line[number.begin]));
    }

    void covered(const prose::ProseNumber& number, const std::string& at) {
        if (pending_.left > 0)
            --pending_.left, ++tagged_, ++kinds_[pending_.kind];
        else
            problems_.push_back(at + ": " + number.text +
                                " looks measured: make it a value marker, or tag it "
                                "(<!--exact-->, <!--input-->, <!--const-->, <!--P-->)");
    }

    // A block of raw HTML (CommonMark's rule: a line that starts with "<!--" or a tag, e.g. a
    // value marker or <summary>). The tree has its source text only; read line by line as before
    // the tree: comments, markers, `code` and link targets masked, the rest prose.
    void raw_block(const md::Json& b) {
        const std::string html = b["c"][1].get<std::string>();
        if (md::starts_with_inline_marker(html))
            problems_.push_back(where(md::line(b)) +
                                ": starts with a value marker or a number tag: CommonMark (GitHub, pandoc) takes "
                                "the whole line for raw HTML, shows its math and emphasis as typed and breaks the "
                                "paragraph there; move the last word of the line before onto this one");
        std::istringstream lines(html);
        int at = md::line(b);
        bool in_comment = false;
        for (std::string line; std::getline(lines, line); ++at) {
            if (line.find_first_not_of(" \t") == std::string::npos) continue;
            auto skip = masked(line, in_comment);
            sections(line, skip, where(at));
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
            std::sort(events.begin(), events.end(), [](const Event& x, const Event& y) { return x.at < y.at; });
            for (const Event& e : events) {
                if (e.tag)
                    open_tag(*e.tag, where(at), manual_, pending_);
                else
                    covered(*e.number, where(at));
            }
        }
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
    md::Page page_;
    std::string name_;
    bool manual_ = false, in_value_ = false, in_link_ = false;
    Pending pending_;
    Text text_;
    std::vector<std::string> problems_;
    std::map<std::string, int> kinds_;
    int files_ = 0, markers_ = 0, hand_ = 0, tagged_ = 0;
};

}  // namespace

int check_numbers(const fs::path& root) { return NumberLint(root).run(); }

}  // namespace snippets
