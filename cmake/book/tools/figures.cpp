// book --check-figures <root> <folder>...: no source writes gnuplot's Symbol-font escape for a
// Greek letter, and every SVG under the folders names a font that has every character of its
// text (fontconfig's fc-list). SVG is XML, not Markdown: its text and font families are read
// with regular expressions.
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "book.hpp"
#include "prose.hpp"
#include "run.hpp"

namespace book {

namespace {

using prose::rel;

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
// (cmake/book/, cmake/checks/) name the escape, and are not scanned.
// gnuplot's Symbol-font escape ({/Symbol w} for Ω), in the sources that draw figures. Returns how
// many sources it read.
int check_escapes(const fs::path& root, const std::string& escape, std::vector<std::string>& problems) {
    int sources = 0;
    for (const char* dir : {"chapters", "exercises", "tests", "figures", "cmake"}) {
        if (!fs::exists(root / dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
            if (!e.is_regular_file()) continue;
            const std::string r = rel(e.path(), root), ext = e.path().extension().string();
            if (r.rfind("cmake/book/", 0) == 0 || r.rfind("cmake/checks/", 0) == 0) continue;
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
            if (!have_fc_) have_fc_ = run({"fc-list", "--version"}).status == 0;
            if (!*have_fc_) return answered = false;
            const Output o =
                run({"fc-list", ":family=" + family + (charset.empty() ? "" : ":charset=" + charset), "family"});
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

}  // namespace

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

}  // namespace book
