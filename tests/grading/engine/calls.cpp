#include "calls.hpp"

#include <algorithm>
#include <cctype>

#include "support/text.hpp"

namespace grading::calls {

std::vector<bool> code_mask(const std::string& s) {
    std::vector<bool> code(s.size(), true);
    std::size_t i = 0;
    bool line_start = true;
    auto blank = [&](std::size_t from, std::size_t to) {
        for (std::size_t k = from; k < to && k < s.size(); ++k) code[k] = false;
    };
    while (i < s.size()) {
        const char c = s[i];
        std::size_t end = i + 1;
        if (line_start && c == '#') {
            end = s.find('\n', i);
        } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            end = s.find('\n', i);
        } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            end = s.find("*/", i + 2);
            end = end == std::string::npos ? end : end + 2;
        } else if (c == '"' || c == '\'') {
            end = i + 1;
            while (end < s.size() && s[end] != c) end += s[end] == '\\' ? 2 : 1;
            ++end;
        } else {
            if (c == '\n')
                line_start = true;
            else if (c != ' ' && c != '\t')
                line_start = false;
            ++i;
            continue;
        }
        if (end == std::string::npos || end > s.size()) end = s.size();
        blank(i, end);
        i = end;
    }
    return code;
}

namespace {

bool is_ident(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The name of the function whose header ends at `open` (a '{'), or "" if it is not a function.
std::string function_name(const std::string& s, const std::vector<bool>& code, std::size_t from, std::size_t open,
                          std::string* header) {
    std::string h;
    for (std::size_t k = from; k < open; ++k) h += code[k] && s[k] != '\n' ? s[k] : ' ';
    *header = support::trim(h);
    const auto paren = h.find('(');
    if (paren == std::string::npos || h.find("namespace") != std::string::npos) return "";
    auto e = paren;
    while (e > 0 && h[e - 1] == ' ') --e;
    auto b = e;
    while (b > 0 && is_ident(h[b - 1])) --b;
    return h.substr(b, e - b);
}

}  // namespace

std::vector<Body> function_bodies(const std::string& s, const std::vector<bool>& code, std::string* error) {
    std::vector<Body> bodies;
    std::vector<bool> is_function;   // a stack: true for a function's brace
    std::size_t functions_open = 0;  // the stack's function braces: 0 or 1 (a brace inside a
                                     // function is never a function's); a count, not a search
    std::size_t header_from = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!code[i]) continue;
        if (s[i] == '{') {
            std::string header, name;
            if (functions_open == 0) name = function_name(s, code, header_from, i, &header);
            is_function.push_back(!name.empty());
            if (!name.empty()) bodies.push_back({i, std::string::npos, name, header}), ++functions_open;
        } else if (s[i] == '}') {
            if (is_function.empty()) {
                if (error) *error = "unbalanced braces";
                return {};
            }
            if (is_function.back()) {
                if (functions_open == 1) bodies.back().end = i;
                --functions_open;
            }
            is_function.pop_back();
        }
        if (functions_open == 0 && (s[i] == ';' || s[i] == '{' || s[i] == '}')) header_from = i + 1;
    }
    return bodies;
}

std::map<std::string, std::set<std::string>> uses_of(const std::string& s, const std::set<std::string>& exercises) {
    const auto code = code_mask(s);
    const auto bodies = function_bodies(s, code);
    std::set<std::string> defined;
    for (const auto& b : bodies) defined.insert(b.name);
    // function -> the file's functions it calls: every identifier of its code followed by '(' (one
    // pass over the text, so a file of many functions costs no more than its length)
    std::map<std::string, std::set<std::string>> calls;
    for (const auto& b : bodies) {
        const std::size_t end = std::min(b.end, s.size());
        for (std::size_t i = b.begin; i < end;) {
            if (!code[i] || !is_ident(s[i]) || (i > b.begin && is_ident(s[i - 1]))) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < end && is_ident(s[j])) ++j;
            std::size_t k = j;
            while (k < end && (s[k] == ' ' || s[k] == '\n' || s[k] == '\t')) ++k;
            const std::string name = s.substr(i, j - i);
            if (k < end && s[k] == '(' && name != b.name && defined.count(name)) calls[b.name].insert(name);
            i = j;
        }
    }
    std::map<std::string, std::set<std::string>> uses;
    for (const auto& e : exercises) {
        std::set<std::string> seen;
        std::vector<std::string> todo(calls[e].begin(), calls[e].end());
        while (!todo.empty()) {
            const std::string f = todo.back();
            todo.pop_back();
            if (!seen.insert(f).second) continue;
            todo.insert(todo.end(), calls[f].begin(), calls[f].end());
        }
        for (const auto& f : seen)
            if (f != e && exercises.count(f)) uses[e].insert(f);
    }
    return uses;
}

}  // namespace grading::calls
