#include "markdown.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "run.hpp"

namespace md {

namespace {

// The line of a data-pos attribute, "file@12:1-14:3", taken out of `attr` ([id, classes, pairs]);
// 0 when it has none.
int take_position(Json& attr) {
    if (!attr.is_array() || attr.size() != 3 || !attr[0].is_string() || !attr[2].is_array()) return 0;
    // A list item has two: the item's, then its text's ("1:3-2:1;2:3-3:1"); the first is its line.
    auto& pairs = attr[2];
    int line = 0;
    for (auto it = pairs.begin(); it != pairs.end();) {
        if (!it->is_array() || it->size() != 2 || (*it)[0] != "data-pos") {
            ++it;
            continue;
        }
        const std::string pos = (*it)[1].get<std::string>();
        const auto at = pos.rfind('@');
        if (!line && at != std::string::npos) line = std::atoi(pos.c_str() + at + 1);
        it = pairs.erase(it);
    }
    return line;
}

// A Span or Div that only carries a position: what sourcepos wraps around every node.
bool is_wrapper(const Json& node) {
    if (!node.is_object() || !(is(node, "Span") || is(node, "Div"))) return false;
    const Json& attr = node["c"][0];
    return attr[0] == "" && attr[1].empty() && !attr[2].empty() &&
           std::all_of(attr[2].begin(), attr[2].end(), [](const Json& pair) { return pair[0] == "data-pos"; });
}

Json fold(Json node, int line);

// The items of an array, each folded; a wrapper's contents take its place.
Json fold_array(Json array, int line) {
    Json out = Json::array();
    for (auto& item : array) {
        if (is_wrapper(item)) {
            const int at = take_position(item["c"][0]);
            for (auto& inner : fold_array(std::move(item["c"][1]), at ? at : line)) out.push_back(std::move(inner));
        } else {
            out.push_back(fold(std::move(item), line));
        }
    }
    return out;
}

// One node: its own position (an attribute's data-pos) taken as its line, its contents folded.
Json fold(Json node, int line) {
    if (node.is_array()) {
        const int at = take_position(node);
        return fold_array(std::move(node), at ? at : line);
    }
    if (!node.is_object() || !node.contains("t")) return node;
    if (node.contains("c") && node["c"].is_array())
        for (auto& part : node["c"])
            if (const int at = take_position(part)) line = at;
    node["line"] = line;
    if (node.contains("c")) node["c"] = fold(std::move(node["c"]), line);
    return node;
}

std::vector<std::string> source_lines(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

// pandoc gives a raw HTML block inside a list item the line of the item: each RawBlock's line is
// set to the first source line, from there on, that has the block's first line.
void place_raw_blocks(Json& node, const std::vector<std::string>& lines) {
    if (node.is_array()) {
        for (auto& item : node) place_raw_blocks(item, lines);
        return;
    }
    if (!node.is_object() || !node.contains("c")) return;
    if (is(node, "RawBlock")) {
        const std::string text = node["c"][1].get<std::string>();
        std::string first = text.substr(0, text.find('\n'));
        first.erase(0, first.find_first_not_of(" \t"));
        for (auto i = static_cast<std::size_t>(std::max(line(node), 1)) - 1; i < lines.size(); ++i)
            if (!first.empty() && lines[i].find(first) != std::string::npos) {
                node["line"] = static_cast<int>(i) + 1;
                break;
            }
        return;
    }
    place_raw_blocks(node["c"], lines);
}

// pandoc's tree of a page's text, from the cache when pandoc has parsed the same text before:
// <tmp>/workbook-book-trees/<hash of the text and the pandoc>.json, written whole or not at all
// (a rename), so that the checks that read every page do not each start pandoc on each page.
Json parse(const fs::path& file, const std::string& text, const std::string& pandoc) {
    static const std::string from = "--from=gfm+tex_math_dollars+smart+sourcepos";
    const fs::path cache = fs::temp_directory_path() / "workbook-book-trees";
    char name[64];
    std::snprintf(name, sizeof name, "%016zx-%zu.json", std::hash<std::string>{}(pandoc + from + text), text.size());
    const fs::path cached = cache / name;
    std::error_code ec;
    if (!fs::exists(cached)) {
        fs::create_directories(cache, ec);
        const fs::path tmp = cache / (std::string(name) + "." + std::to_string(getpid()));
        const book::Output o = book::run({pandoc, from, "--to=json", "--output=" + tmp.string(), file.string()});
        if (o.status != 0) throw std::runtime_error(file.string() + ": pandoc cannot read it: " + o.text);
        fs::rename(tmp, cached);
    }
    std::ifstream in(cached);
    return Json::parse(in);
}

}  // namespace

Page read_page(const fs::path& file, const std::string& pandoc) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    Json tree = parse(file, text.str(), pandoc);
    Page page{file, source_lines(file), fold(std::move(tree["blocks"]), 0), tree["pandoc-api-version"]};
    place_raw_blocks(page.blocks, page.lines);
    return page;
}

void walk(const Json& node, const std::function<bool(const Json&)>& visit) {
    if (node.is_array()) {
        for (const auto& item : node) walk(item, visit);
        return;
    }
    if (!node.is_object() || !node.contains("t")) return;
    if (!visit(node) || !node.contains("c")) return;
    walk(node["c"], visit);
}

std::string raw_html(const Json& node) {
    if (!(is(node, "RawInline") || is(node, "RawBlock"))) return "";
    const Json& c = node["c"];
    return c[0] == "html" ? c[1].get<std::string>() : "";
}

std::string text(const Json& node, bool everything) {
    std::string out;
    walk(node, [&](const Json& n) {
        const std::string& t = type(n);
        if (t == "Str") out += n["c"].get<std::string>();
        if (t == "Space" || t == "SoftBreak" || t == "LineBreak") out += ' ';
        if (t == "Code" || t == "Math") out += n["c"][1].get<std::string>();
        if (t == "Para" || t == "Plain" || t == "Header") out += out.empty() || out.back() == '\n' ? "" : "\n";
        if (t == "Quoted") out += n["c"][0]["t"] == "DoubleQuote" ? "\"" : "'";
        if (!everything) return t != "Note";
        if (t == "CodeBlock") out += n["c"][1].get<std::string>() + "\n";
        if (t == "RawInline" || t == "RawBlock") out += n["c"][1].get<std::string>();
        if (t == "Link" || t == "Image") out += " " + n["c"][2][0].get<std::string>() + " ";
        return true;
    });
    return out;
}

}  // namespace md

