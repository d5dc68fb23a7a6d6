// The hint ladders: reader, TeX-subset printer and the nudge rule (see hints.hpp).
#include "hints.hpp"

#include <cctype>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "support/file.hpp"
#include "support/text.hpp"

namespace hints {

namespace {

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::string line;
    std::istringstream in(text);
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

using support::trim;

bool starts_with(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }

// ---- TeX subset -> Unicode --------------------------------------------------------------------
const std::map<std::string, std::string>& symbols() {
    static const std::map<std::string, std::string> m = {
        {"alpha", "α"}, {"beta", "β"},   {"gamma", "γ"},  {"delta", "δ"},  {"epsilon", "ε"}, {"varepsilon", "ε"},
        {"zeta", "ζ"},  {"eta", "η"},    {"theta", "θ"},  {"kappa", "κ"},  {"lambda", "λ"},  {"mu", "μ"},
        {"nu", "ν"},    {"xi", "ξ"},     {"pi", "π"},     {"rho", "ρ"},    {"sigma", "σ"},   {"tau", "τ"},
        {"phi", "φ"},   {"varphi", "φ"}, {"chi", "χ"},    {"psi", "ψ"},    {"omega", "ω"},   {"Gamma", "Γ"},
        {"Delta", "Δ"}, {"Theta", "Θ"},  {"Lambda", "Λ"}, {"Pi", "Π"},     {"Sigma", "Σ"},   {"Phi", "Φ"},
        {"Psi", "Ψ"},   {"Omega", "Ω"},  {"cdot", "·"},   {"times", "×"},  {"top", "ᵀ"},     {"le", "≤"},
        {"ge", "≥"},    {"ne", "≠"},     {"approx", "≈"}, {"pm", "±"},     {"to", "→"},      {"lVert", "‖"},
        {"rVert", "‖"}, {"lvert", "|"},  {"rvert", "|"},  {"langle", "⟨"}, {"rangle", "⟩"},  {"infty", "∞"},
        {"sum", "Σ"},   {"quad", " "},
    };
    return m;
}
const std::map<std::string, std::string>& functions() {
    static const std::map<std::string, std::string> m = {
        {"sin", "sin"}, {"cos", "cos"}, {"tan", "tan"}, {"arccos", "arccos"}, {"min", "min"}, {"max", "max"},
    };
    return m;
}
const std::map<char, std::string>& superscripts() {
    static const std::map<char, std::string> m = {
        {'0', "⁰"}, {'1', "¹"}, {'2', "²"}, {'3', "³"}, {'4', "⁴"}, {'5', "⁵"}, {'6', "⁶"},
        {'7', "⁷"}, {'8', "⁸"}, {'9', "⁹"}, {'+', "⁺"}, {'-', "⁻"}, {'a', "ᵃ"}, {'b', "ᵇ"},
        {'n', "ⁿ"}, {'i', "ⁱ"}, {'p', "ᵖ"}, {'k', "ᵏ"}, {'T', "ᵀ"},
    };
    return m;
}
const std::map<char, std::string>& subscripts() {
    static const std::map<char, std::string> m = {
        {'0', "₀"}, {'1', "₁"}, {'2', "₂"}, {'3', "₃"}, {'4', "₄"}, {'5', "₅"},
        {'6', "₆"}, {'7', "₇"}, {'8', "₈"}, {'9', "₉"}, {'+', "₊"}, {'-', "₋"},
    };
    return m;
}

bool is_letter_start(const std::string& s) {
    if (s.empty()) return false;
    const unsigned char c = static_cast<unsigned char>(s[0]);
    return std::isalnum(c) || c >= 0x80;  // a letter, a digit, or a Greek letter (UTF-8)
}
// Characters of one visible symbol (a UTF-8 sequence counts as one).
std::size_t symbol_count(const std::string& s) {
    std::size_t n = 0;
    for (unsigned char c : s) n += (c & 0xC0) != 0x80;
    return n;
}

class Math {
public:
    explicit Math(const std::string& tex) : s_(tex) {}
    std::string run() {
        std::string out = group_until('\0');
        return out;
    }

private:
    const std::string& s_;
    std::size_t i_ = 0;

