// Likely mistakes, named (README.md, "Likely mistakes, named"): the catalogue of the mutation
// gate's killed mutants, each with its failure signature and a sentence in the student's terms,
// and the matching of a graded submission against it.
//
// A *signature* is an exercise's tests and, for each, "pass" or how it failed: the verdict fail
// and the failed check's first line with its numbers blanked (the grader's file and line stay),
// so that it does not depend on the graders' random inputs (--seed). Only an exercise whose
// tests all pass or fail is matched: a crash, a timeout, a build error, a missing file or a stub's
// todo(...) is never given a likely mistake, and the catalogue holds no mutant that did any of
// those. A match is said as a pattern ("this pattern of failures is what ... gives"), never as
// certain; when several mistakes share a signature all are named (up to kNamed, then "or n more").
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace grading {
struct SubmissionResult;
}

namespace grading::mistakes {

// One test's outcome, as results .json or a SubmissionResult holds it.
struct Outcome {
    std::string topic, exercise, test, verdict;
    bool not_started = false;
    std::string message;  // why it did not pass
};

// "pass", or "fail: <the failed check's first line, numbers blanked>"; "" when the test neither
// passed nor failed plainly (such an exercise is never matched).
std::string how(const Outcome& o);

using Signature = std::map<std::string, std::string>;  // test name -> how()

// One catalogued mistake: a killed mutant of an exercise.
struct Entry {
    std::string topic, exercise, mutant, mistake;
    Signature signature;
};

struct Catalogue {
    std::vector<Entry> entries;
    std::map<std::string, std::string> hashes;  // topic -> hash of the graders and solution it came from
    // "topic/exercise" -> the topic's other exercises its reference calls: while one of those does
    // not pass, the exercise is not named (its failures may be theirs)
    std::map<std::string, std::set<std::string>> uses;
    std::string error;  // a file that could not be read
};

// Every <topic>.json in `dir` (a missing folder is an empty catalogue).
Catalogue load(const std::string& dir);
// The catalogue the grading run uses: <root>/tests/grading/mutants/catalogue, read once.
const Catalogue& for_root(const std::string& root);
nlohmann::ordered_json to_json(const std::string& topic, const std::string& hash, const std::vector<Entry>& entries,
                               const std::map<std::string, std::set<std::string>>& uses);

// An exercise's signature; empty when it is not to be matched (it passes, or a test of it did
// something other than pass or fail, or it is not started).
Signature signature_of(const std::vector<Outcome>& outcomes, const std::string& topic, const std::string& exercise);

// A failing exercise whose signature is catalogued, with every mistake that gives it.
struct Named {
    std::string topic, exercise;
    std::vector<std::string> mistakes;  // sorted, distinct
    std::vector<std::string> mutants;   // the catalogue's mutants that give it
    std::string text() const;           // "This pattern of failures is what ... gives (a likely ...)"
};

std::vector<Named> name(const Catalogue& catalogue, const std::vector<Outcome>& outcomes);

std::vector<Outcome> outcomes_of(const SubmissionResult& result);
std::vector<Outcome> outcomes_of(const nlohmann::json& results);  // a results .json

// results .json's extra_data "likely_mistakes": [{"topic", "exercise", "mistakes": [...]}].
nlohmann::ordered_json to_json(const std::vector<Named>& named);
// The results .json with that field added (unchanged when nothing is named).
nlohmann::ordered_json with_likely_mistakes(nlohmann::ordered_json results, const std::vector<Named>& named);

// For the class report: each likely mistake (topic, exercise, sentence) and how many results
// in `results_dir` (results/<student>.json) name it.
struct ClassCount {
    std::string topic, exercise, mistake;
    int students = 0;
};
std::vector<ClassCount> count_in_class(const std::string& results_dir);

}  // namespace grading::mistakes
