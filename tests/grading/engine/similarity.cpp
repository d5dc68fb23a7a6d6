// The similarity report of a class (similarity.md and similarity.csv): for each exercise, the
// submissions whose code matches the reference solution or another submission once names,
// whitespace, comments and literals are normalised away. It flags; it never changes a grade.
//
// The method is MOSS's (Schleimer, Wilkerson and Aiken, "Winnowing: local algorithms for
// document fingerprinting", SIGMOD 2003): the code is cut into tokens, every run of K tokens is
// hashed, and winnowing keeps the smallest hash of every W consecutive ones as a fingerprint,
// so that any run of W + K - 1 tokens two files share is sure to leave a fingerprint in both.
// Written here by hand because Debian packages no library that does it for C++ source (MOSS is
// a web service; sherlock and sim are programs with their own report formats and no notion of
// exercises); the tokenizer knows just enough C++ for this and no more.
#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "grading.hpp"

namespace grading {

namespace {

// Tokens per k-gram (about one statement), and the winnowing window.
constexpr std::size_t K = 12, W = 4;
// A pair is listed for an exercise when at least half of the smaller fingerprint set is shared
// (and at least kMinShared fingerprints), and either the two files also match as a whole at that
// level, or the exercise alone is long (kAlone tokens on both sides) and nearly the same (kStrong).
// One function that matches moderately is weak evidence alone: a contract and its helpers leave
// few ways to write a short function, or even the opening checks and closing lines of a long one.
constexpr double kThreshold = 0.5, kStrong = 0.8;
constexpr std::size_t kMinShared = 3, kAlone = 80;

enum class Kind { identifier, keyword, number, text, punct };

struct Token {
    std::string text;
    Kind kind;
    int line;
};

bool is_keyword(const std::string& s) {
    static const std::set<std::string> words = {"alignas",      "alignof",       "auto",        "bool",
                                                "break",        "case",          "catch",       "char",
                                                "class",        "const",         "consteval",   "constexpr",
                                                "constinit",    "const_cast",    "continue",    "decltype",
                                                "default",      "delete",        "do",          "double",
                                                "dynamic_cast", "else",          "enum",        "explicit",
                                                "extern",       "false",         "float",       "for",
                                                "friend",       "goto",          "if",          "inline",
                                                "int",          "long",          "mutable",     "namespace",
                                                "new",          "noexcept",      "nullptr",     "operator",
                                                "private",      "protected",     "public",      "reinterpret_cast",
                                                "return",       "short",         "signed",      "sizeof",
                                                "static",       "static_assert", "static_cast", "struct",
                                                "switch",       "template",      "this",        "throw",
                                                "true",         "try",           "typedef",     "typename",
                                                "union",        "unsigned",      "using",       "virtual",
                                                "void",         "volatile",      "while"};
    return words.count(s) > 0;
}

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Skips whitespace, comments and preprocessor lines from i; counts lines.
std::size_t skip_blank(const std::string& s, std::size_t i, int& line, bool& line_start) {
    while (i < s.size()) {
        const char c = s[i];
        if (c == '\n') {
            ++line, ++i, line_start = true;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (s.compare(i, 2, "//") == 0 || (c == '#' && line_start)) {
            // A comment or a directive runs to the end of the line (a directive, past a "\\" that ends one).
            while (i < s.size() && s[i] != '\n') {
                if (c == '#' && s[i] == '\\' && i + 1 < s.size() && s[i + 1] == '\n') ++line, ++i;
                ++i;
            }
        } else if (s.compare(i, 2, "/*") == 0) {
            const std::size_t end = s.find("*/", i + 2);
            const std::size_t stop = end == std::string::npos ? s.size() : end + 2;
            line += static_cast<int>(
                std::count(s.begin() + static_cast<long>(i), s.begin() + static_cast<long>(stop), '\n'));
            i = stop;
        } else {
            break;
        }
    }
    return i;
}

// The end of the string or character literal that starts at i (its opening quote, or R" for a raw string).
std::size_t literal_end(const std::string& s, std::size_t i) {
    if (s[i] == 'R') {
        const std::size_t open = s.find('(', i + 2);
        if (open == std::string::npos) return s.size();
        const std::string close = ")" + s.substr(i + 2, open - i - 2) + "\"";
        const std::size_t end = s.find(close, open);
        return end == std::string::npos ? s.size() : end + close.size();
    }
    const char quote = s[i];
    for (std::size_t j = i + 1; j < s.size(); ++j) {
        if (s[j] == '\\')
            ++j;
        else if (s[j] == quote || s[j] == '\n')
            return j + 1;
    }
    return s.size();
}

std::size_t number_end(const std::string& s, std::size_t i) {
    std::size_t j = i + 1;
    while (j < s.size()) {
        const char c = s[j];
        if ((c == '+' || c == '-') && std::string("eEpP").find(s[j - 1]) != std::string::npos)
            ++j;
        else if (ident_char(c) || c == '.' || (c == '\'' && j + 1 < s.size() && ident_char(s[j + 1])))
            ++j;
        else
            break;
    }
    return j;
}

std::size_t punct_length(const std::string& s, std::size_t i) {
    static const char* longer[] = {"<<=", ">>=", "...", "->*", "<=>", "::", "->", "<<", ">>", "<=", ">=", "==", "!=",
                                   "&&",  "||",  "++",  "--",  "+=",  "-=", "*=", "/=", "%=", "&=", "|=", "^=", ".*"};
    for (const char* p : longer)
        if (s.compare(i, std::char_traits<char>::length(p), p) == 0) return std::char_traits<char>::length(p);
    return 1;
}

std::vector<Token> tokenize(const std::string& s) {
    std::vector<Token> tokens;
    int line = 1;
    bool line_start = true;
    for (std::size_t i = skip_blank(s, 0, line, line_start); i < s.size(); i = skip_blank(s, i, line, line_start)) {
        line_start = false;
        const char c = s[i];
        std::size_t end;
        Kind kind;
        if (ident_char(c) && !std::isdigit(static_cast<unsigned char>(c))) {
            end = i;
            while (end < s.size() && ident_char(s[end])) ++end;
            const std::string word = s.substr(i, end - i);
            const bool prefix = end < s.size() && (s[end] == '"' || s[end] == '\'') &&
                                (word == "u8" || word == "u" || word == "U" || word == "L" || word == "R" ||
                                 word == "u8R" || word == "uR" || word == "UR" || word == "LR");
            if (prefix)
                end = literal_end(s, word.back() == 'R' ? end - 1 : end), kind = Kind::text;
            else
                kind = is_keyword(word) ? Kind::keyword : Kind::identifier;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            end = number_end(s, i), kind = Kind::number;
        } else if (c == '"' || c == '\'') {
            end = literal_end(s, i), kind = Kind::text;
        } else {
            end = i + punct_length(s, i), kind = Kind::punct;
        }
        const std::string text = s.substr(i, end - i);
        tokens.push_back({text, kind, line});
        line += static_cast<int>(std::count(text.begin(), text.end(), '\n'));
        i = end;
    }
    return tokens;
}

// ---- functions -------------------------------------------------------------------------------

struct Function {
    std::string name;
    std::size_t open = 0, close = 0;  // the body's braces
    std::size_t params = 0;           // the parameter list's "("
};

std::size_t matching_open(const std::vector<Token>& t, std::size_t close) {
    int depth = 0;
    for (std::size_t j = close + 1; j-- > 0;) {
        if (t[j].text == ")")
            ++depth;
        else if (t[j].text == "(" && --depth == 0)
            return j;
    }
    return std::string::npos;
}

// What the brace at i opens, at namespace scope: 'N' a namespace (or extern "C"), 'F' the body
// of a function (then *f is filled in), 'O' anything else.
char brace_kind(const std::vector<Token>& t, std::size_t i, Function* f) {
    std::size_t j = i;
    while (j > 0 && (t[j - 1].kind == Kind::identifier || t[j - 1].text == "::")) --j;
    if (j > 0 && (t[j - 1].text == "namespace" || (t[j - 1].kind == Kind::text && j > 1 && t[j - 2].text == "extern")))
        return 'N';
    // Back over what may follow a parameter list: const, noexcept, override, -> Type.
    static const std::set<std::string> trailing = {
        "const", "noexcept", "override", "final", "->", "::", "<", ">", "&", "&&", "*", ",", "volatile", "mutable"};
    for (j = i; j > 0; --j) {
        const Token& p = t[j - 1];
        if (p.text == ")") break;
        if (p.kind != Kind::identifier && !trailing.count(p.text) && p.kind != Kind::keyword) return 'O';
        if (p.text == "struct" || p.text == "class" || p.text == "enum" || p.text == "union" || p.text == "namespace")
            return 'O';
    }
    if (j == 0) return 'O';
    const std::size_t open = matching_open(t, j - 1);
    if (open == std::string::npos || open == 0 || t[open - 1].kind != Kind::identifier) return 'O';
    f->name = t[open - 1].text, f->params = open, f->open = i;
    return 'F';
}

// The functions defined at namespace scope, with their bodies' token ranges.
std::vector<Function> functions(const std::vector<Token>& t) {
    std::vector<Function> found;
    std::vector<std::pair<char, std::size_t>> stack;  // what each open brace is, and where the function is in found
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i].text == "{") {
            const bool outside = std::all_of(stack.begin(), stack.end(), [](const auto& e) { return e.first == 'N'; });
            Function f;
            const char kind = outside ? brace_kind(t, i, &f) : 'O';
            if (kind == 'F') found.push_back(f);
            stack.push_back({kind, found.size() - 1});
        } else if (t[i].text == "}" && !stack.empty()) {
            if (stack.back().first == 'F') found[stack.back().second].close = i;
            stack.pop_back();
        }
    }
    found.erase(std::remove_if(found.begin(), found.end(), [](const Function& f) { return f.close == 0; }),
                found.end());
    return found;
}

