// The two sides of one topic's API in a graded test, generated at build time (workbook_api).
//
// The API functions are found, not listed: every function the grader's objects call (undefined
// there) that the topic's reference library defines. For each, from its mangled name and its
// demangled signature, the generator writes
//   judge_<topic>.cpp  the function as the trusted judge defines it: it sends the call's inputs
//                      to the student's process and returns what the student's function returned
//                      (remote/judge.hpp);
//   serve_<topic>.cpp  the table of the student's process: for each function's number, an entry
//                      that reads the inputs, calls the student's function and answers
//                      (remote/serve.hpp).
// A new topic or function is therefore graded with no change here; a type the wire cannot
// carry stops the build with a static_assert naming it (tests/grading/engine/remote/wire.hpp).
#include <cxxabi.h>

#include <cstdlib>
#include <map>
#include <set>

#include "grading.hpp"

namespace grading {

namespace {

std::string demangle(const std::string& symbol) {
    int status = 0;
    char* text = abi::__cxa_demangle(symbol.c_str(), nullptr, nullptr, &status);
    if (status != 0 || !text) return {};
    std::string out = text;
    std::free(text);
    return out;
}

// "rigid::f(A, B<C, D> const&)" -> name "rigid::f", parameters {"A", "B<C, D> const&"}.
bool parse_signature(const std::string& s, std::string& name, std::vector<std::string>& parameters) {
    int depth = 0;
    std::size_t open = std::string::npos;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '<')
            ++depth;
        else if (c == '>')
            --depth;
        else if (c == '(' && depth == 0) {
            open = i;
            break;
        }
    }
    if (open == std::string::npos || s.back() != ')') return false;
    name = s.substr(0, open);
    if (name.find("operator") != std::string::npos || name.find_first_of(" <>()") != std::string::npos) return false;
    const std::string inside = s.substr(open + 1, s.size() - open - 2);
    // The parameter list must close at the very end (no " const" of a member function).
    depth = 0;
    std::string current;
    for (const char c : inside) {
        if (c == '<' || c == '(') ++depth;
        if (c == '>' || c == ')') --depth;
        if (depth < 0) return false;
        if (c == ',' && depth == 0) {
            parameters.push_back(trim(current));
            current.clear();
        } else {
            current += c;
        }
    }
    if (depth != 0) return false;
    if (!trim(current).empty()) parameters.push_back(trim(current));
    return true;
}

// Lines of `nm -P` on the given files: (symbol, type).
std::string run_nm(const std::string& nm, const std::vector<std::string>& args, const std::string& scratch,
                   std::vector<std::pair<std::string, char>>& symbols) {
    std::vector<std::string> argv = {nm, "-P"};
    argv.insert(argv.end(), args.begin(), args.end());
    Limits limits;
    limits.cpu_seconds = 120, limits.wall_seconds = 1200;
    limits.memory_mb = 4096;
    limits.output_bytes = 256L << 20;
    limits.forbid_processes = false;
    const Outcome o = run_limited(argv, ".", scratch, limits);
    const std::string text = read_file(scratch);
    std::remove(scratch.c_str());
    if (!o.started || o.exit_code != 0) return "nm failed on " + args.back() + (o.error.empty() ? "" : ": " + o.error);
    for (const auto& line : split(text, '\n')) {
        const auto f = split(line, ' ');
        if (f.size() >= 2 && f[1].size() == 1 && !f[0].empty() && f[0].back() != ':')
            symbols.push_back({f[0], f[1][0]});
    }
    return {};
}

bool write_if_changed(const std::string& path, const std::string& text) {
    bool ok = false;
    if (read_file(path, &ok) == text && ok) return true;
    return write_file(path, text);
}

}  // namespace

