// Starting a program: the one place the book's tools start one (pandoc, fc-list). By its argument
// vector, through posix_spawnp: never a shell. Kept to this one function so that it can later call
// the workbook's support library (cmake/tools/support/) instead.
#pragma once

#include <string>
#include <vector>

namespace book {

struct Output {
    int status;        // the exit status; -1 when it could not start or did not exit
    std::string text;  // what it wrote on stdout and stderr, interleaved
};

// Runs argv[0] (found on the PATH) with argv, and waits for it.
Output run(const std::vector<std::string>& argv);

}  // namespace book