// ---- normalisation -----------------------------------------------------------------------------

// Whether p can end a type: a name, a built-in type, or (with_punct) ">", "&", "*" and "&&".
bool type_like(const Token& p, bool with_punct) {
    static const std::set<std::string> builtin = {"auto", "bool",  "char",   "double",   "float", "int",
                                                  "long", "short", "signed", "unsigned", "void"};
    static const std::set<std::string> punct = {">", "&", "*", "&&"};
    return p.kind == Kind::identifier || builtin.count(p.text) > 0 || (with_punct && punct.count(p.text) > 0);
}

// The names this file chooses itself: its helper functions, parameters, variables and types.
// They become one placeholder, so that renaming them changes nothing. Names it uses but does not
// declare (the API's, the standard library's, Eigen's members) are kept: a copy cannot change them.
std::set<std::string> declared_names(const std::vector<Token>& t, const std::vector<Function>& fns,
                                     const std::set<std::string>& api) {
    std::set<std::string> names;
    for (const auto& f : fns) {
        if (!api.count(f.name)) names.insert(f.name);
        int depth = 0;
        for (std::size_t j = f.params; j < f.open; ++j) {
            depth += t[j].text == "(" ? 1 : t[j].text == ")" ? -1 : 0;
            if (depth == 1 && t[j].kind == Kind::identifier && j + 1 < t.size() &&
                (t[j + 1].text == "," || t[j + 1].text == ")" || t[j + 1].text == "="))
                names.insert(t[j].text);
        }
    }
    static const std::set<std::string> after = {"=", ";", "{", ",", ":", "["};
    for (std::size_t j = 1; j + 1 < t.size(); ++j) {
        if (t[j].kind != Kind::identifier) continue;
        const Token &p = t[j - 1], &n = t[j + 1];
        // "Vec3 v = ...", "Vec3& v;", and "Vec3 v(...)" (but not "s * hat(u)", which is a call).
        const bool variable = (type_like(p, true) && after.count(n.text)) || (type_like(p, false) && n.text == "(");
        const bool more = p.text == "," && (n.text == "=" || n.text == ";");
        const bool type =
            p.text == "struct" || p.text == "class" || p.text == "enum" || (p.text == "using" && n.text == "=");
        if ((variable || more || type) && !api.count(t[j].text)) names.insert(t[j].text);
    }
    return names;
}

