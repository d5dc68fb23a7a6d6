// gnuplot scripts kept as text files and filled in at run time: the scenes' figures
// (chapters/kit/figure.hpp) and the grading run's class report (tests/grading/engine/class_report.cpp).
// A .gp file is embedded in its program at build time (workbook_embed_gnuplot,
// cmake/Workbook.cmake) as a Script; where the run decides (a title's number, a range, a file
// name, a list of curves), the text has a placeholder @name@ (letters, digits, _; not starting
// with a digit), a syntax gnuplot's own text never has.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace support {

// A gnuplot script embedded from its .gp file: the file's name (for messages) and its text.
struct Script {
    std::string_view name;
    std::string_view text;
};

// The values of a script's placeholders: {{"title", "..."}, {"xmax", "3.5"}}.
using Fill = std::vector<std::pair<std::string, std::string>>;

// `script`'s text with every @name@ replaced by its value (once: a value is not scanned again).
// Throws std::logic_error naming the script for a placeholder without a value, or a value
// without a placeholder. An '@' that does not open a placeholder (a gnuplot macro) stays, and so
// does a comment line (its first non-blank a '#'), which may name placeholders.
std::string filled(const Script& script, const Fill& values = {});

// A list placeholder's value: `clause` (a script of one line of gnuplot, after any comment lines;
// a plot's curve, say) filled once per item of `items`, the copies joined by `separator` on one
// line, as a plot command needs them. Empty for no items; throws std::logic_error as filled()
// does, and for a clause of more than one line.
std::string joined(const Script& clause, const std::vector<Fill>& items, const std::string& separator = ", ");

// gnuplot's way of writing a string literal: single quotes, inner quotes doubled.
std::string gnuplot_quoted(const std::string& text);

}  // namespace support
