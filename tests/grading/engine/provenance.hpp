// Where a result came from (issue 33): the test environment every results/<student>.json (under
// extra_data.provenance, which Gradescope's results.json format documents as "extra data to be
// stored") and run.json carry, so that a regrade or a comparison across machines can be trusted.
//
//   compiler, compiler_path    CMake's CXX compiler as the build used it (id and version);
//   eigen, gsl, doctest        the Debian package and its version, from dpkg-query at build time;
//   commit, modified           `git rev-parse HEAD` of the workbook at build time ("unknown" outside
//                              git), and whether tracked files differed from it;
//   graders                    a hash of the manifest and of every topic's judge binary (the
//                              compiled graders: the same checkout path and build give the same);
//   grader_sources             a hash of the manifest and of every topic's tests/<topic>_test.cpp
//                              (the same on any machine with the same graders);
//   limits, limits_hash        the limits each test and compile ran under, and their hash.
// The first five come from <build>/grading/provenance.txt (tests/grading/engine/provenance.cmake). The
// seed (--seed) is not among them: it never goes into a results .json.
#pragma once

#include <nlohmann/json.hpp>

#include "grading.hpp"

namespace grading {

nlohmann::ordered_json provenance(const Setup& setup, const Options& options);

}  // namespace grading