// One token as compared: keywords and punctuation as they are, declared names as "#" (but a
// member or qualified name, after ".", "->" or "::", as it is), every number as "0", every
// string or character as "\"\"".
std::string normal(const Token& token, const Token* before, const std::set<std::string>& declared) {
    const bool member = before && (before->text == "." || before->text == "->" || before->text == "::");
    switch (token.kind) {
        case Kind::number:
            return "0";
        case Kind::text:
            return "\"\"";
        case Kind::identifier:
            return declared.count(token.text) && !member ? "#" : token.text;
        default:
            return token.text;
    }
}

// ---- fingerprints ------------------------------------------------------------------------------

struct Code {
    std::vector<std::string> tokens;  // normalised
    std::vector<int> lines;           // of each token in its file
};

struct Print {
    std::uint64_t hash;
    std::size_t at;  // the k-gram's first token in its Code
};

std::vector<std::uint64_t> kgram_hashes(const Code& code) {
    std::vector<std::uint64_t> hashes;
    for (std::size_t i = 0; i + K <= code.tokens.size(); ++i) {
        std::string gram;
        for (std::size_t k = 0; k < K; ++k) gram += code.tokens[i + k] + '\x1f';
        hashes.push_back(hash(gram));
    }
    return hashes;
}

// Winnowing: the smallest hash of every window of W k-grams (the rightmost when tied), each
// position once; k-grams whose hash is in `base` (the stubs' code) are never chosen.
std::vector<Print> winnow(const Code& code, const std::set<std::uint64_t>& base) {
    const std::vector<std::uint64_t> h = kgram_hashes(code);
    std::vector<Print> prints;
    const std::size_t window = std::min(W, h.size());
    for (std::size_t start = 0; window > 0 && start + window <= h.size(); ++start) {
        std::size_t best = std::string::npos;
        for (std::size_t j = start; j < start + window; ++j)
            if (!base.count(h[j]) && (best == std::string::npos || h[j] <= h[best])) best = j;
        if (best != std::string::npos && (prints.empty() || prints.back().at != best))
            prints.push_back({h[best], best});
    }
    return prints;
}

