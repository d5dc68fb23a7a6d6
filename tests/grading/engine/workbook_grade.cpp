// workbook_grade: the grading run's command line (cmake/workbook grade and check call it).
//
//   workbook_grade grade --setup <build>/grading <submissions> <out> [options]
//   workbook_grade check --setup <build>/grading [--folder <exercises>] [chapter|topic|exercise]
//   workbook_grade similarity --setup <build>/grading <submissions> <out>
//   workbook_grade manifest --topics <topics.txt> --points <points.txt> --out <manifest.txt>
//
// grade: one folder per student in <submissions>, each holding exercises/*.cpp (or the .cpp
// files directly). Writes <out>/results/<student>.json (Gradescope's results.json),
// <out>/class.csv, <out>/summary.md, <out>/canvas.csv and <out>/moodle.csv (the LMS imports),
// <out>/similarity.md and .csv (similarity.cpp; the same as the similarity command writes),
// <out>/item_analysis.md and .csv and <out>/class_report.html (item_analysis.hpp) and
// <out>/run.json (timings: the only file that changes from run to run). Submissions are graded in parallel, each in its
// own worker process; a submission whose result is already there for the same inputs is not graded again.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <map>

#include "catalog.hpp"
#include "grading.hpp"
#include "item_analysis.hpp"
#include "provenance.hpp"

using namespace grading;