namespace md {

std::map<int, std::vector<std::string>> value_marker_lines(const Page& page) {
    static const std::string open = "<!-- value:", close = "-->";
    std::map<int, std::vector<std::string>> out;
    walk(page.blocks, [&](const Json& n) {
        const std::string html = raw_html(n);
        if (html.find(open) == std::string::npos) return true;
        std::istringstream lines(html);  // a RawInline is one comment; a RawBlock whole lines
        int at = line(n);
        for (std::string l; std::getline(lines, l); ++at)
            for (std::size_t b = l.find(open); b != std::string::npos; b = l.find(open, b + 1)) {
                const auto e = l.find(close, b);
                if (e != std::string::npos) out[at].push_back(l.substr(b, e + close.size() - b));
            }
        return true;
    });
    return out;
}

bool starts_with_inline_marker(const std::string& html) {
    // A value marker's opening or closing comment, or a comment of one word (a number tag's grammar,
    // prose.hpp: "<!--exact-->", "<!--P:3-->").
    static const std::regex marker(R"(^\s*<!--\s*(value:|end value\s*-->|[A-Za-z]+(:[0-9]+)?\s*-->))");
    return std::regex_search(html, marker);
}

namespace {

// The name in "<!-- snippet: NAME -->", else "". An HTML comment's grammar, not Markdown's.
std::string snippet_name(const Json& block) {
    static const std::regex marker(R"(^<!-- snippet: ([A-Za-z0-9_]+) -->\s*$)");
    std::smatch m;
    const std::string html = raw_html(block);
    return std::regex_match(html, m, marker) ? m[1].str() : "";
}

bool is_snippet_end(const Json& block) {
    static const std::regex marker(R"(^<!-- end snippet -->\s*$)");
    return std::regex_match(raw_html(block), marker);
}

// Every list of blocks of the tree: the document's, and those inside lists, quotes and divs.
void block_lists(const Json& blocks, const std::function<void(const Json&)>& visit) {
    visit(blocks);
    for (const auto& b : blocks) {
        if (is(b, "BlockQuote")) block_lists(b["c"], visit);
        if (is(b, "Div")) block_lists(b["c"][1], visit);
        if (is(b, "BulletList") || is(b, "OrderedList"))
            for (const auto& item : is(b, "BulletList") ? b["c"] : b["c"][1]) block_lists(item, visit);
    }
}

}  // namespace

std::vector<Quotation> quotations(const Page& page) {
    std::vector<Quotation> out;
    block_lists(page.blocks, [&](const Json& blocks) {
        for (std::size_t i = 0; i < blocks.size(); ++i) {
            Quotation q;
            q.name = snippet_name(blocks[i]);
            q.line = line(blocks[i]);
            if (q.name.empty()) continue;
            std::size_t j = i + 1;
            while (j < blocks.size() && !is_snippet_end(blocks[j]) && snippet_name(blocks[j]).empty()) ++j;
            if (j < blocks.size() && is_snippet_end(blocks[j])) q.end_line = line(blocks[j]);
            const Json& first = blocks[std::min(i + 1, blocks.size() - 1)];
            q.one_cpp_block = j == i + 2 && is(first, "CodeBlock") && first["c"][0][1] == Json::array({"cpp"});
            if (q.one_cpp_block) q.code = first["c"][1].get<std::string>();
            out.push_back(q);
            i = q.end_line ? j : i;
        }
    });
    return out;
}

}  // namespace md