// One side of a comparison: normalised code, its fingerprints and their distinct hashes.
struct Part {
    Code code;
    std::vector<Print> prints;
    std::set<std::uint64_t> hashes;
};

Part make_part(Code code, const std::set<std::uint64_t>& base) {
    Part p;
    p.code = std::move(code);
    p.prints = winnow(p.code, base);
    for (const auto& f : p.prints) p.hashes.insert(f.hash);
    return p;
}

void append_body(Code& code, const std::vector<Token>& t, const Function& f, const std::set<std::string>& declared) {
    for (std::size_t j = f.open + 1; j < f.close; ++j) {
        if (t[j].text == "std" && j + 1 < f.close && t[j + 1].text == "::") {  // std::cos and cos are one
            ++j;
            continue;
        }
        code.tokens.push_back(normal(t[j], &t[j - 1], declared));
        code.lines.push_back(t[j].line);
    }
}

// An exercise's code: the body of its function, then of every helper of the file it calls
// (directly or not); other exercises it calls are compared on their own.
Code exercise_code(const std::vector<Token>& t, const std::vector<Function>& fns, const std::string& exercise,
                   const std::set<std::string>& api, const std::set<std::string>& declared) {
    Code code;
    std::set<std::string> taken;
    std::vector<std::string> queue = {exercise};
    while (!queue.empty()) {
        const std::string name = queue.back();
        queue.pop_back();
        if (!taken.insert(name).second) continue;
        for (const auto& f : fns) {
            if (f.name != name) continue;
            append_body(code, t, f, declared);
            for (std::size_t j = f.open + 1; j < f.close; ++j)
                if (t[j].kind == Kind::identifier && !api.count(t[j].text)) queue.push_back(t[j].text);
        }
    }
    return code;
}

struct Analysed {
    std::map<std::string, Part> exercises;
    Part file;  // every function of the file
};

Analysed analyse(const std::string& source, const std::set<std::string>& api, const std::set<std::uint64_t>& base) {
    const std::vector<Token> t = tokenize(source);
    const std::vector<Function> fns = functions(t);
    const std::set<std::string> declared = declared_names(t, fns, api);
    Analysed a;
    Code all;
    for (const auto& f : fns) append_body(all, t, f, declared);
    a.file = make_part(all, base);
    for (const auto& name : api) a.exercises[name] = make_part(exercise_code(t, fns, name, api, declared), base);
    return a;
}

// Every k-gram hash of the stub's code: what every submission starts from, never a match.
std::set<std::uint64_t> base_hashes(const std::string& stub, const std::set<std::string>& api) {
    const Analysed a = analyse(stub, api, {});
    std::set<std::uint64_t> base;
    for (const auto& h : kgram_hashes(a.file.code)) base.insert(h);
    return base;
}

std::size_t shared_count(const Part& a, const Part& b) {
    std::size_t n = 0;
    for (const auto h : a.hashes) n += b.hashes.count(h);
    return n;
}

double score_of(const Part& a, const Part& b) {
    const std::size_t smaller = std::min(a.hashes.size(), b.hashes.size());
    return smaller ? static_cast<double>(shared_count(a, b)) / static_cast<double>(smaller) : 0;
}