namespace {

volatile std::sig_atomic_t stop_signal = 0;
void on_stop(int sig) { stop_signal = sig; }

const char* usage =
    "usage:\n"
    "  workbook_grade grade --setup <build>/grading <submissions-folder> <out-folder> [options]\n"
    "  workbook_grade check --setup <build>/grading [--folder <exercises-folder>] [--out <folder>] "
    "[chapter|topic|exercise] [options]\n"
    "  workbook_grade similarity --setup <build>/grading <submissions-folder> <out-folder>\n"
    "  workbook_grade manifest --topics <topics.txt> --points <points.txt> --out <manifest.txt>\n"
    "options:\n"
    "  -j <n>                 submissions graded at once (default: the number of cores)\n"
    "  --timeout <s>          processor time each process of a test may use (default 10; a grader may ask more)\n"
    "  --wall-timeout <s>     wall-clock backstop of each test, against a process that waits forever\n"
    "                         (default 60, or 4 times the test's processor time if longer)\n"
    "  --memory <MB>          address space of each test (default 1024)\n"
    "  --output-limit <KB>    what each test may write (default 1024)\n"
    "  --threads <n>          threads a test may start besides its main one, as root (default 16)\n"
    "  --build-timeout <s>    processor time of each compile and link (default 120; wall-clock backstop 600)\n"
    "  --build-memory <MB>    address space of the compiler (default 4096)\n"
    "  --max-file-size <KB>   largest exercise file taken from a submission (default 1024)\n"
    "  --only <name>          grade only this submission (repeat it, or join names with commas;\n"
    "                         a name that itself holds a comma is taken whole); for sharding: no class files\n"
    "  --assignment <name>    the column of canvas.csv and moodle.csv (default: Grioli workbook)\n"
    "  --force                grade again even when a result for the same inputs exists\n"
    "  --keep-work            keep each submission's build folder (<out>/.work/)\n"
    "  --seed <n>             draw the graders' random inputs from this seed, not the public one\n"
    "                         (recorded in run.json; students' check uses the public one)\n"
    "  --private-feedback names|total\n"
    "                         what students see of private tests (a build with WORKBOOK_PRIVATE_TESTS):\n"
    "                         each by name and verdict (default), or per exercise only how many pass\n"
    "  --unsafe               grade without a sandbox where there is none (no bubblewrap, not root):\n"
    "                         students' code then runs as you, and can read and write what you can\n"
    "the mutation gate's (tests/grading/mutants/mutants.cpp):\n"
    "  --test-env NAME=VALUE  add to each test's environment (repeat it)\n"
    "  --object-cache <dir>   compile a file once for many gradings (keyed by source and command)\n";

int fail(const std::string& message) {
    std::fprintf(stderr, "workbook_grade: %s\n", message.c_str());
    return 2;
}

struct Args {
    std::string setup, topics, points, out, folder;
    std::string assignment = "Grioli workbook";  // the column of canvas.csv and moodle.csv
    std::string private_feedback = "names";      // private tests: by name, or a total per exercise
    std::vector<std::string> positional;
    std::vector<std::string> only;  // as given: a name, or names joined by commas
    int jobs = 0;
    bool force = false, unsafe = false;
    Options options;
    nlohmann::ordered_json provenance;  // grade: of this run, put into every result it writes (provenance.hpp)
};

// ---- the command line (CLI11) ----------------------------------------------------------------
// Every command (grade, check, similarity, manifest) takes the same options; the usage above is
// the help. An option given twice takes its last value (cmake/workbook passes -j before the
// instructor's own options), except --only and --test-env, which add one value each time.

std::string positive(const std::string& value) {
    char* end = nullptr;
    const double x = std::strtod(value.c_str(), &end);
    return end != value.c_str() && !*end && x > 0 ? "" : "needs a positive number, not '" + value + "'";
}

// An option whose positive value is stored through `set` (a limit, in the unit Options keeps).
void limit(CLI::App& app, const std::string& name, std::function<void(double)> set) {
    app.add_option_function<double>(name, [set](const double& x) { set(x); })->check(positive);
}

void limit_options(CLI::App& app, Options& o) {
    limit(app, "--timeout", [&o](double x) { o.test_limits.cpu_seconds = x; });
    limit(app, "--wall-timeout", [&o](double x) { o.test_limits.wall_seconds = x; });
    limit(app, "--memory", [&o](double x) { o.test_limits.memory_mb = static_cast<long>(x); });
    limit(app, "--output-limit", [&o](double x) { o.test_limits.output_bytes = static_cast<long>(x * 1024); });
    limit(app, "--threads", [&o](double x) { o.test_limits.threads = static_cast<int>(x); });
    limit(app, "--build-timeout", [&o](double x) {
        o.build_limits.cpu_seconds = x;
        o.build_limits.wall_seconds = std::max(600.0, 5 * x);
    });
    limit(app, "--build-memory", [&o](double x) { o.build_limits.memory_mb = static_cast<long>(x); });
    limit(app, "--max-file-size", [&o](double x) { o.max_file_bytes = static_cast<long>(x * 1024); });
    app.add_option("--test-env", o.test_environment)
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check([](const std::string& e) {
            return e.find('=') == std::string::npos || e.front() == '=' ? "needs NAME=VALUE, not '" + e + "'" : "";
        });
    app.add_option("--object-cache", o.object_cache);
}

void command_options(CLI::App& app, Args& a) {
    app.set_help_flag();
    app.add_flag_callback("-h,--help", [] { std::printf("%s", usage), std::exit(0); });
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    for (const auto& [name, value] : {std::pair{"--setup", &a.setup},
                                      {"--topics", &a.topics},
                                      {"--points", &a.points},
                                      {"--out", &a.out},
                                      {"--folder", &a.folder},
                                      {"--assignment", &a.assignment}})
        app.add_option(name, *value);
    app.add_option("--private-feedback", a.private_feedback)->check(CLI::IsMember({"names", "total"}));
    limit(app, "-j,--jobs", [&a](double x) { a.jobs = static_cast<int>(x); });
    app.add_option("--only", a.only)->allow_extra_args(false)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_flag("--force", a.force);
    app.add_flag("--keep-work", a.options.keep_work);
    app.add_flag("--unsafe", a.unsafe);
    app.add_option("--seed", a.options.seed)->check([](const std::string& v) {
        errno = 0;
        const bool number = !v.empty() && v.find_first_not_of("0123456789") == std::string::npos &&
                            (std::strtoull(v.c_str(), nullptr, 10), errno == 0);
        return number ? "" : "needs a whole number below 2^64 (at most 18446744073709551615)";
    });
    limit_options(app, a.options);
    app.add_option("arguments", a.positional)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

// --seed's value, out of the command line that /proc shows to every user of the machine.
void wipe_seed(int argc, char** argv) {
    for (int i = 2; i < argc; ++i) {
        char* value = nullptr;
        if (std::strcmp(argv[i], "--seed") == 0 && i + 1 < argc)
            value = argv[i + 1];
        else if (std::strncmp(argv[i], "--seed=", 7) == 0)
            value = argv[i] + 7;
        for (char* c = value; c && *c; ++c) *c = 'x';
    }
}

std::string absolute(const std::string& path) {
    if (starts_with(path, "/")) return path;
    char buffer[4096];
    if (!getcwd(buffer, sizeof buffer)) return path;
    return std::string(buffer) + "/" + path;
}

std::string load(const Args& a, Setup& setup) {
    if (a.setup.empty()) return "--setup <build>/grading is required";
    if (auto problem = load_setup(absolute(a.setup), setup); !problem.empty()) return problem;
    return set_private_feedback(setup, a.private_feedback);
}

// The submissions: one folder each. A hidden folder (.git, .DS_Store, an editor's backup) is not
// a student: it is named in `ignored`, not graded; so is anything that is not a folder.
void list_students(const std::string& submissions, std::vector<std::string>& students,
                   std::vector<std::string>& ignored) {
    for (const auto& name : list_dir(submissions)) {
        const std::string path = submissions + "/" + name;
        struct stat st;
        if (lstat(path.c_str(), &st) != 0) continue;
        if (starts_with(name, "."))
            ignored.push_back(name + ": a hidden name (it starts with '.'), not graded; rename it to grade it");
        else if (S_ISDIR(st.st_mode) || S_ISLNK(st.st_mode))
            students.push_back(name);
        else
            ignored.push_back(name + ": not a folder");
    }
}

// similarity.md and similarity.csv in out: what matches the reference or another submission.
// Returns how many submissions it lists.
std::size_t write_similarity(const Setup& setup, const std::vector<ClassFiles>& files, const std::string& out) {
    const std::vector<SimilarityHit> hits = find_similar(setup, files);
    write_file(out + "/similarity.md", similarity_markdown(setup, hits, files.size()));
    write_file(out + "/similarity.csv", similarity_csv(hits));
    std::set<std::string> listed;
    for (const auto& h : hits) {
        listed.insert(h.student);
        if (!h.other.empty()) listed.insert(h.other);
    }
    return listed.size();
}

// The class files: class.csv, summary.md, the LMS imports and the similarity report.
void write_class_files(const Setup& setup, const Args& a, const std::string& out,
                       const std::vector<SubmissionResult>& results, const std::vector<ClassFiles>& files,
                       const std::vector<std::string>& ignored) {
    write_file(out + "/class.csv", class_csv(setup, results));
    write_file(out + "/summary.md", class_summary(setup, results, ignored));
    write_file(out + "/canvas.csv", canvas_csv(results, a.assignment));
    write_file(out + "/moodle.csv", moodle_csv(results, a.assignment));
    const std::size_t listed = write_similarity(setup, files, out);
    std::printf("Similarity: %zu submissions match the reference or one another on some exercise (%s/similarity.md)\n",
                listed, out.c_str());
    std::printf("%s\n", write_item_analysis(setup, results, files, out).c_str());  // item_analysis.hpp
}

// ---- similarity ----------------------------------------------------------------------------------
// The similarity report alone, without grading: workbook_grade similarity --setup <dir> <submissions> <out>.
int similarity(const Args& a) {
    if (a.positional.size() != 2)
        return fail(std::string("similarity needs <submissions-folder> <out-folder>\n") + usage);
    Setup setup;
    if (const auto problem = load(a, setup); !problem.empty()) return fail(problem);
    const std::string submissions = absolute(a.positional[0]), out = absolute(a.positional[1]);
    if (!is_directory(submissions)) return fail(submissions + " is not a folder");
    if (!make_dirs(out)) return fail("cannot create " + out);
    std::vector<std::string> students, ignored;
    list_students(submissions, students, ignored);
    std::vector<ClassFiles> files;
    for (const auto& s : students) files.push_back({s, collect_files(setup, a.options, submissions + "/" + s)});
    const std::size_t listed = write_similarity(setup, files, out);
    std::printf(
        "Compared %zu submissions: %zu match the reference or one another on some exercise (%s/similarity.md)\n",
        files.size(), listed, out.c_str());
    return 0;
}

// ---- grade -------------------------------------------------------------------------------------
// One submission of the class run: its files, and its result (resumed, or from its worker).
struct Item {
    std::string name;
    std::vector<SubmittedFile> files;
    std::string fingerprint;
    bool resumed = false, graded = false, ok = false;
    double seconds = 0;
    SubmissionResult result;
};

// --only: the submissions named (a name with a comma is taken whole when it is one). Returns an
// empty string or the error.
std::string select_students(const Args& a, const std::string& submissions, std::vector<std::string>& students) {
    if (a.only.empty()) return {};
    std::set<std::string> only;
    for (const auto& value : a.only) {
        if (std::find(students.begin(), students.end(), value) != students.end()) {
            only.insert(value);
            continue;
        }
        for (const auto& name : split(value, ',')) {
            if (name.empty()) continue;
            if (std::find(students.begin(), students.end(), name) == students.end())
                return "--only " + name + ": no such submission in " + submissions;
            only.insert(name);
        }
    }
    std::vector<std::string> kept;
    for (const auto& s : students)
        if (only.count(s)) kept.push_back(s);
    students = kept;
    return {};
}

// The out folder, locked: a whole-class run holds its lock alone; shards (--only) share it with
// each other, and each submission has a lock of its own. Returns an empty string or the error.
std::string open_out_folder(const Args& a, const Setup& setup, const std::string& out) {
    if (!make_dirs(out)) return "cannot create " + out;
    const int lock = open((out + "/.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock < 0) return "cannot create " + out + "/.lock";
    if (flock(lock, (a.only.empty() ? LOCK_EX : LOCK_SH) | LOCK_NB) != 0)
        return "another grading run is writing to " + out + " (it holds " + out +
               "/.lock); wait for it to finish, or stop it, then run again";
    for (const char* sub : {"results", "logs", ".work", ".locks"})
        if (!make_dirs(out + "/" + sub)) return "cannot create " + out + "/" + sub;
    write_file(out + "/manifest.txt", setup.manifest_text);
    return {};  // the lock stays held until the run ends
}

// Each submission's files and fingerprint; a complete earlier result for the same inputs is
// taken as it is (the .tsv is written last, by a worker that finished) unless --force.
std::vector<Item> collect_items(const Setup& setup, const Args& a, const std::string& submissions,
                                const std::string& out, const std::vector<std::string>& students) {
    std::vector<Item> items;
    for (const auto& s : students) {
        Item item;
        item.name = s;
        item.files = collect_files(setup, a.options, submissions + "/" + s);
        item.fingerprint = fingerprint(setup, a.options, item.files, Selection{}.key());
        SubmissionResult previous;
        const std::string base = out + "/results/" + s;
        if (!a.force && read_results_tsv(base + ".tsv", previous) && previous.fingerprint == item.fingerprint &&
            previous.seed == a.options.seed && previous.json_hash == hex(hash(read_file(base + ".json")))) {
            item.resumed = item.ok = true;
            item.result = previous;
        }
        items.push_back(std::move(item));
    }
    return items;
}

// The worker of one submission (a child process). Another run (a shard) grading the same
// submission holds its lock: exit 3. Everything is made in a folder of this worker's own and
// published when complete: the logs, then results/<student>.json, then the .tsv, which marks
// completion.
[[noreturn]] void grade_in_worker(const Setup& setup, const Args& a, const std::string& out, const Item& item) {
    stop_children_on_signal();
    prctl(PR_SET_PDEATHSIG, SIGTERM);  // the main process is gone: so is its worker, and what it runs
    const int mine = open((out + "/.locks/" + item.name).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (mine < 0 || flock(mine, LOCK_EX | LOCK_NB) != 0) _exit(3);
    const std::string work = out + "/.work/" + item.name + "." + std::to_string(getpid());
    SubmissionResult r = grade_submission(setup, a.options, item.name, item.files, Selection{}, work, work + ".logs");
    r.seed = a.options.seed;
    r.provenance = a.provenance;
    const std::string base = out + "/results/" + item.name, logs = out + "/logs/" + item.name;
    remove_tree(logs);
    bool written = std::rename((work + ".logs").c_str(), logs.c_str()) == 0;
    const std::string json = results_json(setup, r);
    written = written && write_file(base + ".json", json) && write_file(base + ".tsv", results_tsv(r, json));
    std::fflush(stdout);
    _exit(written ? 0 : 1);
}

// The pool of workers: at most `jobs` at once, each grading one submission in a child process.
class Pool {
public:
    Pool(const Setup& setup, const Args& a, const std::string& out, std::vector<Item>& items, int jobs)
        : setup_(setup), a_(a), out_(out), items_(items), jobs_(jobs) {}

    // Grades every item not resumed. Returns -1 when done, or the exit status of an interrupted
    // or failed run.
    int run() {
        for (auto& item : items_)
            if (item.resumed) report(item);
        for (;;) {
            if (!start_workers()) return fail("fork failed");
            if (running_.empty()) return -1;
            if (stop_signal) return stop();
            int status = 0;
            const pid_t pid = waitpid(-1, &status, WNOHANG);
            if (pid == 0) {
                pollfd none{-1, 0, 0};
                poll(&none, 0, 20);
            } else if (pid < 0) {
                if (errno != EINTR) return -1;
            } else {
                finished(pid, status);
            }
        }
    }

private:
    using Clock = std::chrono::steady_clock;

    bool start_workers() {
        while (static_cast<int>(running_.size()) < jobs_ && next_ < items_.size()) {
            Item& item = items_[next_];
            if (item.resumed) {
                ++next_;
                continue;
            }
            std::fflush(stdout);
            std::fflush(stderr);
            const pid_t pid = fork();
            if (pid < 0) return false;
            if (pid == 0) grade_in_worker(setup_, a_, out_, item);
            running_[pid] = {next_, Clock::now()};
            ++next_;
        }
        return true;
    }

    // Interrupted: stop every worker (their tests and compilers die with them) and keep nothing
    // of theirs; what was complete stays.
    int stop() {
        for (const auto& [pid, slot] : running_) kill(pid, SIGTERM);
        for (const auto& [pid, slot] : running_) {
            for (int k = 0; k < 200 && waitpid(pid, nullptr, WNOHANG) == 0; ++k) usleep(10000);
            kill(pid, SIGKILL);
            while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
            }
            const std::string name = items_[slot.first].name;
            remove_tree(out_ + "/.work/" + name + "." + std::to_string(pid));
            remove_tree(out_ + "/.work/" + name + "." + std::to_string(pid) + ".logs");
        }
        rmdir((out_ + "/.work").c_str());
        std::printf(
            "Interrupted by %s: %zu submissions stopped, no result written for them; %zu graded before. "
            "Run again to grade the rest.\n",
            signal_name(stop_signal).c_str(), running_.size(), done_);
        std::fflush(stdout);
        return 128 + stop_signal;
    }

    // A worker ended: its time, and its result (or why there is none).
    void finished(pid_t pid, int status) {
        const auto it = running_.find(pid);
        if (it == running_.end()) return;
        Item& item = items_[it->second.first];
        item.seconds = std::chrono::duration<double>(Clock::now() - it->second.second).count();
        running_.erase(it);
        item.graded = true;
        if (WIFEXITED(status) && WEXITSTATUS(status) == 3) {
            item.graded = false;
            item.result = SubmissionResult{};
            item.result.student = item.name;
            item.result.notes.push_back("not graded: another grading run is grading it now");
            std::printf("[%*zu/%zu] %-24s being graded by another run: skipped\n", width(), ++done_, items_.size(),
                        item.name.c_str());
            std::fflush(stdout);
            return;
        }
        item.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
                  read_results_tsv(out_ + "/results/" + item.name + ".tsv", item.result);
        if (!item.ok) {
            item.result = SubmissionResult{};
            item.result.student = item.name;
            item.result.notes.push_back("not graded: the grading worker failed");
        }
        report(item);
    }

    int width() const { return static_cast<int>(std::to_string(items_.size()).size()); }

    // One line per submission: its score and its verdicts.
    void report(const Item& item) {
        std::map<Verdict, int> count;
        for (const auto& t : item.result.tests) ++count[t.verdict];
        std::string verdicts;
        for (const Verdict v : test_verdicts)
            if (count[v])
                verdicts += std::string(verdicts.empty() ? "" : ", ") + std::to_string(count[v]) + " " + to_string(v);
        std::printf("[%*zu/%zu] %-24s %7s / %-5s %s  (%s)\n", width(), ++done_, items_.size(), item.name.c_str(),
                    format_number(item.result.score).c_str(), format_number(item.result.max_score).c_str(),
                    verdicts.c_str(),
                    item.resumed ? "already graded"
                    : item.ok    ? (format_number(item.seconds) + " s").c_str()
                                 : "harness error");
        std::fflush(stdout);
    }

    const Setup& setup_;
    const Args& a_;
    const std::string& out_;
    std::vector<Item>& items_;
    int jobs_;
    std::map<pid_t, std::pair<std::size_t, Clock::time_point>> running_;
    std::size_t next_ = 0, done_ = 0;
};

// The totals on the terminal. Returns how many submissions this run graded. (No CPU time: the
// sandboxed compiles and tests are not the workers' children as the kernel counts CPU time.)
int print_totals(const std::vector<Item>& items, double wall, int jobs) {
    int graded = 0;
    double graded_wall = 0;
    for (const auto& item : items)
        if (item.graded) ++graded, graded_wall += item.seconds;
    std::printf("Graded %d submissions in %s s with %d jobs (%zu already graded)", graded, format_number(wall).c_str(),
                jobs, items.size() - graded);
    if (graded)
        std::printf(": %s s of wall time per submission, %s s per submission overall",
                    format_number(graded_wall / graded).c_str(), format_number(wall / graded).c_str());
    std::printf("\n");
    return graded;
}

// run.json: timings and the date. They change from run to run, so they live apart from the results.
void write_run_json(const std::string& out, const std::vector<Item>& items, int jobs, double wall, int graded,
                    const std::string& seed, const nlohmann::ordered_json& provenance) {
    char date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    char host[256] = "";
    gethostname(host, sizeof host - 1);
    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
    for (const auto& item : items)
        runs.push_back(
            {{"student", item.name}, {"graded_in_this_run", item.graded}, {"wall_seconds", json_number(item.seconds)}});
    write_file(out + "/run.json", json_text({{"finished", date},
                                             {"host", host},
                                             {"jobs", jobs},
                                             {"seed", seed.empty() ? "public" : seed},
                                             {"wall_seconds", json_number(wall)},
                                             {"graded", graded},
                                             {"already_graded", items.size() - static_cast<std::size_t>(graded)},
                                             {"provenance", provenance},
                                             {"submissions", runs}}));
}

void on_stop_signals() {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction action {};
        action.sa_handler = on_stop;
        sigemptyset(&action.sa_mask);
        sigaction(sig, &action, nullptr);  // no SA_RESTART: waiting stops at once
    }
}

int grade(const Args& a) {
    if (a.positional.size() != 2) return fail(std::string("grade needs <submissions-folder> <out-folder>\n") + usage);
    Setup setup;
    if (const auto problem = load(a, setup); !problem.empty()) return fail(problem);
    const std::string submissions = absolute(a.positional[0]);
    const std::string out = absolute(a.positional[1]);
    if (!is_directory(submissions)) return fail(submissions + " is not a folder");
    if (starts_with(out + "/", submissions + "/"))
        return fail("the out folder must not be inside the submissions folder");
    std::vector<std::string> students, ignored;
    list_students(submissions, students, ignored);
    if (const auto problem = select_students(a, submissions, students); !problem.empty()) return fail(problem);
    if (const auto problem = open_out_folder(a, setup, out); !problem.empty()) return fail(problem);

    const int jobs = std::max(1, a.jobs > 0 ? a.jobs : static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN)));
    std::size_t tests = 0;
    for (const auto& t : setup.topics)
        for (const auto& e : t.exercises) tests += e.tests.size();
    const std::string sandbox = configure_sandbox();
    if (isolation() == Isolation::limits_only && !a.unsafe)
        return fail(sandbox +
                    ": refusing to grade, since students' code would run as you, able to read and write what you can "
                    "(the workbook, the build, the results). Install bubblewrap or run as root; or, knowing that, "
                    "pass --unsafe.");
    if (!a.options.seed.empty() && std::strtoull(a.options.seed.c_str(), nullptr, 10) < (1ull << 40))
        std::fprintf(stderr,
                     "workbook_grade: warning: --seed is below 2^40: a submission could find it by trying every "
                     "seed against its inputs; use a random 64-bit number (od -An -N8 -tu8 /dev/urandom)\n");
    std::printf("Grading %zu submissions from %s with %d jobs: %zu topics, %zu tests each (%s%s)\n", students.size(),
                submissions.c_str(), jobs, setup.topics.size(), tests, sandbox.c_str(),
                a.options.seed.empty() ? "; the public seed: pass --seed to draw inputs students have not seen" : "");
    std::fflush(stdout);
    Args staged = a;
    staged.provenance = provenance(setup, a.options);
    if (const auto problem = make_stage(setup, staged.options.stage); !problem.empty()) return fail(problem);
    std::vector<Item> items = collect_items(setup, staged, submissions, out, students);
    on_stop_signals();
    const auto start = std::chrono::steady_clock::now();
    const int status = Pool(setup, staged, out, items, jobs).run();
    remove_stage(staged.options.stage);
    if (status >= 0) return status;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rmdir((out + "/.work").c_str());  // when empty: other runs (shards) may still be working there
    const int graded = print_totals(items, wall, jobs);
    if (a.only.empty()) {
        std::vector<SubmissionResult> results;
        std::vector<ClassFiles> files;
        for (const auto& item : items) results.push_back(item.result), files.push_back({item.name, item.files});
        write_class_files(setup, a, out, results, files, ignored);
        write_run_json(out, items, jobs, wall, graded, a.options.seed, staged.provenance);
        std::printf("Results: %s/summary.md, %s/class.csv (canvas.csv, moodle.csv), %s/results/<student>.json\n",
                    out.c_str(), out.c_str(), out.c_str());
    }
    const bool errors = std::any_of(items.begin(), items.end(), [](const Item& item) { return !item.ok; });
    return errors ? 1 : 0;
}

// ---- check -------------------------------------------------------------------------------------
int check(const Args& a) {
    Setup setup;
    if (const auto problem = load(a, setup); !problem.empty()) return fail(problem);
    drop_private_tests(setup);  // a student's check never grades the instructor's private tests
    const std::string folder = a.folder.empty() ? setup.root + "/exercises" : absolute(a.folder);
    if (a.positional.size() > 1) return fail("check takes at most one chapter, topic or exercise");
    Selection selection;
    std::string what = "every chapter";
    if (!a.positional.empty()) {
        // The key's grammar is the front door's (catalog.hpp): the same chapters, topics and exercises.
        Catalog catalog;
        if (auto problem = load_catalog(setup.dir + "/catalog.json", catalog); !problem.empty()) return fail(problem);
        KeySelection key;
        if (auto problem = select_key(catalog, a.positional[0], key); !problem.empty()) return fail(problem);
        for (const auto& name : key.topics) {
            const bool built =
                std::any_of(setup.topics.begin(), setup.topics.end(), [&](const Topic& t) { return t.name == name; });
            if (!built)
                return fail("the graders of " + name + " are not built in " + setup.dir + " (cmake/workbook check " +
                            a.positional[0] + " builds them)");
            selection.topics.insert(name);
        }
        selection.exercise = key.exercise;
        what = key.what;
    }
    const std::string sandbox = configure_sandbox();
    std::printf("Checking %s in %s with the graders (the instructor's grading run uses the same ones)\n", what.c_str(),
                relative_to_root(setup, folder).c_str());
    if (isolation() != Isolation::namespaces) std::printf("%s\n", sandbox.c_str());
    std::fflush(stdout);
    const std::string dir = a.out.empty() ? setup.dir + "/check" : absolute(a.out);
    make_dirs(dir);
    const int lock = open((dir + "/.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock < 0 || flock(lock, LOCK_EX | LOCK_NB) != 0)
        return fail("another check is running in " + dir + "; wait for it to finish");
    const auto files = collect_files(setup, a.options, folder);
    Options options = a.options;
    if (const auto problem = make_stage(setup, options.stage); !problem.empty()) return fail(problem);
    SubmissionResult r = grade_submission(setup, options, "check", files, selection, dir + "/work", dir + "/logs");
    r.provenance = provenance(setup, a.options);
    remove_stage(options.stage);
    write_file(dir + "/results.json", results_json(setup, r));
    const bool all = print_check(setup, r, relative_to_root(setup, folder));
    for (const auto& n : r.notes)
        if (n.find("does not build") != std::string::npos) {
            std::printf("The compiler's full output is in %s/logs/.\n", relative_to_root(setup, dir).c_str());
            break;
        }
    return all ? 0 : 1;
}

int manifest(const Args& a) {
    if (a.topics.empty() || a.points.empty() || a.out.empty())
        return fail(std::string("manifest needs --topics, --points and --out\n") + usage);
    const std::string problem = make_manifest(a.topics, a.points, a.out);
    return problem.empty() ? 0 : fail(problem);
}

}  // namespace

// One subcommand per job (CLI11): grade, check, similarity and manifest take the same options
// (the usage above is the help). A wrong one exits with status 2. (The build step that writes a
// topic's judge and student's side is workbook_api.)
int main(int argc, char** argv) {
    Args a;
    CLI::App app{"workbook_grade"};
    app.set_help_flag();
    app.add_flag_callback("-h,--help", [] { std::printf("%s", usage), std::exit(0); });
    app.require_subcommand(1);
    const std::vector<std::pair<const char*, int (*)(const Args&)>> commands = {
        {"grade", grade}, {"check", check}, {"similarity", similarity}, {"manifest", manifest}};
    std::vector<CLI::App*> subcommands;
    for (const auto& [name, run] : commands) {
        subcommands.push_back(app.add_subcommand(name));
        command_options(*subcommands.back(), a);
    }
    app.add_subcommand("help")->callback([] { std::printf("%s", usage), std::exit(0); });
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        wipe_seed(argc, argv);
        std::fprintf(stderr, "workbook_grade: %s\n%s", e.what(), usage);
        return 2;
    }
    wipe_seed(argc, argv);
    for (std::size_t k = 0; k < commands.size(); ++k)
        if (subcommands[k]->parsed()) return commands[k].second(a);
    return fail(std::string("no command\n") + usage);
}
