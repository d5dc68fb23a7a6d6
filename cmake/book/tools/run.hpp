// Starting a program: the one place the book's tools start one (pandoc, fc-list), through the
// workbook's support library (cmake/support/include/support/process.hpp): by its argument vector, never a
// shell.
#pragma once

#include <string>
#include <vector>

#include "support/process.hpp"

namespace book {

struct Output {
    int status;        // the exit status; -1 when it could not start or did not exit
    std::string text;  // what it wrote on stdout and stderr, interleaved
};

// Runs argv[0] (found on the PATH) with argv, and waits for it.
inline Output run(const std::vector<std::string>& argv) {
    support::RunOptions options;
    options.stderr_to_stdout = true;
    const support::Result r = support::run(argv, options);
    return {r.status, r.out + r.error};
}

}  // namespace book