    // One argument: {...}, a command, or one character.
    std::string argument() {
        while (i_ < s_.size() && s_[i_] == ' ') ++i_;
        if (i_ >= s_.size()) return "";
        if (s_[i_] == '{') {
            ++i_;
            return group_until('}');
        }
        if (s_[i_] == '\\') return command();
        return std::string(1, s_[i_++]);
    }
    // Parentheses around a compound argument only: x/2, √x², (a + b)/2.
    static std::string wrap(const std::string& x) {
        return x.find_first_of(" +-/*=") == std::string::npos && x.find("·") == std::string::npos &&
                       x.find("×") == std::string::npos
                   ? x
                   : "(" + x + ")";
    }
    std::string script(bool up) {
        const std::string arg = argument();
        const auto& table = up ? superscripts() : subscripts();
        std::string mapped;
        bool all = !arg.empty();
        for (std::size_t k = 0; k < arg.size() && all; ++k) {
            if (up && starts_with(arg.substr(k), "ᵀ")) {  // ^\top, ^{a\top}
                mapped += "ᵀ";
                k += std::string("ᵀ").size() - 1;
                continue;
            }
            const auto it = table.find(arg[k]);
            if (it == table.end())
                all = false;
            else
                mapped += it->second;
        }
        if (all) return mapped;
        return std::string(up ? "^" : "_") + (up ? wrap(arg) : arg);
    }
    std::string command() {
        ++i_;  // the backslash
        if (i_ >= s_.size()) return "\\";
        if (!std::isalpha(static_cast<unsigned char>(s_[i_]))) {
            const char c = s_[i_++];
            if (c == ',' || c == ';' || c == ' ' || c == '!') return " ";
            if (c == '{' || c == '}' || c == '|') return std::string(1, c);
            return std::string("\\") + c;
        }
        std::size_t b = i_;
        while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) ++i_;
        const std::string name = s_.substr(b, i_ - b);
        if (name == "lVert" || name == "lvert" || name == "langle")  // an opening delimiter: no space after it
            while (i_ < s_.size() && s_[i_] == ' ') ++i_;
        if (name == "rVert" || name == "rvert" || name == "rangle")
            return "\x02" + symbols().at(name);  // closing: none before it
        if (const auto it = symbols().find(name); it != symbols().end()) return it->second;
        if (const auto it = functions().find(name); it != functions().end()) return "\x03" + it->second + "\x01";
        if (name == "mathbf" || name == "boldsymbol" || name == "mathrm") return argument();
        if (name == "frac" || name == "tfrac" || name == "dfrac") {
            const std::string a = argument(), d = argument();
            if (a == "1" && d == "2") return "½";
            return wrap(a) + "/" + wrap(d);
        }
        if (name == "sqrt") return "√" + wrap(argument());
        if (name == "hat" || name == "dot") {
            const std::string a = argument();
            if (symbol_count(a) == 1) return a + (name == "hat" ? "\u0302" : "\u0307");
            return std::string(name == "hat" ? "hat" : "d/dt ") + "(" + a + ")";
        }
        return "\\" + name;  // unknown: left for tex_left() to report
    }
    std::string group_until(char end) {
        std::string out;
        while (i_ < s_.size()) {
            const char c = s_[i_];
            if (c == end) {
                ++i_;
                break;
            }
            std::string piece;
            if (c == '\\')
                piece = command();
            else if (c == '{')
                ++i_, piece = group_until('}');
            else if (c == '^')
                ++i_, piece = script(true);
            else if (c == '_')
                ++i_, piece = script(false);
            else
                piece = std::string(1, c), ++i_;
            append(out, piece);
        }
        return out;
    }
    // A function name (marked \x01) is followed by a space before a letter: sin φ, not sinφ.
    // A subscript written with _ is followed by a space before a letter: ε_kij W_ij. A closing
    // delimiter (marked \x02) takes no space before it; a function name (marked \x03) one.
    static void append(std::string& out, std::string piece) {
        if (starts_with(piece, "\x02")) {
            piece.erase(0, 1);
            while (!out.empty() && out.back() == ' ') out.pop_back();
        }
        if (starts_with(piece, "\x03")) {
            piece.erase(0, 1);
            if (!out.empty() && out.back() != ' ' && out.back() != '(' && out.back() != '/' && out.back() != '\x01')
                out += ' ';
        }
        if (!out.empty() && out.find('_') != std::string::npos && is_letter_start(piece) &&
            std::isalnum(static_cast<unsigned char>(out.back()))) {
            // the last word of out is a _ subscript: keep the next symbol apart
            const auto sub = out.rfind('_');
            const auto sep = out.find_last_of(" ()+-/");
            if (sep == std::string::npos || sub > sep) out += ' ';
        }
        if (!out.empty() && out.back() == '\x01') {
            out.pop_back();
            if (piece.find('/') != std::string::npos) {  // sin φ/2 would read as (sin φ)/2
                out += "(" + piece + ")";
                return;
            }
            if (is_letter_start(piece) || starts_with(piece, "√")) out += ' ';
        }
        out += piece;
    }
};

std::string math_to_text(const std::string& tex) {
    std::string out = Math(tex).run();
    std::string clean;
    for (char c : out)
        if (c != '\x01' && !(c == ' ' && !clean.empty() && clean.back() == ' ')) clean += c;
    return trim(clean);
}

// Calls f(segment, kind) for the pieces of a line: 'c' code in backticks, 'm' math, 't' text.
template <typename F>
void segments(const std::string& line, F f) {
    std::size_t i = 0;
    std::string text;
    while (i < line.size()) {
        const char c = line[i];
        if (c == '`') {
            const auto e = line.find('`', i + 1);
            if (e != std::string::npos) {
                if (!text.empty()) f(text, 't'), text.clear();
                f(line.substr(i, e - i + 1), 'c');
                i = e + 1;
                continue;
            }
        }
        if (c == '$') {
            const auto e = line.find('$', i + 1);
            if (e != std::string::npos && e > i + 1) {
                if (!text.empty()) f(text, 't'), text.clear();
                f(line.substr(i + 1, e - i - 1), 'm');
                i = e + 1;
                continue;
            }
        }
        text += c;
        ++i;
    }
    if (!text.empty()) f(text, 't');
}

}  // namespace