// The lines of `a` that its fingerprints shared with `b` cover, as ranges: "3-7, 10".
std::string shared_lines(const Part& a, const Part& b) {
    std::set<int> lines;
    for (const auto& f : a.prints)
        if (b.hashes.count(f.hash))
            for (std::size_t k = f.at; k < f.at + K && k < a.code.lines.size(); ++k) lines.insert(a.code.lines[k]);
    std::string out;
    for (auto it = lines.begin(); it != lines.end();) {
        int last = *it;
        auto next = std::next(it);
        while (next != lines.end() && *next == last + 1) last = *next++;
        out += (out.empty() ? "" : ", ") + std::to_string(*it) + (last > *it ? "-" + std::to_string(last) : "");
        it = next;
    }
    return out;
}

struct Candidate {
    std::string name;  // "" for the reference
    Analysed code;
};

// The hits of one pair of files, exercise by exercise.
void compare(const Topic& topic, const Candidate& a, const Candidate& b, bool all, std::vector<SimilarityHit>& hits) {
    const double file_score = score_of(a.code.file, b.code.file);
    for (const auto& e : topic.exercises) {
        const Part& pa = a.code.exercises.at(e.name);
        const Part& pb = b.code.exercises.at(e.name);
        const std::size_t shared = shared_count(pa, pb);
        const double score = score_of(pa, pb);
        const std::size_t shorter = std::min(pa.code.tokens.size(), pb.code.tokens.size());
        const bool alone = shorter >= kAlone && score >= kStrong;
        const bool listed = shared >= kMinShared && score >= kThreshold && (file_score >= kThreshold || alone);
        if (!listed && !(all && shared > 0)) continue;
        SimilarityHit h;
        h.listed = listed;
        h.topic = topic.name, h.exercise = e.name, h.student = a.name, h.other = b.name;
        h.score = score, h.file_score = file_score, h.shared = static_cast<int>(shared);
        h.fingerprints = static_cast<int>(pa.hashes.size()), h.other_fingerprints = static_cast<int>(pb.hashes.size());
        h.tokens = static_cast<int>(pa.code.tokens.size());
        h.lines = shared_lines(pa, pb), h.other_lines = shared_lines(pb, pa);
        hits.push_back(h);
    }
}

}  // namespace

std::vector<SimilarityHit> find_similar(const Setup& setup, const std::vector<ClassFiles>& files, bool all) {
    std::vector<SimilarityHit> hits;
    for (std::size_t k = 0; k < setup.topics.size(); ++k) {
        const Topic& topic = setup.topics[k];
        std::set<std::string> api;
        for (const auto& e : topic.exercises) api.insert(e.name);
        const std::set<std::uint64_t> base = base_hashes(read_file(pristine_stub(setup, topic.name)), api);
        std::vector<Candidate> candidates;
        bool ok = false;
        const std::string reference = read_file(setup.root + "/solutions/" + topic.name + ".cpp", &ok);
        if (ok) candidates.push_back({"", analyse(reference, api, base)});
        for (const auto& student : files)
            if (k < student.files.size() && student.files[k].state == "ok")
                candidates.push_back({student.student, analyse(student.files[k].content, api, base)});
        for (std::size_t i = 0; i < candidates.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)  // the reference (j == 0) or an earlier submission
                if (!candidates[i].name.empty()) compare(topic, candidates[i], candidates[j], all, hits);
    }
    return hits;
}

