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
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "support/file.hpp"
#include "support/text.hpp"
#include "verdict.hpp"

namespace grading {

inline constexpr const char* harness_version = "workbook_grade 1";

// ---- text and files (util.cpp) ----------------------------------------------------------
// read_file, write_file (via a temporary + rename), split and trim: the support library's
// (cmake/support/), shared with the workbook's other programs.
using support::read_file;
using support::split;
using support::trim;
using support::write_file;
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
// Where a program runs: as it is (the workbook's own tools), as a student's process (Sandbox::
// test), or as a student's compile and link (Sandbox::build).
enum class Sandbox { none, test, build };

struct Bind {
    std::string source, target;  // a folder of the harness's, and where the sandbox sees it
    bool writable = false;
};

// A program's budget is processor time: RLIMIT_CPU, which each process counts for itself
// (SIGXCPU at cpu_seconds, SIGKILL a second later), so that a loaded machine, which stretches
// wall time, changes no verdict. The wall clock is only a backstop against a process that
// sleeps or blocks forever: at wall_seconds the whole process group is killed.
struct Limits {
    double cpu_seconds = 10;               // processor time of each process (RLIMIT_CPU)
    double wall_seconds = 60;              // the backstop: killed (the whole process group) after this
    long memory_mb = 1024;                 // address space
    long output_bytes = 1 << 20;           // any file it writes, its output included
    bool forbid_processes = true;          // Sandbox::none: no fork, no threads (RLIMIT_NPROC 0)
    Sandbox sandbox = Sandbox::none;       // see configure_sandbox
    std::vector<Bind> binds;               // Sandbox::build: what the compile sees besides /usr
    int threads = 16;                      // Sandbox::test: threads besides the main one (see below)
    std::vector<std::string> environment;  // more NAME=value for the program
};

// The sandbox of a student's code (sandbox.cpp). With bubblewrap: new user, PID, mount,
// network, IPC and UTS namespaces; /usr read-only, a fresh /proc and /dev; no capabilities;
// everything it starts dies with it. A student's process (Sandbox::test) sees besides only an
// empty size-limited /work, its working folder, and its own binary (a copy, read-only); inside,
// before any of the student's code runs, it installs a seccomp filter: threads, but no new
// process and no new program (tests/grading/engine/remote/serve.cpp). A compile (Sandbox::build) sees
// an empty /tmp and the folders Limits::binds names: the API headers, the link inputs and the
// submission's own folder. Started as root, either first becomes a user of its own
// (sandbox_uid(): it owns no file and no other process), and a student's process may then run
// `threads` threads besides its main one (RLIMIT_NPROC, which counts that user's processes);
// not started as root, the number of its threads is bounded by its memory limit alone.
// Without a working bubblewrap: as a user of its own when root, with the limits and the filter;
// otherwise with no sandbox at all (isolation() tells; `grade` refuses that unless --unsafe).
enum class Isolation { namespaces, user, limits_only };
// Probes what works here (once per run); returns a sentence for the log.
std::string configure_sandbox();
Isolation isolation();
unsigned sandbox_uid();

struct Outcome {
    bool started = false;
    bool timed_out = false;
    bool stopped = false;     // stopped by the harness at the end of its grace (wait_limited), not at its deadline
    int signal = 0;           // the signal that ended it, 0 if it exited
    int exit_code = -1;       // when it exited
    double seconds = 0;       // wall time
    double cpu_seconds = 0;   // processor time, its own and that of every process it started
    bool out_of_cpu = false;  // ended by its processor-time budget (SIGXCPU, or SIGKILL past it)
    bool ran_alone = false;   // stopped by the backstop with processor time to spare, then run again alone
    std::string error;        // why it could not start
};

// Runs argv[0] with stdin from /dev/null and stdout and stderr into output_path. The
// descriptors in pass_fds become its 3, 4, ...; with a report, the program also gets a pipe as
// the next one, read into *report while it runs (up to report_limit bytes; *report_overflow
// tells when more came): outside the output limit, and in no file the program could name.
// In a sandbox, cwd only matters without namespaces.
Outcome run_limited(const std::vector<std::string>& argv, const std::string& cwd, const std::string& output_path,
                    const Limits& limits, std::string* report = nullptr, std::size_t report_limit = 64u << 20,
                    bool* report_overflow = nullptr, const std::vector<int>& pass_fds = {});
// The same in two steps, to run two programs at once (a student's process and its judge).
struct Started {
    Outcome outcome;  // why it could not start (outcome.error), until wait_limited fills it
    struct Impl;
    std::unique_ptr<Impl> impl;
    Started();
    ~Started();  // stops it if it still runs
    Started(Started&&) noexcept;
    Started& operator=(Started&&) noexcept;
};
Started start_limited(const std::vector<std::string>& argv, const std::string& cwd, const std::string& output_path,
                      const Limits& limits, const std::vector<int>& pass_fds = {}, std::string* report = nullptr,
                      std::size_t report_limit = 64u << 20, bool* report_overflow = nullptr);
// Waits until it ends, its deadline, or (grace_seconds >= 0) that many seconds from now.
Outcome wait_limited(Started& started, double grace_seconds = -1);
std::string signal_name(int signal);
// For a worker: SIGINT, SIGTERM or SIGHUP kills the process groups run_limited waits for
// (a compiler and its cc1plus, or a test, its sandbox and its judge), then ends the worker.
void stop_children_on_signal();

// ---- what is graded (setup.cpp) ------------------------------------------------------------
struct Test {
    std::string name;
    int line = 0;
    double seconds = 0;          // the time the grader says it needs (doctest::timeout), if more than --timeout
    std::string private_file{};  // a private test (private.cpp): its file as the judge names it; "" if public
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
    std::string reference;             // the reference grader binary
    std::vector<std::string> objects;  // the grader's compiled tests
    // How a student's file is built, as the build sandbox sees it (see View): the compile
    // command with @API@, @SOURCE@ and @OBJECT@ to fill in, and what its object is linked with
    // (the student's side of the API, the reference libraries of the topic's dependencies, the
    // system's libraries) with @LINK@ for the folder of the link inputs.
    std::vector<std::string> compile;
    std::vector<std::string> link;
    std::string judge;  // the trusted judge of this topic's tests (no student code)
};

// A file the build sandbox sees under @LINK@/<name>: copied there from the build when the run
// starts (Stage).
struct LinkInput {
    std::string name, path;
};

struct Setup {
    std::string dir, root, build, compiler, nm;
    std::vector<std::string> link_flags;
    std::vector<Chapter> chapters;
    std::vector<Topic> topics;
    std::vector<LinkInput> link_inputs;
    std::string manifest_text;
    std::string fingerprint;    // of everything on the instructor's side
    bool private_names = true;  // --private-feedback: students see private tests by name, or per exercise a total
};

// The folder a run builds students' files in (in /tmp, made by make_stage, removed by
// remove_stage): copies of the API headers (api/exercises/rigid/, api/exercises/provided/rigid/)
// and of the link inputs (link/), and a folder per build (jobs/). The build sandbox binds
// api/ at /workbook, link/ at /link and a job's folder at /submission; without namespaces the
// compile reads them where they are.
struct Stage {
    std::string dir;
};
std::string make_stage(const Setup& setup, Stage& stage);  // an empty string or the error
void remove_stage(const Stage& stage);
// A new job folder (exercises/, obj/, bin/), owned by the sandbox's user when the run is root's.
std::string make_job(const Stage& stage, std::string& job);
// Where a build sees the API headers (@API@), the link inputs (@LINK@) and its job folder.
struct View {
    std::string api, link, submission;
};
View view_of(const Stage& stage, const std::string& job);

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
    Limits build_limits{120, 600, 4096, 256L << 20, false, Sandbox::none, {}, 0, {}};
    long max_file_bytes = 1 << 20;
    bool keep_work = false;
    // The mutation gate's (tests/grading/mutants/): NAME=VALUE pairs added to each test's
    // environment, and a folder of compiled objects keyed by the source and the compile command,
    // so that one file graded many times is compiled once.
    std::vector<std::string> test_environment;
    std::string object_cache;
    Stage stage;       // where students' files are built (make_stage)
    std::string seed;  // the graders' random inputs: checks::rng()'s seed (empty: the public one)
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
    Verdict verdict = Verdict::fail;  // pass, fail, timeout, crash, build error, missing (verdict.hpp)
    double score = 0, max_score = 0;
    bool not_started = false;  // failed on the stub's todo("<exercise>")
    std::string message;       // why it did not pass (for the student)
    std::string output;        // what the test printed, truncated
    bool hidden = false;       // a private test: message and output withheld (private.cpp)
};

