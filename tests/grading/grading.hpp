// The grading run: the instructor's batch grading of a class (`cmake/workbook grade`) and the
// student's own check (`cmake/workbook check`). Both grade with the same code, so they reach
// the same verdicts.
//
// What is graded comes from the build: grading/topics.txt (written by CMake from the
// workbook_topic / workbook_grader declarations) and grading/manifest.txt (every exercise and
// test, listed from the reference graders). A submission is a folder of exercises/<topic>.cpp
// files. Each topic file is compiled alone, with the exact flags of the build, and linked with
// the instructor's prebuilt objects: the grader's tests, the doctest main and the reference
// libraries of the topic's dependencies, and the topic's recorder. Every test then runs in its
// own sandboxed process, which only records what the student's functions returned; its verdict
// comes from the trusted replay binary, which runs the same test on that record (api.cpp,
// replay/), and from how the student's process ended.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace grading {

inline constexpr const char* harness_version = "workbook_grade 1";

// ---- text and files (util.cpp) ----------------------------------------------------------
std::string read_file(const std::string& path, bool* ok = nullptr);
bool write_file(const std::string& path, const std::string& text);  // via a temporary + rename
std::vector<std::string> split(const std::string& s, char separator);
std::string trim(const std::string& s);
bool starts_with(const std::string& s, const std::string& prefix);
bool ends_with(const std::string& s, const std::string& suffix);
std::string replace_all(std::string s, const std::string& from, const std::string& to);
// JSON through nlohmann-json: indented, UTF-8 as is (invalid UTF-8 becomes U+FFFD), a final newline.
std::string json_text(const nlohmann::ordered_json& j);
double json_number(double x);         // rounded to 4 decimals, as format_number shows it
std::string format_number(double x);  // at most 4 decimals, no trailing zeros
std::string first_lines(const std::string& s, std::size_t max_chars);
std::uint64_t hash(const std::string& data, std::uint64_t seed = 0xcbf29ce484222325ULL);
std::string hex(std::uint64_t x);
bool make_dirs(const std::string& path);
void remove_tree(const std::string& path);
bool is_directory(const std::string& path);                  // a real folder, not a symbolic link to one
std::vector<std::string> list_dir(const std::string& path);  // sorted names, without . and ..
std::vector<std::string> shell_split(const std::string& command);

// ---- running a program under limits (sandbox.cpp) -----------------------------------------
struct Limits {
    double wall_seconds = 10;              // killed (the whole process group) after this
    long memory_mb = 1024;                 // address space
    long output_bytes = 1 << 20;           // any file it writes, its output included
    bool forbid_processes = true;          // no fork, no threads (RLIMIT_NPROC 0)
    bool isolate = false;                  // in the sandbox (see configure_sandbox)
    std::vector<std::string> environment;  // more NAME=value for the program
};

// The sandbox of a student's test process (sandbox.cpp). With bubblewrap: new user, PID,
// mount, network, IPC and UTS namespaces; only /usr (read-only), a fresh /proc and /dev, an
// empty size-limited /work as its working folder and the test binary itself (a copy, read-only)
// are visible; no capabilities; no new processes (RLIMIT_NPROC 0 inside); and everything it
// starts dies with it. Started as root, it first becomes the unprivileged user nobody (65534).
// Without a working bubblewrap: as nobody when root, with the limits alone otherwise.
enum class Isolation { namespaces, user, limits_only };
// Probes what works here (once per run); returns a sentence for the log.
std::string configure_sandbox();
Isolation isolation();

struct Outcome {
    bool started = false;
    bool timed_out = false;
    int signal = 0;      // the signal that ended it, 0 if it exited
    int exit_code = -1;  // when it exited
    double seconds = 0;
    std::string error;  // why it could not start
};

// Runs argv[0] with stdin from /dev/null and stdout and stderr into output_path. With a
// report, the program also gets a pipe as file descriptor 3 (/dev/fd/3), read into *report
// while it runs (up to report_limit bytes; *report_overflow tells when more came): outside the
// output limit, and in no file the program could name. With limits.isolate it runs in the
// sandbox, and cwd only matters without namespaces.
Outcome run_limited(const std::vector<std::string>& argv, const std::string& cwd, const std::string& output_path,
                    const Limits& limits, std::string* report = nullptr, std::size_t report_limit = 64u << 20,
                    bool* report_overflow = nullptr);
std::string signal_name(int signal);
// For a worker: SIGINT, SIGTERM or SIGHUP kills the process group run_limited is waiting for
// (a compiler and its cc1plus, or a test and its sandbox), then ends the worker.
void stop_children_on_signal();

// ---- what is graded (setup.cpp) ------------------------------------------------------------
struct Test {
    std::string name;
    int line = 0;
};

struct Exercise {
    std::string name;
    double points = 1;
    std::vector<Test> tests;
};

struct Chapter {
    std::string label;  // ch01
    int number = 0;     // 1
    std::string slug;   // 01_pure_rotations
    std::string title;  // Pure rotations
};

struct Topic {
    std::string name, chapter;
    std::string test_file;  // tests/<topic>_test.cpp, relative to the root
    std::vector<Exercise> exercises;
    std::string reference;              // the reference grader binary
    std::vector<std::string> objects;   // the grader's compiled tests
    std::vector<std::string> link;      // what a student's object is linked with
    std::vector<std::string> compile;   // compile command; @SOURCE@ and @OBJECT@ to fill in
    std::string replay;                 // the trusted verdict binary (no student code)
    std::vector<std::string> recorder;  // objects linked into a student's test binary
    std::vector<std::string> wraps;     // -Wl,--wrap=<symbol>, one per API function the grader calls
};