// ---- the reader ---------------------------------------------------------------------------------
namespace {

// Reads a hints file line by line; each step returns "" or the first problem, "<file>:<line>: ...".
class LadderReader {
public:
    explicit LadderReader(const std::string& file_name) : file_(file_name) {}

    std::string line(std::size_t n, const std::string& line) {
        if (starts_with(trim(line), "```")) fence_ = !fence_;
        const bool heading = !fence_ && starts_with(line, "#");
        if (heading && (starts_with(line, "# ") || starts_with(line, "## ") || starts_with(line, "### ")))
            return section(n, line);
        if (heading && starts_with(line, "####")) return level(n, trim(line));
        if (heading) return at(n, "'" + trim(line) + "': an unknown heading level");
        return text(n, line);
    }

    std::string finish(std::size_t last) {
        if (fence_) return at(last, "a code block (```) is not closed");
        return close(last);
    }

    Hints take() {
        for (auto& l : hints_.ladders)
            for (auto& level : l.levels) level = trim(level);
        return std::move(hints_);
    }

private:
    std::string at(std::size_t n, const std::string& what) const {
        return file_ + ":" + std::to_string(n + 1) + ": " + what;
    }

    // The ladder being read is complete: 2 or 3 levels, none empty.
    std::string close(std::size_t n) const {
        if (!current_) return "";
        if (current_->levels.size() < 2)
            return at(n, "the hints of '" + current_->exercise + "' have " + std::to_string(current_->levels.size()) +
                             " level(s); a ladder has 2 or 3 (#### Hint 1, #### Hint 2, optionally #### Hint 3)");
        for (std::size_t k = 0; k < current_->levels.size(); ++k)
            if (trim(current_->levels[k]).empty())
                return file_ + ":" + std::to_string(current_->line) + ": Hint " + std::to_string(k + 1) + " of '" +
                       current_->exercise + "' is empty";
        return "";
    }

