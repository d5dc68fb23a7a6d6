// The one grammar of the keys a user types: what a chapter, a topic or an exercise named on the
// command line means (`cmake/workbook check KEY`, `scenes CHAPTER`, `gradescope TOPIC...`), and
// which topics a student has started. Written once, here: the front door asks workbook_topics
// (a small program of its own, built in seconds, before any grader), and `workbook_grade check`
// reads the same key with the same code.
//
// What it reads was written by CMake when it configured the build folder, so it knows every
// chapter and topic before anything is built: <build>/grading/catalog.json (every topic with
// graders and its chapter, in the order of the contents; workbook_grading() in
// tests/grading/grading.cmake), the table of contents (<build>/contents.json) and the stubs as
// committed (<build>/pristine/exercises/, cmake/pristine_stubs.cmake), whose todo("<name>") calls
// name each topic's exercises. The stubs are read nowhere else.
#pragma once

#include <string>
#include <vector>

namespace grading {

struct CatalogChapter {
    std::string label;  // ch01
    int number = 0;     // 1
    std::string folder, title;
};

struct CatalogTopic {
    std::string name, chapter;           // rotation, ch01
    std::string stub;                    // its stub as committed (<build>/pristine/exercises/<name>.cpp)
    bool stub_from_git = true;           // false: no git, the stub is the tree's file as it was
    std::vector<std::string> exercises;  // the todo("<name>") of its stub, in order
};

struct Catalog {
    std::string root;  // the workbook
    std::vector<CatalogChapter> chapters;
    std::vector<CatalogTopic> topics;  // every topic with graders, in chapter order
};

// Reads <build>/grading/catalog.json and what it names. Returns an empty string or the error.
std::string load_catalog(const std::string& path, Catalog& catalog);

// The chapter a key names: its label (ch01), its folder (01_pure_rotations), its number (1) or
// its number in two digits (01); nullptr when none.
const CatalogChapter* chapter_of_key(const Catalog& catalog, const std::string& key);

// What a key names: a chapter (its topics), a topic, or an exercise (its topic, and the exercise).
struct KeySelection {
    std::vector<std::string> topics;
    std::string exercise;  // when the key is an exercise
    std::string what;      // "Chapter 1", "exercises/rotation.cpp", "the exercise hat"
};
// Returns an empty string, or the error that lists what a key can be.
std::string select_key(const Catalog& catalog, const std::string& key, KeySelection& selection);

// A topic is started when the student's file (<folder>/<topic>.cpp) differs from its stub as
// committed; without git (the stub is the tree's file), always.
bool started(const CatalogTopic& topic, const std::string& folder);

// Names joined by a separator; as one CMake list ("rotation;precession"): what CMake's list
// commands read as they are.
std::string joined(const std::vector<std::string>& names, const std::string& separator);
std::string cmake_list(const std::vector<std::string>& names);

}  // namespace grading
