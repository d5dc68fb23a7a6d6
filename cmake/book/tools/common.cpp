#include "book.hpp"
#include "markdown.hpp"
#include "prose.hpp"

namespace book {

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

std::string first_heading(const fs::path& file) {
    const md::Page page = md::read_page(file);
    for (const auto& b : page.blocks) {
        const int at = md::line(b);
        if (!md::is(b, "Header") || b["c"][0] != 1 || at < 1 || static_cast<std::size_t>(at) > page.lines.size())
            continue;
        // The heading as written on its line, without its markup (a title is plain text).
        const std::string& l = page.lines[static_cast<std::size_t>(at) - 1];
        std::string t;
        for (char c : l.substr(l.find_first_not_of("# ")))
            if (c != '*' && c != '`' && c != '_') t += c;
        return t;
    }
    return file.stem().string();
}

std::vector<std::string> chapter_list(const fs::path& contents) {
    if (contents.empty())
        throw std::runtime_error(
            "--contents <build>/contents.json is required (CMake writes it from chapters/README.md)");
    std::vector<std::string> out;
    const auto json = prose::read_json(contents);
    for (const auto& c : json.at("chapters")) out.push_back(c.at("folder").get<std::string>());
    return out;
}

}  // namespace book
