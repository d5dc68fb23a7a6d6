// The book's Markdown as pandoc parses it: a page read with
//     pandoc --from=gfm+tex_math_dollars+smart+sourcepos --to=json
// (the flavour the render reads, plus source positions), as pandoc's document tree (its JSON
// AST: {"t": type, "c": contents}), which the checks walk instead of scanning Markdown lines.
//
// The tree is read with the positions folded in: pandoc's sourcepos wraps every inline in a
// Span and every block in a Div carrying data-pos="file@line:col-line:col"; read_page() takes
// those wrappers out again (their contents take their place) and gives every node a "line"
// (1-based, of the page's source), inherited from the nearest node that has one.
//
// What the tree cannot say, which the checks read from the source line a node gives: how many
// cells an author wrote in a table row (pandoc pads a short row with empty cells), and the lines
// of a raw HTML block (CommonMark's: a line that starts with "<!--" or a tag is a RawBlock whole;
// the prose keeps value markers and number tags off the start of a line, see
// starts_with_inline_marker).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace md {

namespace fs = std::filesystem;
using Json = nlohmann::json;

struct Page {
    fs::path file;
    std::vector<std::string> lines;  // the source, for the two things above
    Json blocks;                     // the document's blocks, positions folded in
    Json api_version;                // pandoc's "pandoc-api-version", to write the tree back
};

// Reads and parses one page; throws when pandoc cannot.
Page read_page(const fs::path& file, const std::string& pandoc = "pandoc");

inline const std::string& type(const Json& node) { return node.at("t").get_ref<const std::string&>(); }
inline bool is(const Json& node, const char* t) { return node.is_object() && node.value("t", "") == t; }
inline int line(const Json& node) { return node.value("line", 0); }

// Every node below `node` (arrays and objects), in document order, the node itself first.
// `visit` returns false to skip a node's contents.
void walk(const Json& node, const std::function<bool(const Json&)>& visit);

// The text of inlines or blocks as a reader sees it: Str, spaces, code, math; no link targets,
// no raw HTML. With `everything`, also the code blocks, the raw HTML and the link targets (what a
// "does it name ..." check searches).
std::string text(const Json& node, bool everything = false);

// A RawInline or RawBlock of HTML: its text, else "".
std::string raw_html(const Json& node);

}  // namespace md

namespace md {

// ------------------------------------------------------------------ the book's markers in the tree

// The value markers of a page that are Markdown's (raw HTML in the tree, never in code): for each
// source line, the opening comments "<!-- value: ... -->" found there. A marker inside a
// paragraph is a RawInline; one that starts a line is a RawBlock of that whole line (CommonMark's
// HTML block), read with the marker's own grammar (prose.hpp).
std::map<int, std::vector<std::string>> value_marker_lines(const Page& page);

// Whether raw HTML starts (after blanks) with a marker that belongs inside a paragraph: a value
// marker "<!-- value: ... -->" or a number tag "<!--exact-->" (prose.hpp). At the start of a
// line CommonMark takes the whole line for an HTML block: the prose keeps them off it.
bool starts_with_inline_marker(const std::string& html);

// A quotation of a code snippet: "<!-- snippet: NAME -->", a code block, "<!-- end snippet -->".
struct Quotation {
    std::string name;
    int line = 0, end_line = 0;  // of the two markers; end_line 0 when there is no end marker
    bool one_cpp_block = false;  // exactly one ```cpp block between them
    std::string code;            // its text (pandoc's: without the last newline)
};

std::vector<Quotation> quotations(const Page& page);

}  // namespace md
