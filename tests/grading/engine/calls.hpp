// Which exercises an exercise's reference calls: read from the code of solutions/<topic>.cpp, with
// comments, literals and # lines masked out. Written once, here, for every reader: the grading
// manifest's `uses` lines (so that a failure caused by another exercise of the student's names it:
// report.cpp), the mutation gate (which mutates the same function bodies) and the catalogue of
// likely mistakes (which names no mistake while an exercise it uses fails).
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace grading::calls {

// A mask over the text: false inside comments, string and character literals and # lines.
std::vector<bool> code_mask(const std::string& s);

// A function defined at namespace level: the positions of its braces, its name and its header.
struct Body {
    std::size_t begin, end;
    std::string name, header;
};
// Every function body at namespace level, in order. Unbalanced braces: an empty list and *error.
std::vector<Body> function_bodies(const std::string& s, const std::vector<bool>& code, std::string* error = nullptr);

// For each of `exercises` defined in `source`, the others of `exercises` its body calls, directly
// or through the file's helpers (an exercise with none is left out).
std::map<std::string, std::set<std::string>> uses_of(const std::string& source, const std::set<std::string>& exercises);

}  // namespace grading::calls
