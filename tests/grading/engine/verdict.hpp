// The verdicts of the grading run, named in one place: the words that results/<student>.json and
// .tsv, summary.md, the run's progress lines, the student's check and the mutation gate use.
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace grading {

// A test's verdict. not_started is an exercise's status alone: a test that failed on the stub's
// todo("<exercise>") keeps the verdict fail, with TestResult::not_started set.
enum class Verdict { pass, fail, timeout, crash, build_error, missing, not_started };

// A test's verdicts, in the order of summary.md's columns and the progress line's counts.
inline constexpr std::array<Verdict, 6> test_verdicts = {Verdict::pass,  Verdict::fail,        Verdict::timeout,
                                                         Verdict::crash, Verdict::build_error, Verdict::missing};

constexpr std::string_view name(Verdict v) {
    switch (v) {
        case Verdict::pass:
            return "pass";
        case Verdict::fail:
            return "fail";
        case Verdict::timeout:
            return "timeout";
        case Verdict::crash:
            return "crash";
        case Verdict::build_error:
            return "build error";
        case Verdict::missing:
            return "missing";
        case Verdict::not_started:
            return "not started";
    }
    return "?";
}

inline std::string to_string(Verdict v) { return std::string(name(v)); }

// The verdict a word names; false when it names none.
inline bool from_string(std::string_view word, Verdict& v) {
    for (const Verdict x : {Verdict::pass, Verdict::fail, Verdict::timeout, Verdict::crash, Verdict::build_error,
                            Verdict::missing, Verdict::not_started})
        if (name(x) == word) return v = x, true;
    return false;
}

}  // namespace grading
