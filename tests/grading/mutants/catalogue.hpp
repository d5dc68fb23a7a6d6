// The catalogue of likely mistakes (tests/grading/engine/mistakes.hpp), made from a run of the mutation
// gate: workbook_mutants catalogue and workbook_mutants stale (mutants.cpp's commands).
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace mutants {

// A mutant as the gate lists it (its place and change), without its source.
struct Listed {
    std::string id, topic, function, op;
    int line = 0;
    std::string before, after;
    bool exercise = false;
};

// The mistake in the student's terms, from the operator and the changed expression, e.g.
// "in compose: `.transpose()` dropped from `R.transpose() * v`".
std::string describe(const Listed& m);

// The hash of what a topic's catalogue comes from: the solution, its graders and their helpers,
// the API header, the topic's lines of the manifest and the gate's mutants of the solution.
std::string topic_hash(const std::string& root, const std::string& manifest, const std::string& topic,
                       const std::vector<Listed>& mutants);

// Writes <catalogue>/<topic>.json for each topic of `mutants` from the gate's run in `gate_out`
// (mutants.json, checks/<id>/results.json). Returns 0, or 2 with a message on stderr.
// `uses`: topic -> exercise -> the other exercises its reference calls.
int write_catalogue(const std::string& root, const std::string& manifest, const std::string& gate_out,
                    const std::string& catalogue, const std::vector<Listed>& mutants,
                    const std::map<std::string, std::map<std::string, std::set<std::string>>>& uses);

// 0 when every topic's catalogue in `catalogue` has the hash of this tree (1 when one is stale,
// naming it and the command that makes it again; 2 when one cannot be read).
int check_fresh(const std::string& root, const std::string& manifest, const std::string& catalogue,
                const std::vector<Listed>& mutants);

}  // namespace mutants

namespace mutants {

// The zero-false-naming audit: every results .json in `results` (a grading run's results/) whose
// student is not in `may_name` (submissions that really are wrong answers) must carry no likely
// mistake, in its file and when matched again against `catalogue`. With `plant`, an entry whose
// signature is one of those results' failing exercises is added to the catalogue first (a
// planted fault: the audit must then fail). Returns 0 when none is named, 1 when one is (naming
// it), 3 when there is nothing to plant on.
// The measurement on a class of mutants (students named by mutant id, as the gate numbers them) and
// other submissions: how many mutants are named correctly, and whether any other is named.
int measure(const std::string& catalogue, const std::string& results);

int audit(const std::string& catalogue, const std::string& results, const std::vector<std::string>& may_name,
          bool plant);

}  // namespace mutants