namespace {

// An API function the graders call: its symbol, its qualified name and its parameter types.
struct Function {
    std::string symbol, name;
    std::vector<std::string> parameters;
};

// The functions the grader's objects call (undefined in them) and the reference library defines,
// found with nm. Returns an empty string or the error.
std::string called_functions(const std::string& topic, const std::string& nm, const std::string& library,
                             const std::vector<std::string>& objects, const std::string& out_dir,
                             std::vector<Function>& list) {
    std::vector<std::pair<std::string, char>> defined, used;
    const std::string scratch = out_dir + "/nm_" + topic + ".txt";
    if (auto e = run_nm(nm, {"--defined-only", library}, scratch, defined); !e.empty()) return e;
    std::vector<std::string> undefined = {"--undefined-only"};
    undefined.insert(undefined.end(), objects.begin(), objects.end());
    if (auto e = run_nm(nm, undefined, scratch, used); !e.empty()) return e;
    std::set<std::string> functions;
    for (const auto& [symbol, type] : defined)
        if (type == 'T' || type == 'W') functions.insert(symbol);
    std::set<std::string> called;
    for (const auto& [symbol, type] : used)
        if (type == 'U' && functions.count(symbol)) called.insert(symbol);
    if (called.empty()) return "the graders of " + topic + " call no function of " + library;
    for (const auto& symbol : called) {
        Function f{symbol, "", {}};
        const std::string signature = demangle(symbol);
        if (signature.empty() || !parse_signature(signature, f.name, f.parameters))
            return "the grader of " + topic + " calls " + (signature.empty() ? symbol : signature) +
                   ", which the grading run cannot send to a student's process (only free functions are supported)";
        list.push_back(f);
    }
    return {};
}

// The types of every call, found by the compiler: P<k>_<p> the parameters, R<k> the result.
std::string type_aliases(const std::vector<Function>& list) {
    std::string types = "namespace workbook_generated {\n";
    for (std::size_t k = 0; k < list.size(); ++k) {
        const Function& f = list[k];
        const std::string n = std::to_string(k);
        std::string declvals;
        for (std::size_t p = 0; p < f.parameters.size(); ++p) {
            types += "using P" + n + "_" + std::to_string(p) + " = " + f.parameters[p] + ";\n";
            declvals += std::string(p ? ", " : "") + "std::declval<P" + n + "_" + std::to_string(p) + ">()";
        }
        types += "using R" + n + " = decltype(" + f.name + "(" + declvals + "));  // " + f.symbol + "\n";
    }
    return types + "}  // namespace workbook_generated\n\n";
}

// The parameter list of call k ("P0_0 a0, P0_1 a1" when named), its arguments (", a0, a1") and
// its types for judge::call and serve::serve_call ("R0, P0_0, P0_1").
std::string parameters(std::size_t k, const Function& f, bool named) {
    std::string s;
    for (std::size_t p = 0; p < f.parameters.size(); ++p)
        s += std::string(p ? ", " : "") + "workbook_generated::P" + std::to_string(k) + "_" + std::to_string(p) +
             (named ? " a" + std::to_string(p) : "");
    return s;
}
std::string arguments(const Function& f) {
    std::string s;
    for (std::size_t p = 0; p < f.parameters.size(); ++p) s += ", a" + std::to_string(p);
    return s;
}
std::string type_list(std::size_t k, const Function& f) {
    std::string s = "workbook_generated::R" + std::to_string(k);
    for (std::size_t p = 0; p < f.parameters.size(); ++p)
        s += ", workbook_generated::P" + std::to_string(k) + "_" + std::to_string(p);
    return s;
}

}  // namespace

std::string make_api(const std::string& topic, const std::string& nm, const std::string& library,
                     const std::vector<std::string>& objects, const std::string& out_dir) {
    if (!make_dirs(out_dir)) return "cannot create " + out_dir;
    std::vector<Function> list;
    if (auto e = called_functions(topic, nm, library, objects, out_dir, list); !e.empty()) return e;
    const std::string head = "// Generated by `workbook_api` (tests/grading/engine/api.cpp) from the graders of " +
                             topic + " and its reference library. Do not edit.\n";
    const std::string types = type_aliases(list);
    std::string judge =
        head + "#include <utility>\n\n#include \"rigid/" + topic + ".hpp\"\n#include \"judge.hpp\"\n\n" + types;
    std::string serve =
        head + "#include <utility>\n\n#include \"rigid/" + topic + ".hpp\"\n#include \"serve.hpp\"\n\n" + types;
    judge += "namespace workbook_remote::judge {\nconst char* const api_names[] = {\n";
    for (const auto& f : list) judge += "    \"" + f.name + "\",\n";
    judge += "};\nconst std::uint32_t api_count = " + std::to_string(list.size()) +
             ";\n}  // namespace workbook_remote::judge\n\n";
    serve += "namespace {\n\n";
    std::string table;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const std::string n = std::to_string(k), R = "workbook_generated::R" + n;
        const Function& f = list[k];
        judge += "// " + f.symbol + "\n" + R + " " + f.name + "(" + parameters(k, f, true) +
                 ") {\n    return workbook_remote::judge::call<" + type_list(k, f) + ">(" + n + arguments(f) +
                 ");\n}\n\n";
        serve += "// " + f.name + "\nvoid entry_" + n +
                 "(const std::string& message, std::size_t at, std::uint32_t frame) {\n    "
                 "workbook_remote::serve::serve_call<" +
                 type_list(k, f) + ">(&" + f.name + ", message, at, frame);\n}\n\n";
        table += "    &entry_" + n + ",\n";
    }
    serve += "}  // namespace\n\nnamespace workbook_remote::serve {\nconst Entry api_table[] = {\n" + table +
             "};\nconst std::uint32_t api_count = " + std::to_string(list.size()) +
             ";\n}  // namespace workbook_remote::serve\n";
    if (!write_if_changed(out_dir + "/judge_" + topic + ".cpp", judge) ||
        !write_if_changed(out_dir + "/serve_" + topic + ".cpp", serve))
        return "cannot write into " + out_dir;
    return {};
}

}  // namespace grading