struct SubmissionResult {
    std::string student;
    std::string seed;  // the --seed it was graded with (in the .tsv only, never in the results .json)
    std::string fingerprint;
    std::string json_hash;  // of the results .json it was written with (from the .tsv)
    std::vector<TestResult> tests;
    std::vector<std::string> notes;  // one line per topic that did not build, or was refused
    // "<topic>/<exercise>" -> the topic's other exercises that the student's own code of it calls,
    // directly or through the file's helpers (calls.hpp, read from the submitted file): blame()
    std::map<std::string, std::set<std::string>> uses;
    double score = 0, max_score = 0;
    nlohmann::ordered_json provenance;  // the test environment (provenance.hpp): the .json's extra_data, if set
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

// One exercise of a submission: its status (the worst of its tests' verdicts, or pass), how many
// of its tests pass, and the first that does not.
struct ExerciseStatus {
    std::optional<Verdict> status;  // pass, fail, not started, build error, missing, timeout, crash; none: not selected
    int passed = 0, total = 0;
    double score = 0;
    const TestResult* first_problem = nullptr;
};

ExerciseStatus status_of(const SubmissionResult& r, const std::string& topic, const std::string& exercise);

// Blame through the call chain: an exercise that ran and does not pass, while an exercise that the
// student's code of it calls (SubmissionResult::uses) was graded in this run and does not pass
// either. The text says so
// first: "integrate_rk4 calls your rk4_step, which fails 3 of its 4 tests: fix that first". Said in
// `check` (report.cpp), on each failing test in the results .json and in its extra_data.blame.
struct Blame {
    std::string topic, exercise;
    std::vector<std::string> callees;
    std::string text;
};
std::vector<Blame> blame(const Setup& setup, const SubmissionResult& r);

std::string results_json(const Setup& setup, const SubmissionResult& result);
// The completion marker: every verdict and score, and the hash of the results .json written with it.
std::string results_tsv(const SubmissionResult& result, const std::string& json = "");
bool read_results_tsv(const std::string& path, SubmissionResult& result);

// ---- private tests (private.cpp; README.md, "Private tests") --------------------------------------
// An instructor's own graders (WORKBOOK_PRIVATE_TESTS), built into the judges only. Their results
// show students a name and a verdict (or, with --private-feedback total, a total per exercise);
// the failed check's message, what the test printed and anything the student's code said about
// its inputs go to the staff log, logs/<student>/private.txt, alone.
bool has_private_tests(const Setup& setup);
// --private-feedback names|total (an empty string or the error). With private tests, the mode and
// the judges that hold them join the fingerprint (a private test changed: every result regraded).
std::string set_private_feedback(Setup& setup, const std::string& mode);
// The student's own check never grades private tests: they are dropped from its setup.
void drop_private_tests(Setup& setup);
// After a private test ran: its detail appended to <log_dir>/private.txt (when not ""), then withheld
// from `t` (and its name too, with --private-feedback total).
void withhold_private(TestResult& t, const Setup& setup, const std::string& log_dir);
// What a student's results list: every test, private ones collapsed per exercise when not by name.
std::vector<TestResult> student_view(const Setup& setup, const std::vector<TestResult>& tests);

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
