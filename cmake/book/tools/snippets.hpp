// The checks of the prose that cmake/book/tools/snippets.cpp runs (its command line), each in its own
// translation unit: snippet_values.cpp (code snippets and value markers), numbers.cpp (numbers
// that look measured, sections named by number), names.cpp (names of code in the prose).
#pragma once

#include <filesystem>

#include "prose.hpp"

namespace snippets {

namespace fs = std::filesystem;

enum class Mode { check, check_values, update, diff };

// Checks (or refreshes) the quoted code and the value markers of every prose file.
//   runs:  the declared runs (check_values, update with values, diff)
//   smoke: the test suite's reports (check_values; may be null)
//   tree:  a build's figures (diff)
int snippets_and_values(const fs::path& root, Mode mode, const prose::Runs* runs, const fs::path* smoke,
                        const fs::path* tree);

int check_numbers(const fs::path& root);

int check_names(const fs::path& root);

}  // namespace snippets
