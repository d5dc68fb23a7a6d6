// gnuplot scripts filled in (script.hpp): shared by the scenes' figures (chapters/kit/figure.cpp,
// and the live book's recorder, cmake/book/live/figure_live.cpp) and the class report
// (tests/grading/engine/class_report.cpp).
#include "support/script.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace support {

namespace {

bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The length of the placeholder name that starts at text[at] and is closed by '@', or 0.
std::size_t placeholder_at(std::string_view text, std::size_t at) {
    std::size_t end = at;
    while (end < text.size() && name_char(text[end])) ++end;
    const bool opens = end > at && !std::isdigit(static_cast<unsigned char>(text[at]));
    return (opens && end < text.size() && text[end] == '@') ? end - at : 0;
}

// Whether text[at] starts a comment line: at a line's start, after blanks only, a '#'.
bool comment_at(std::string_view text, std::size_t at) {
    if (at > 0 && text[at - 1] != '\n') return false;
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
    return at < text.size() && text[at] == '#';
}

std::string message(const Script& script, const std::string& what) {
    return "gnuplot script " + std::string(script.name) + ": " + what;
}

}  // namespace

std::string filled(const Script& script, const Fill& values) {
    const std::string_view text = script.text;
    std::vector<bool> used(values.size(), false);
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
        if (comment_at(text, i)) {  // a comment line may name a placeholder: it stays as it is
            const std::size_t end = std::min(text.find('\n', i), text.size());
            out.append(text.substr(i, end - i));
            i = end;
            continue;
        }
        const std::size_t n = text[i] == '@' ? placeholder_at(text, i + 1) : 0;
        if (n == 0) {
            out += text[i++];
            continue;
        }
        const std::string_view name = text.substr(i + 1, n);
        std::size_t k = 0;
        while (k < values.size() && values[k].first != name) ++k;
        if (k == values.size())
            throw std::logic_error(message(script, "no value for its placeholder @" + std::string(name) + "@"));
        out += values[k].second;
        used[k] = true;
        i += n + 2;
    }
    for (std::size_t k = 0; k < values.size(); ++k)
        if (!used[k])
            throw std::logic_error(
                message(script, "a value for @" + values[k].first + "@, a placeholder it does not have"));
    return out;
}

std::string joined(const Script& clause, const std::vector<Fill>& items, const std::string& separator) {
    std::string_view text = clause.text;
    while (comment_at(text, 0)) text.remove_prefix(std::min(text.find('\n'), text.size() - 1) + 1);
    if (!text.empty() && text.back() == '\n') text.remove_suffix(1);
    if (text.find('\n') != std::string_view::npos)
        throw std::logic_error(message(clause, "a clause must be one line of gnuplot (after its comments)"));
    const Script line{clause.name, text};
    std::string out;
    for (std::size_t k = 0; k < items.size(); ++k) out += (k ? separator : "") + filled(line, items[k]);
    return out;
}

std::string gnuplot_quoted(const std::string& text) {
    std::string out = "'";
    for (const char c : text) out += (c == '\'') ? std::string("''") : std::string(1, c);
    return out + "'";
}

}  // namespace support