namespace {

std::string percent(double x) { return std::to_string(static_cast<int>(x * 100 + 0.5)) + "%"; }

std::string match_name(const SimilarityHit& h) { return h.other.empty() ? "solutions/" + h.topic + ".cpp" : h.other; }

bool matches_reference(const std::vector<SimilarityHit>& hits, const std::string& student,
                       const std::string& exercise) {
    return std::any_of(hits.begin(), hits.end(), [&](const SimilarityHit& h) {
        return h.other.empty() && h.student == student && h.exercise == exercise;
    });
}

// One line per flagged submission: how many exercises match the reference, and whom else.
std::string flagged_table(const std::vector<SimilarityHit>& hits) {
    std::map<std::string, std::pair<int, std::map<std::string, int>>> by;
    for (const auto& h : hits) {
        if (h.other.empty())
            ++by[h.student].first;
        else
            ++by[h.student].second[h.other], ++by[h.other].second[h.student];
    }
    std::string out =
        "| Submission | Exercises that match the reference | Submissions it matches (exercises) |\n|---|---:|---|\n";
    for (const auto& [student, row] : by) {
        std::string others;
        for (const auto& [other, n] : row.second)
            others += (others.empty() ? "" : ", ") + other + " (" + std::to_string(n) + ")";
        out += "| " + replace_all(student, "|", "\\|") + " | " + std::to_string(row.first) + " | " +
               replace_all(others, "|", "\\|") + " |\n";
    }
    return out;
}

std::string exercise_section(const Setup& setup, const Topic& topic, const Exercise& e,
                             const std::vector<SimilarityHit>& hits) {
    const Chapter* c = find_chapter(setup, topic.chapter);
    std::string rows;
    int explained = 0;
    for (const auto& h : hits) {
        if (h.topic != topic.name || h.exercise != e.name) continue;
        if (!h.other.empty() && matches_reference(hits, h.student, e.name) &&
            matches_reference(hits, h.other, e.name)) {
            ++explained;  // both are the reference's: the pair says nothing more
            continue;
        }
        rows += "| " + replace_all(h.student, "|", "\\|") + " | " + replace_all(match_name(h), "|", "\\|") + " | " +
                percent(h.score) + " | " + percent(h.file_score) + " | " + std::to_string(h.shared) + " of " +
                std::to_string(std::min(h.fingerprints, h.other_fingerprints)) + " | " + h.lines + " | " +
                h.other_lines + " |\n";
    }
    if (rows.empty() && explained == 0) return {};
    std::string out = "\n## `" + e.name + "` (" + (c ? "Chapter " + std::to_string(c->number) : topic.chapter) +
                      ", exercises/" + topic.name + ".cpp)\n\n";
    if (!rows.empty())
        out +=
            "| Submission | Matches | Score | Whole file | Shared fingerprints | Its lines | Their lines |\n"
            "|---|---|---:|---:|---:|---|---|\n" +
            rows;
    if (explained)
        out += "\n" + std::to_string(explained) +
               " more pairs of submissions match each other because both match the "
               "reference; they are listed in `similarity.csv`.\n";
    return out;
}

}  // namespace

std::string similarity_markdown(const Setup& setup, const std::vector<SimilarityHit>& hits, std::size_t submissions) {
    char method[900];
    std::snprintf(
        method, sizeof method,
        "Each exercise's code (its function and the helpers it calls) is compared with the reference solution "
        "and with every other submission after the names it declares, whitespace, comments and literals are "
        "normalised away: winnowed fingerprints of %zu-token k-grams, window %zu, as MOSS computes them; code "
        "the stubs already hold is ignored. *Score*: the share of the smaller set of fingerprints found in the "
        "other. A pair is listed for an exercise at %s or more (at least %zu fingerprints shared) when the *whole "
        "file* matches at %s too, or when the exercise alone scores %s or more and is at least %zu tokens long: "
        "a contract leaves few ways to write a short function, so one moderate match alone is no evidence. A "
        "listing is a reason to look, not a verdict: it changes no grade.\n",
        K, W, percent(kThreshold).c_str(), kMinShared, percent(kThreshold).c_str(), percent(kStrong).c_str(), kAlone);
    std::string out = "# Similarity\n\n" + std::to_string(submissions) + " submissions compared.\n\n" + method;
    if (hits.empty()) return out + "\nNo submission matches the reference solution or another submission.\n";
    out += "\n## Submissions listed\n\n" + flagged_table(hits);
    for (const auto& topic : setup.topics)
        for (const auto& e : topic.exercises) out += exercise_section(setup, topic, e, hits);
    return out;
}

std::string similarity_csv(const std::vector<SimilarityHit>& hits) {
    auto field = [](const std::string& s) {
        return s.find_first_of(",\"\n") == std::string::npos ? s : "\"" + replace_all(s, "\"", "\"\"") + "\"";
    };
    std::string out =
        "topic,exercise,submission,matches,score,whole_file_score,shared_fingerprints,"
        "submission_fingerprints,match_fingerprints,submission_tokens,submission_lines,match_lines\n";
    for (const auto& h : hits) {
        char scores[64];
        std::snprintf(scores, sizeof scores, "%.2f,%.2f", h.score, h.file_score);
        out += h.topic + "," + h.exercise + "," + field(h.student) + "," + field(match_name(h)) + "," + scores + "," +
               std::to_string(h.shared) + "," + std::to_string(h.fingerprints) + "," +
               std::to_string(h.other_fingerprints) + "," + std::to_string(h.tokens) + "," + field(h.lines) + "," +
               field(h.other_lines) + "\n";
    }
    return out;
}

}  // namespace grading
