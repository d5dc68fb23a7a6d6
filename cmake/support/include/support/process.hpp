// Starting a program from an argument vector (posix_spawnp: the PATH is searched for argv[0]),
// never through a shell: no quoting, no word splitting, no expansion of what a path holds.
//
//   const support::Result r = support::run({"gnuplot", "-d", script});
//   if (r.status != 0) ... r.err ...
//
// The program's stdin is /dev/null. Its stdout and stderr are captured (Result::out, err),
// written to files, or, for stderr, sent where stdout goes.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace support {

struct Result {
    int status = -1;         // its exit status; 128 + the signal that ended it; -1: it did not start
    std::string out, err;    // what it wrote, when captured
    bool timed_out = false;  // killed (SIGKILL) at its timeout: status is then 128 + 9
    std::string error;       // why it did not start
};

struct RunOptions {
    double timeout = 0;             // seconds until it is killed; 0: it may take as long as it takes
    std::string stdout_file;        // empty: captured; else written there (created or truncated)
    std::string stderr_file;        // the same for stderr
    bool stderr_to_stdout = false;  // stderr goes where stdout goes (stderr_file then unused)
};

// Runs it to its end (or its timeout).
Result run(const std::vector<std::string>& argv, const RunOptions& options = {});

// Starts it and returns at once: its process id, or -1 with *error saying why. Nothing is
// captured: what options leave to capture goes to /dev/null.
pid_t spawn(const std::vector<std::string>& argv, const RunOptions& options = {}, std::string* error = nullptr);

// Waits for a process spawn() started, at most `seconds` (0: only looks): its status as
// Result::status says, or -1 while it still runs. Once it returned a status the process is gone.
int wait(pid_t pid, double seconds);

}  // namespace support