    // A #, ## or ### heading closes the ladder; a ### heading opens the next exercise's.
    std::string section(std::size_t n, const std::string& line) {
        if (auto e = close(n); !e.empty()) return e;
        current_ = nullptr;
        if (!starts_with(line, "### ")) return "";
        const std::string name = trim(line.substr(4));
        if (!std::regex_match(name, std::regex("[A-Za-z_][A-Za-z0-9_]*")))
            return at(n, "'### " + name + "' is not an exercise name (one identifier, as in exercises/rigid/*.hpp)");
        if (find(hints_, name)) return at(n, "'" + name + "' has a second ### section");
        hints_.ladders.push_back({name, static_cast<int>(n + 1), {}});
        current_ = &hints_.ladders.back();
        return "";
    }

    // "#### Hint k": the next level of the open ladder, in order 1, 2, 3.
    std::string level(std::size_t n, const std::string& t) {
        std::smatch m;
        if (!current_) return at(n, "'" + t + "' outside an exercise's ### section");
        if (!std::regex_match(t, m, std::regex("#### Hint ([0-9]+)")))
            return at(n, "'" + t + "': the only level-4 headings are #### Hint 1, #### Hint 2 and #### Hint 3");
        const int expected = static_cast<int>(current_->levels.size()) + 1;
        if (expected > 3) return at(n, "'" + current_->exercise + "' has more than 3 levels");
        if (std::stoi(m[1]) != expected)
            return at(n, "'" + t + "' in '" + current_->exercise + "': expected #### Hint " + std::to_string(expected) +
                             " (levels go 1, 2, 3 in order)");
        current_->levels.emplace_back();
        return "";
    }

    // Text belongs to the open level; outside a ladder it is the title, the introduction or a note.
    std::string text(std::size_t n, const std::string& line) {
        if (!current_) return "";
        if (current_->levels.empty())
            return trim(line).empty()
                       ? ""
                       : at(n, "text before '#### Hint 1' in '" + current_->exercise + "': every hint is in a level");
        current_->levels.back() += line + "\n";
        return "";
    }

    std::string file_;
    Hints hints_;
    Ladder* current_ = nullptr;
    bool fence_ = false;
};

}  // namespace

Hints parse(const std::string& text, const std::string& file_name) {
    const auto lines = lines_of(text);
    LadderReader reader(file_name);
    std::string error;
    for (std::size_t n = 0; n < lines.size() && error.empty(); ++n) error = reader.line(n, lines[n]);
    if (error.empty()) error = reader.finish(lines.empty() ? 0 : lines.size() - 1);
    Hints h = reader.take();
    h.error = error;
    return h;
}

Hints read(const std::string& path) {
    bool ok = false;
    const std::string text = support::read_file(path, &ok);
    if (!ok) {
        Hints h;
        h.error = path + ": cannot read the hints";
        return h;
    }
    return parse(text, path);
}

const Ladder* find(const Hints& hints, const std::string& exercise) {
    for (const auto& l : hints.ladders)
        if (l.exercise == exercise) return &l;
    return nullptr;
}

// ---- the printer ------------------------------------------------------------------------------------
std::string plain_text(const std::string& markdown) {
    std::string out;
    for (const auto& line : lines_of(markdown)) {
        std::string converted;
        segments(line, [&](const std::string& piece, char kind) {
            if (kind == 'c')
                converted += piece;
            else if (kind == 'm')
                converted += math_to_text(piece);
            else
                converted += std::regex_replace(piece, std::regex("\\*\\*"), "");
        });
        out += converted + "\n";
    }
    return out;
}

std::string tex_left(const std::string& text) {
    std::string found;
    for (const auto& line : lines_of(text))
        segments(line, [&](const std::string& piece, char kind) {
            if (!found.empty() || kind == 'c') return;
            if (kind == 'm') {
                found = "$" + piece + "$";
                return;
            }
            std::smatch m;
            if (std::regex_search(piece, m, std::regex("\\\\[A-Za-z]+|\\\\[,;!{}]|[{}]|[\\^_]\\{")))
                found = m.str() + " in '" + trim(piece) + "'";
        });
    return found;
}