struct Setup {
    std::string dir, root, build, compiler, nm;
    std::vector<std::string> link_flags;
    std::vector<Chapter> chapters;
    std::vector<Topic> topics;
    std::string manifest_text;
    std::string fingerprint;  // of everything on the instructor's side
};

// Writes the manifest from topics.txt (build time). Returns an empty string or the error.
std::string make_manifest(const std::string& topics_path, const std::string& points_path, const std::string& out_path);
// Writes <out_dir>/record_<topic>.cpp, replay_<topic>.cpp and wrap_<topic>.txt (build time, api.cpp).
std::string make_api(const std::string& topic, const std::string& nm, const std::string& library,
                     const std::vector<std::string>& objects, const std::string& out_dir);
// Reads <dir>/topics.txt and <dir>/manifest.txt. Returns an empty string or the error.
std::string load_setup(const std::string& dir, Setup& setup);
const Chapter* find_chapter(const Setup& setup, const std::string& label);
// The topic's stub as committed, never the student's edited file (pristine.cpp).
std::string pristine_stub(const Setup& setup, const std::string& topic);
std::string relative_to_root(const Setup& setup, std::string text);

// ---- grading one submission (grade.cpp) ------------------------------------------------------
struct Options {
    Limits test_limits;
    Limits build_limits{120, 4096, 256L << 20, false, false, {}};
    long max_file_bytes = 1 << 20;
    bool keep_work = false;
    // The mutation gate's (tests/grading/mutants/): NAME=VALUE pairs added to each test's
    // environment, and a folder of compiled objects keyed by the source and the compile command,
    // so that one file graded many times is compiled once.
    std::vector<std::string> test_environment;
    std::string object_cache;
};

// One topic's file as found in a submission.
struct SubmittedFile {
    std::string topic;
    std::string state;   // "ok", "missing" or "refused"
    std::string reason;  // why it is missing or refused
    std::string content;
};

// The submission's own folder of .cpp files: <dir>/exercises/ when there is one, else <dir>.
std::string exercise_folder(const std::string& dir);
std::vector<SubmittedFile> collect_files(const Setup& setup, const Options& options, const std::string& dir);
std::string fingerprint(const Setup& setup, const Options& options, const std::vector<SubmittedFile>& files,
                        const std::string& selection);

struct TestResult {
    std::string chapter, topic, exercise, name;
    std::string verdict;  // pass, fail, timeout, crash, build error, missing
    double score = 0, max_score = 0;
    bool not_started = false;  // failed on the stub's todo("<exercise>")
    std::string message;       // why it did not pass (for the student)
    std::string output;        // what the test printed, truncated
};

struct SubmissionResult {
    std::string student;
    std::string fingerprint;
    std::string json_hash;  // of the results .json it was written with (from the .tsv)
    std::vector<TestResult> tests;
    std::vector<std::string> notes;  // one line per topic that did not build, or was refused
    double score = 0, max_score = 0;
};

// A selection: topics, and optionally one exercise, to grade (empty: everything).
struct Selection {
    std::set<std::string> topics;
    std::string exercise;
    std::string key() const;
};

SubmissionResult grade_submission(const Setup& setup, const Options& options, const std::string& student,
                                  const std::vector<SubmittedFile>& files, const Selection& selection,
                                  const std::string& work_dir, const std::string& log_dir);

std::string results_json(const Setup& setup, const SubmissionResult& result);
// The completion marker: every verdict and score, and the hash of the results .json written with it.
std::string results_tsv(const SubmissionResult& result, const std::string& json = "");
bool read_results_tsv(const std::string& path, SubmissionResult& result);

// ---- similarity (similarity.cpp) ----------------------------------------------------------------
// Code that matches the reference solution or another submission, exercise by exercise, after
// names, whitespace, comments and literals are normalised (winnowed token fingerprints, as MOSS).
struct ClassFiles {
    std::string student;
    std::vector<SubmittedFile> files;  // one per topic of the setup, as collect_files returns them
};

struct SimilarityHit {
    std::string topic, exercise, student;
    std::string other;                 // a submission, or "" for the reference solution
    double score = 0, file_score = 0;  // shared / the smaller fingerprint set, for the exercise and the whole file
    int shared = 0, fingerprints = 0, other_fingerprints = 0, tokens = 0;
    std::string lines, other_lines;  // the lines the shared fingerprints cover, on each side
    bool listed = true;              // false: below the report's rules (returned only with `all`)
};

// The pairs the report lists; with `all`, every pair that shares a fingerprint (for measuring).
// The writers below take listed hits only.
std::vector<SimilarityHit> find_similar(const Setup& setup, const std::vector<ClassFiles>& files, bool all = false);
std::string similarity_markdown(const Setup& setup, const std::vector<SimilarityHit>& hits, std::size_t submissions);
std::string similarity_csv(const std::vector<SimilarityHit>& hits);

// ---- reports (report.cpp) -------------------------------------------------------------------
std::string class_csv(const Setup& setup, const std::vector<SubmissionResult>& results);
std::string class_summary(const Setup& setup, const std::vector<SubmissionResult>& results,
                          const std::vector<std::string>& ignored);
// The total scores for an LMS's gradebook import (gradebook.cpp): Canvas and Moodle.
std::string canvas_csv(const std::vector<SubmissionResult>& results, const std::string& assignment);
std::string moodle_csv(const std::vector<SubmissionResult>& results, const std::string& assignment);
// The student's view: progress per chapter, the first exercise that does not pass, its hint.
// Returns true when every selected exercise passes.
bool print_check(const Setup& setup, const SubmissionResult& result, const std::string& folder);
std::string hint_for(const Setup& setup, const std::string& exercise);

}  // namespace grading
