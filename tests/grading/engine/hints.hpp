// The hint ladders of exercises/hints.md: the reader, the terminal printer and the rules a
// ladder must follow (README.md, "How to use it"; the format is in exercises/hints.md itself).
//
//   ### exercise_name          one section per exercise function
//   #### Hint 1                a nudge: which equation or property to use, no code of the answer
//   #### Hint 2                the approach
//   #### Hint 3                (optional) close to the answer
//
// Math is TeX between $...$, in a small subset (Greek letters, _ and ^, \cdot, \times, \tfrac,
// \sqrt, \sin, \cos, \top, \hat, \dot, \lVert...). The book renders it as MathML (pandoc); the
// terminal gets plain text with Unicode (plain_text). Written by hand: no Debian package turns
// TeX math into plain text (pandoc's plain writer keeps the TeX source of inline math).
#pragma once

#include <string>
#include <vector>

namespace hints {

struct Ladder {
    std::string exercise;
    int line = 0;                     // of its ### heading
    std::vector<std::string> levels;  // the Markdown of Hint 1, Hint 2 (and Hint 3)
};

struct Hints {
    std::vector<Ladder> ladders;
    std::string error;  // empty, or "<file>:<line>: what is wrong"
};

// Reads the ladders of a hints file; on a malformed file, `error` names the line and the rule.
Hints parse(const std::string& text, const std::string& file_name);
Hints read(const std::string& path);
const Ladder* find(const Hints& hints, const std::string& exercise);

// Markdown with TeX math -> terminal text: $\Omega_k = \tfrac{1}{2}\epsilon_{kij}W_{ij}$ becomes
// Ω_k = 1/2 ε_kij W_ij; **bold** loses its stars; code in backticks stays as it is.
std::string plain_text(const std::string& markdown);
// What of TeX is left in a terminal text (outside code in backticks): "" when nothing is.
std::string tex_left(const std::string& text);
// Why a level-1 hint holds code of the answer, or "" when it does not. The rule: in a nudge,
// a span in backticks may only name something (an identifier such as `rotation_about`, a
// qualified type such as `std::invalid_argument`, or a path such as `rigid/require.hpp`); any
// other span (operators, calls, literals: `R.transpose() * R_dot`) is code. Outside backticks
// and math, a code block, a call written as name(...), `return`, Eigen:: or the workbook's
// Eigen aliases, and C++ operators (<<, ==, ->, ::, ;) are code too. Math between $...$ is not
// code: a nudge may name the equation to use.
std::string code_in_nudge(const std::string& markdown);
// Every rule a ladder must follow: 2 or 3 levels, no TeX left in the terminal text, no code in
// Hint 1. Returns one line per problem.
std::vector<std::string> lint(const Ladder& ladder, const std::string& file_name);

// The text `check` prints: the level's terminal text, indented, with where it comes from and
// how to get the next level. Empty when the exercise has no such level.
std::string for_terminal(const Ladder& ladder, int level);

}  // namespace hints