// ---- the nudge rule ------------------------------------------------------------------------------
std::string code_in_nudge(const std::string& markdown) {
    const std::regex name(
        "`(~?[A-Za-z_][A-Za-z0-9_]*(::[A-Za-z_][A-Za-z0-9_]*)*|[A-Za-z0-9_./-]+/[A-Za-z0-9_./-]*|[A-Za-z_]+:)`");
    const std::regex eigen_alias("\\b(Mat3|Vec3|VecX|Eigen|MatrixXd|VectorXd)\\b");
    const std::regex call("\\b[A-Za-z_][A-Za-z0-9_]*\\([^)]*\\)");
    const std::regex cpp("<<|==|!=|->|&&|\\|\\||\\+=|-=|::|;\\s*$|\\breturn\\b|\\bauto\\b|\\bconst\\b");
    std::string found;
    bool fence = false;
    for (const auto& line : lines_of(markdown)) {
        if (starts_with(trim(line), "```") || fence) {
            if (starts_with(trim(line), "```")) fence = !fence;
            if (found.empty()) found = "a code block";
            continue;
        }
        if (starts_with(line, "    ") && !trim(line).empty() && found.empty())
            found = "an indented code block: '" + trim(line) + "'";
        segments(line, [&](const std::string& piece, char kind) {
            if (!found.empty()) return;
            std::smatch m;
            if (kind == 'c') {
                if (!std::regex_match(piece, name))
                    found = "code " + piece;
                else if (std::regex_search(piece, m, eigen_alias))
                    found = "an Eigen type " + piece;
            } else if (kind == 't') {
                if (std::regex_search(piece, m, call))
                    found = "a call " + m.str();
                else if (std::regex_search(piece, m, eigen_alias))
                    found = "an Eigen name " + m.str();
                else if (std::regex_search(piece, m, cpp))
                    found = "C++ '" + trim(m.str()) + "' in '" + trim(piece) + "'";
            }
        });
    }
    return found;
}

std::vector<std::string> lint(const Ladder& ladder, const std::string& file_name) {
    std::vector<std::string> problems;
    const std::string where = file_name + ":" + std::to_string(ladder.line) + ": " + ladder.exercise;
    if (ladder.levels.size() < 2 || ladder.levels.size() > 3)
        problems.push_back(where + ": " + std::to_string(ladder.levels.size()) + " levels; a ladder has 2 or 3");
    for (std::size_t k = 0; k < ladder.levels.size(); ++k)
        if (const auto left = tex_left(plain_text(ladder.levels[k])); !left.empty())
            problems.push_back(where + ", Hint " + std::to_string(k + 1) + ": TeX left in the terminal text: " + left);
    // No rung holds code: a hint names the equation, the property or a check the student can
    // make (a value for given inputs, a limiting case), never what to type.
    for (std::size_t k = 0; k < ladder.levels.size(); ++k)
        if (const auto code = code_in_nudge(ladder.levels[k]); !code.empty())
            problems.push_back(where + ", Hint " + std::to_string(k + 1) + " holds code of the answer (" + code +
                               "); a hint names the equation, the property or a check to make, never the code");
    return problems;
}

std::string for_terminal(const Ladder& ladder, int level) {
    if (level < 1 || level > static_cast<int>(ladder.levels.size())) return "";
    std::string out = "\nHint " + std::to_string(level) + " of " + std::to_string(ladder.levels.size()) + " for " +
                      ladder.exercise + " (exercises/hints.md):\n";
    for (const auto& line : lines_of(plain_text(ladder.levels[level - 1]))) out += "  " + line + "\n";
    if (level < static_cast<int>(ladder.levels.size()))
        out += "Stuck after trying it? The next hint: cmake/workbook check " + ladder.exercise + " --hint " +
               std::to_string(level + 1) + "\n";
    return out;
}

}  // namespace hints
