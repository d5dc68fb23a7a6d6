#include "../prose.hpp"
#include "book.hpp"

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
