// The length of every function in C++ sources, without compiling them: universal-ctags
// (Debian's universal-ctags) finds each function definition and the line of its closing brace,
// and a small lexer finds the line of its body's opening brace. A function's length is counted
// as clang-tidy's readability-function-size counts it: the lines after its opening brace's line,
// up to and including its closing brace's. Lambdas are part of the function that holds them
// (clang-tidy counts them so too).
//
//   function_size --lines 60 FILE...
//       prints "FILE:LINE: function 'NAME' has N lines" for each function over 60 lines, exit 1
//       when there is one, 0 when there is none, 2 when ctags cannot be run or read;
//   function_size --lines 0 FILE...
//       every function with its length (what the self-test compares with clang-tidy).
//
// cmake/checks/function_size.cmake runs it over chapters/, exercises/provided/, cmake/ and
// tests/grading/ in a few seconds, where clang-tidy, which compiles each source, takes half an hour.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "support/file.hpp"
#include "support/process.hpp"
#include "support/text.hpp"

namespace {

// A function definition as ctags reports it: where its name is and where its body ends.
struct Definition {
    std::string path, name;
    int line = 0, end = 0;
};

// What the lexer is inside of, besides code.
struct LexState {
    enum Kind { code, block_comment, quoted, raw } kind = code;
    char quote = 0;          // '"' or '\'' inside a quoted literal
    std::string terminator;  // )delim" inside a raw string literal
};

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Inside a comment or a literal at text[i]: where the code starts again (or text.size()).
std::size_t skip_non_code(const std::string& text, std::size_t i, LexState& s) {
    if (s.kind == LexState::block_comment) {
        const auto k = text.find("*/", i);
        if (k == std::string::npos) return text.size();
        s.kind = LexState::code;
        return k + 2;
    }
    if (s.kind == LexState::raw) {
        const auto k = text.find(s.terminator, i);
        if (k == std::string::npos) return text.size();
        s.kind = LexState::code;
        return k + s.terminator.size();
    }
    for (; i < text.size(); ++i) {  // quoted
        if (text[i] == '\\') {
            ++i;
        } else if (text[i] == s.quote) {
            s.kind = LexState::code;
            return i + 1;
        }
    }
    return text.size();
}

// At text[i] in code: the start of a comment or a literal? Sets s and returns where it goes on;
// std::nullopt when text[i] is code.
std::optional<std::size_t> enter_non_code(const std::string& text, std::size_t i, LexState& s) {
    static const std::regex raw_start(R"re(^R"([^()\\ \t]{0,16})\()re");
    const char c = text[i];
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') return text.size();
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
        s.kind = LexState::block_comment;
        return i + 2;
    }
    std::smatch m;
    const std::string rest = c == 'R' ? text.substr(i, 24) : std::string();
    if (c == 'R' &&
        (i == 0 || !is_word_char(text[i - 1]) || text[i - 1] == 'u' || text[i - 1] == '8' || text[i - 1] == 'L' ||
         text[i - 1] == 'U') &&
        std::regex_search(rest, m, raw_start)) {
        s.kind = LexState::raw;
        s.terminator = ")" + m[1].str() + "\"";
        return i + m[0].length();
    }
    if (c == '"' || (c == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(text[i - 1]))))) {
        s.kind = LexState::quoted;  // a ' after a digit separates digits (1'000)
        s.quote = c;
        return i + 1;
    }
    return std::nullopt;
}

// The line of the opening brace of the body that closes on line `end`: the top-level brace
// group, scanning from the start of line `line` (where the name is), that closes there. 0 when
// there is none (ctags and the lexer disagree: reported as an error).
int body_open_line(const std::vector<std::string>& lines, int line, int end) {
    LexState s;
    int depth = 0, open = 0;
    for (int n = line; n <= end && n <= int(lines.size()); ++n) {
        const std::string& text = lines[n - 1];
        if (s.kind == LexState::quoted) s.kind = LexState::code;  // a quote never spans lines
        for (std::size_t i = 0; i < text.size();) {
            if (s.kind != LexState::code) {
                i = skip_non_code(text, i, s);
                continue;
            }
            if (const auto next = enter_non_code(text, i, s)) {
                i = *next;
                continue;
            }
            if (text[i] == '{' && depth++ == 0) open = n;
            if (text[i] == '}' && --depth == 0 && n == end) return open;
            ++i;
        }
    }
    return 0;
}

// Every function definition in the files, by ctags (lambdas left out: ctags names them __anon).
std::vector<Definition> definitions(const std::vector<std::string>& files, std::string& error) {
    std::vector<std::string> argv = {
        "ctags", "--output-format=json", "--fields=+ne", "--kinds-C++=f", "--language-force=C++", "-f", "-"};
    argv.insert(argv.end(), files.begin(), files.end());
    const support::Result r = support::run(argv);
    if (r.status != 0) {
        error = "ctags (universal-ctags) failed (" + std::to_string(r.status) + "): " + r.error + r.err;
        return {};
    }
    std::vector<Definition> found;
    for (const std::string& row : support::split(r.out, '\n')) {
        if (support::trim(row).empty()) continue;
        const nlohmann::json tag = nlohmann::json::parse(row, nullptr, false);
        if (!tag.is_object() || tag.value("_type", "") != "tag") continue;
        const std::string name = tag.value("name", "");
        if (name.rfind("__anon", 0) == 0) continue;
        found.push_back({tag.value("path", ""), name, tag.value("line", 0), tag.value("end", 0)});
    }
    return found;
}

// The files' lines, read once each.
const std::vector<std::string>& lines_of(const std::string& path) {
    static std::map<std::string, std::vector<std::string>> cache;
    auto it = cache.find(path);
    if (it == cache.end()) it = cache.emplace(path, support::split(support::read_file(path), '\n')).first;
    return it->second;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"The functions over a number of lines, as clang-tidy's readability-function-size counts them"};
    int limit = 60;
    std::vector<std::string> files;
    app.add_option("--lines", limit, "report the functions longer than this (0: every function)")->required();
    app.add_option("files", files, "C++ sources and headers")->required();
    CLI11_PARSE(app, argc, argv);

    std::string error;
    const std::vector<Definition> all = definitions(files, error);
    if (!error.empty()) {
        std::fprintf(stderr, "function_size: %s\n", error.c_str());
        return 2;
    }
    bool over = false, broken = false;
    for (const Definition& d : all) {
        const int open = d.end > 0 ? body_open_line(lines_of(d.path), d.line, d.end) : 0;
        if (open == 0) {
            std::fprintf(stderr, "function_size: %s:%d: cannot find the body of '%s' (ctags ends it on line %d)\n",
                         d.path.c_str(), d.line, d.name.c_str(), d.end);
            broken = true;
            continue;
        }
        const int length = d.end - open;
        if (length <= limit) continue;
        over = over || limit > 0;
        std::printf("%s:%d: function '%s' has %d lines\n", d.path.c_str(), d.line, d.name.c_str(), length);
    }
    return broken ? 2 : over ? 1 : 0;
}
