// The grading harness's own test: bad submissions get the verdicts they deserve.
//
//   grading_suite --setup <build>/grading --harness <workbook_grade> --cases <folder> --work <folder>
//                 [--count <n>] [--jobs <n>] [--timeout <s>] [--wall-timeout <s>]
//
// Builds one submission folder per recipe in tests/grading/tests/cases/ (see its README.md), or
// <n> of them cycling through the recipes, grades them all in one parallel run of
// `workbook_grade grade`, and checks every test's verdict, message and the partial credit.
// Then proves the rest of the contract: a second run resumes (grades nothing, same class
// files), and grading a few of them again from scratch gives byte-identical results. Prints
// the verdict table and the time per submission.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <map>
#include <set>

#include "grading.hpp"
#include "support/process.hpp"

using namespace grading;

namespace {

struct Expect {
    std::string key, verdict, text;
};

struct Case {
    std::string name, description, make, topic = "rotation", body, base = "solutions", student;
    bool needs_root = false, needs_namespaces = false;
    std::vector<std::string> replace;
    std::vector<Expect> expects, seeded;  // seeded: when graded with the instructor's --seed
    std::map<std::string, double> scores;
};

Case read_case(const std::string& path, const std::string& name) {
    Case c;
    c.name = name;
    for (const auto& line : split(read_file(path), '\n')) {
        auto field = [&](const std::string& key) -> std::string {
            const std::string prefix = "// " + key + ":";
            return starts_with(line, prefix) ? trim(line.substr(prefix.size())) : std::string("\x01");
        };
        std::string v;
        if ((v = field("case")) != "\x01")
            c.description = v;
        else if ((v = field("make")) != "\x01")
            c.make = v;
        else if ((v = field("topic")) != "\x01")
            c.topic = v;
        else if ((v = field("base")) != "\x01")
            c.base = v;
        else if ((v = field("needs")) != "\x01")
            c.needs_root = v.find("root") != std::string::npos,
            c.needs_namespaces = v.find("namespaces") != std::string::npos;
        else if ((v = field("replace")) != "\x01")
            c.replace.push_back(v);
        else if ((v = field("expect")) != "\x01" || (v = field("seeded")) != "\x01") {
            const auto parts = split(v, '|');
            (starts_with(line, "// seeded:") ? c.seeded : c.expects)
                .push_back(
                    {trim(parts[0]), parts.size() > 1 ? trim(parts[1]) : "", parts.size() > 2 ? trim(parts[2]) : ""});
        } else if ((v = field("score")) != "\x01") {
            const auto parts = split(v, ' ');
            c.scores[parts[0]] = std::stod(parts.back());
        } else if (!starts_with(line, "// case") && !(c.body.empty() && starts_with(line, "// "))) {
            c.body += line + "\n";
        }
    }
    return c;
}

// The expectation for one test: the longest key that prefixes its name (or names its exercise).
const Expect* expectation(const std::vector<Expect>& expects, const TestResult& t) {
    const Expect* best = nullptr;
    std::size_t best_length = 0;
    for (const auto& e : expects) {
        const bool match =
            e.key == "*" || e.key == t.exercise || (e.key.find(':') != std::string::npos && starts_with(t.name, e.key));
        const std::size_t length = e.key == "*" ? 0 : e.key.size();
        if (match && (!best || length > best_length)) best = &e, best_length = length;
    }
    return best;
}

// Starts `workbook_grade grade ...` with its output into a file; returns its process id.
pid_t start_grading(const std::vector<std::string>& argv, const std::string& output) {
    support::RunOptions to_file;
    to_file.stdout_file = output;
    to_file.stderr_to_stdout = true;
    return support::spawn(argv, to_file);
}

// Runs it to its end, its stdout into a file (none: into the suite's; its stderr shows in the
// suite's); its exit status.
int run_into(const std::vector<std::string>& argv, const std::string& output = "") {
    support::RunOptions to_file;
    to_file.stdout_file = output;
    const support::Result r = support::run(argv, to_file);
    std::printf("%s", r.out.c_str());
    std::fflush(stdout);
    std::fprintf(stderr, "%s%s", r.err.c_str(), r.error.c_str());
    return r.status;
}

// Waits until the file holds the text (or the process ended, or the time is up).
bool wait_for(const std::string& file, const std::string& text, pid_t pid, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        if (read_file(file).find(text) != std::string::npos) return true;
        if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
        usleep(20000);
    }
    return false;
}

// Waits for the process at most `seconds`; its exit status, or -1 when it did not end.
int wait_exit(pid_t pid, double seconds) { return support::wait(pid, seconds); }

// Processes whose command line mentions the text (left behind by a run that should be gone).
std::vector<std::string> processes_mentioning(const std::string& text) {
    std::vector<std::string> found;
    for (const auto& name : list_dir("/proc")) {
        if (name.find_first_not_of("0123456789") != std::string::npos || std::stoi(name) == getpid()) continue;
        std::string cmdline = read_file("/proc/" + name + "/cmdline");
        for (char& c : cmdline)
            if (c == '\0') c = ' ';
        if (cmdline.find(text) != std::string::npos) found.push_back(name + ": " + first_lines(cmdline, 200));
    }
    return found;
}

bool same_file(const std::string& a, const std::string& b) {
    bool ok_a = false, ok_b = false;
    const std::string x = read_file(a, &ok_a), y = read_file(b, &ok_b);
    return ok_a && ok_b && x == y;
}

// The suite's options.
struct Args {
    std::string setup_dir, harness, cases_dir, work;
    int count = 0, jobs = 2;
    // Each test's processor time: short for the endless loops (the heaviest grader, 197,511
    // calls of the student's function, about 0.5 s, asks for 30 s itself: doctest::timeout),
    // and a short wall-clock backstop for the one that sleeps (waits_forever.cpp): 12 s, twice.
    std::string timeout = "3", wall_timeout = "12";
};

// Returns 0, or the exit status of a wrong command line.
int parse(int argc, char** argv, Args& a) {
    CLI::App app{"grading_suite"};
    app.set_help_flag();
    for (const auto& [name, value] : {std::pair{"--setup", &a.setup_dir},
                                      {"--harness", &a.harness},
                                      {"--cases", &a.cases_dir},
                                      {"--work", &a.work}})
        app.add_option(name, *value)->required();
    const auto at_least = [](double lo) {
        return [lo](const std::string& v) {
            char* end = nullptr;
            const double x = std::strtod(v.c_str(), &end);
            return end != v.c_str() && !*end && x >= lo ? std::string() : "needs a number >= " + format_number(lo);
        };
    };
    app.add_option("--count", a.count)->check(at_least(0));
    app.add_option("--jobs", a.jobs)->check(at_least(1));
    app.add_option("--timeout", a.timeout)->check(at_least(0.001));
    app.add_option("--wall-timeout", a.wall_timeout)->check(at_least(0.001));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr,
                     "grading_suite: %s\nusage: grading_suite --setup <dir> --harness <exe> --cases <dir> --work <dir> "
                     "[--count n] [--jobs n] [--timeout s] [--wall-timeout s]\n",
                     e.what());
        return 2;
    }
    return 0;
}

// One run of the suite: the class of submissions made from the cases, where they are graded,
// and every problem found.
struct Suite {
    Args a;
    Setup setup;
    std::string secret_path, secret;  // a file only the suite's user may read, and its content
    bool root = false, namespaces = false;
    std::vector<Case> cases;
    std::vector<std::string> skipped;
    std::map<std::string, const Case*> case_of;  // student -> case
    int n = 0;
    static constexpr long max_file_kb = 64;
    std::string subs, out;
    // workbook_grade grade --setup <setup> <subs> <out> -j <jobs> --timeout ... --max-file-size <kb>
    std::vector<std::string> run_args;
    // The same on another out folder.
    std::vector<std::string> grade_args(const std::string& out_folder) const {
        std::vector<std::string> args = run_args;
        args[5] = out_folder;
        return args;
    }
    std::vector<std::string> problems;
};

// The cases; a trick that needs root (to prove what root cannot do) or the namespaces (to prove
// what they hide) is graded only where that holds, and named when it is not.
void read_cases(Suite& s) {
    for (const auto& name : list_dir(s.a.cases_dir)) {
        if (!ends_with(name, ".cpp")) continue;
        Case c = read_case(s.a.cases_dir + "/" + name, name.substr(0, name.size() - 4));
        if ((c.needs_root && !s.root) || (c.needs_namespaces && !s.namespaces)) {
            s.skipped.push_back(c.name);
            continue;
        }
        s.cases.push_back(c);
    }
}

// The submission of one case into `folder`. Returns an empty string or the error.
std::string write_submission(const Suite& s, const Case& c, const std::string& folder, const std::string& student) {
    const std::string file = folder + "/" + c.topic + ".cpp";
    const std::string reference = s.setup.root + "/solutions/" + c.topic + ".cpp";
    if (c.make == "reference" || c.make == "stubs") {
        for (const auto& t : s.setup.topics)
            if (c.make == "reference" || t.name == c.topic)
                write_file(folder + "/" + t.name + ".cpp",
                           read_file(c.make == "reference" ? s.setup.root + "/solutions/" + t.name + ".cpp"
                                                           : pristine_stub(s.setup, t.name)));
    } else if (c.make == "missing") {
    } else if (c.make == "symlink") {
        if (symlink(reference.c_str(), file.c_str()) != 0) return std::string("symlink: ") + std::strerror(errno);
    } else if (c.make == "oversized") {
        std::string text = read_file(reference) + "\n/*";
        while (text.size() <= static_cast<std::size_t>(Suite::max_file_kb * 1024))
            text += " padding padding padding padding\n";
        write_file(file, text + "*/\n");
    } else if (!c.make.empty()) {
        return c.name + ": unknown make: " + c.make;
    } else {
        // The case's code after solutions/<topic>.cpp (or the stub, with base: stubs; alone, with
        // base: none).
        std::string body = replace_all(c.body, "@ROOT@", s.setup.root);
        body = replace_all(body, "@BUILD@", s.setup.build);
        body = replace_all(body, "@OUT@", s.out);
        body = replace_all(body, "@STUDENT@", student);
        body = replace_all(body, "@SECRET@", s.secret_path);
        if (c.base == "none") return write_file(file, body) ? "" : "cannot write " + file;
        const std::string base = c.base == "stubs" ? pristine_stub(s.setup, c.topic) : reference;
        std::string text = "// Generated by grading_suite from tests/grading/tests/cases/" + c.name + ".cpp and " +
                           relative_to_root(s.setup, base) + "\n";
        for (const auto& f : c.replace) text += "#define " + f + " " + f + "_reference_unused\n";
        text += read_file(base);
        for (const auto& f : c.replace) text += "#undef " + f + "\n";
        write_file(file, text + "\n// The case:\n" + body);
    }
    return {};
}

// The submissions: one per case, or <count> cycling through them. Returns an empty string or the error.
std::string make_submissions(Suite& s) {
    make_dirs(s.subs);
    s.n = s.a.count > 0 ? s.a.count : static_cast<int>(s.cases.size());
    for (int k = 0; k < s.n; ++k) {
        const Case& c = s.cases[static_cast<std::size_t>(k) % s.cases.size()];
        char prefix[16];
        std::snprintf(prefix, sizeof prefix, "s%02d_", k + 1);
        const std::string student = s.a.count > 0 ? prefix + c.name : c.name;
        s.case_of[student] = &c;
        const std::string folder = s.subs + "/" + student + "/exercises";
        make_dirs(folder);
        if (auto problem = write_submission(s, c, folder, student); !problem.empty()) return problem;
    }
    return {};
}

// The first run, and an overlapping run on the same out folder while it grades: refused, with
// the reason. Returns the first run's wall time.
double first_run(Suite& s) {
    const std::string& work = s.a.work;
    std::printf("== Grading %d bad and good submissions\n", s.n);
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    const std::string main_log = work + "/grade.txt", overlap_log = work + "/overlap.txt";
    const pid_t main_run = start_grading(s.run_args, main_log);
    if (!wait_for(main_log, "Grading ", main_run, 60))
        s.problems.push_back("the grading run did not start: " + read_file(main_log));
    const int overlap = wait_exit(start_grading(s.run_args, overlap_log), 60);
    if (overlap != 2 || read_file(overlap_log).find("another grading run is writing to") == std::string::npos)
        s.problems.push_back("an overlapping run on the same out folder was not refused (status " +
                             std::to_string(overlap) + "): " + read_file(overlap_log));
    const int status = wait_exit(main_run, 3600);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s", read_file(main_log).c_str());
    std::printf("== An overlapping run on the same out folder: %s", read_file(overlap_log).c_str());
    if (status != 0) s.problems.push_back("the grading run failed (status " + std::to_string(status) + ")");
    // The first run's timings (run.json is rewritten by every run).
    write_file(work + "/first-run.json", read_file(s.out + "/run.json"));
    return wall;
}

// A row of the table: one per expectation of a case.
struct Row {
    std::string student, description, exercise, expected, got;
    int tests = 0;
    double score = 0, max_score = 0;
};

// One submission's verdicts, messages and partial scores against its case (its expectations in
// `out`: the first run's, or, seeded, those of the run with the instructor's seed); its rows.
void check_submission(Suite& s, const std::string& student, const Case& c, std::vector<Row>& rows,
                      const std::string& out, bool seeded = false) {
    const std::vector<Expect>& expects = seeded ? c.seeded : c.expects;
    SubmissionResult r;
    if (!read_results_tsv(out + "/results/" + student + ".tsv", r))
        return s.problems.push_back(student + ": no results");
    const std::string json = read_file(out + "/results/" + student + ".json");
    if (json.find("\"tests\": [") == std::string::npos || json.find("\"score\": ") == std::string::npos)
        s.problems.push_back(student + ": results.json lacks score or tests");
    std::map<std::string, double> exercise_score;
    std::map<std::string, Row> by_key;
    for (const auto& t : r.tests) {
        std::string want = to_string(Verdict::missing), text;
        if (t.topic == c.topic || c.make == "reference") want = to_string(Verdict::pass);
        if (t.topic == c.topic)
            if (const Expect* e = expectation(expects, t)) want = e->verdict, text = e->text;
        const std::string got = to_string(t.not_started ? Verdict::not_started : t.verdict);
        if (got != want)
            s.problems.push_back(student + ": \"" + t.name + "\": expected " + want + ", got " + got + ": " +
                                 t.message);
        else if (!text.empty() && t.message.find(text) == std::string::npos)
            s.problems.push_back(student + ": \"" + t.name + "\": the message lacks \"" + text + "\": " + t.message);
        exercise_score[t.exercise] += t.score;
        if (const Expect* e = t.topic == c.topic ? expectation(expects, t) : nullptr) {
            Row& row = by_key[e->key];
            row.exercise = e->key == "*" ? "every exercise of " + c.topic : e->key;
            if (row.expected.find(want) == std::string::npos) row.expected += (row.expected.empty() ? "" : ", ") + want;
            if (row.got.find(got) == std::string::npos) row.got += (row.got.empty() ? "" : ", ") + got;
            ++row.tests;
            row.score += t.score;
            row.max_score += t.max_score;
        }
    }
    for (const auto& [exercise, points] : c.scores)
        if (!seeded && std::abs(exercise_score[exercise] - points) > 1e-9)
            s.problems.push_back(student + ": " + exercise + " scored " + format_number(exercise_score[exercise]) +
                                 ", expected " + format_number(points));
    if (r.tests.empty()) s.problems.push_back(student + ": no tests graded");
    for (auto& [key, row] : by_key) {
        row.student = student + (seeded ? " (--seed)" : "");
        row.description = c.description;
        rows.push_back(row);
    }
}

// The instructor's seed: the cases with seeded expectations (a table of the public answers) and
// the reference are graded again with --seed; the reference must still pass everything.
void check_seeded(Suite& s, std::vector<Row>& rows) {
    std::string only;
    std::vector<std::string> students;
    for (const auto& [student, c] : s.case_of)
        if (!c->seeded.empty() || c->name == "reference") {
            only += (only.empty() ? "" : ",") + student;
            students.push_back(student);
        }
    if (students.empty()) return;
    const std::string out = s.a.work + "/out-seeded", log = s.a.work + "/seeded.txt";
    std::vector<std::string> args = s.grade_args(out);
    args.insert(args.end(), {"--only", only, "--seed", "4242"});
    std::printf("== Grading %s again with the instructor's seed (--seed)\n", only.c_str());
    std::fflush(stdout);
    const pid_t run = start_grading(args, log);
    // While it grades, no command line on the machine shows the seed (the harness wipes it).
    if (wait_for(log, "Grading ", run, 60) && !processes_mentioning("--seed 4242").empty())
        s.problems.push_back("the seed shows in a command line while the run grades");
    if (wait_exit(run, 1800) != 0) s.problems.push_back("the seeded run failed: " + read_file(log));
    if (read_file(log).find("4242") != std::string::npos) s.problems.push_back("the seed shows in the run's output");
    for (const auto& student : students) {
        const Case& c = *s.case_of[student];
        if (c.name == "reference") {
            Case all = c;
            all.seeded = c.expects;
            check_submission(s, student, all, rows, out, true);
        } else {
            check_submission(s, student, c, rows, out, true);
        }
    }
}

// The exercises none of whose tests sent other inputs under another seed, from two timing logs
// (test name -> hash of the inputs sent; logs/<student>/timing.tsv): they have no test on seeded
// inputs, and a table of the public answers would earn them.
std::set<std::string> unseeded_exercises(const std::map<std::string, std::string>& one,
                                         const std::map<std::string, std::string>& other) {
    std::map<std::string, bool> seeded;
    for (const auto& [test, sent] : one) {
        const std::string exercise = test.substr(0, test.find(':'));
        const auto it = other.find(test);
        seeded[exercise] = seeded[exercise] || (it != other.end() && it->second != sent);
    }
    std::set<std::string> out;
    for (const auto& [exercise, yes] : seeded)
        if (!yes) out.insert(exercise);
    return out;
}

std::map<std::string, std::string> sent_per_test(const std::string& timing) {
    std::map<std::string, std::string> out;
    for (const auto& line : split(read_file(timing), '\n')) {
        const auto f = split(line, '\t');
        if (f.size() >= 5) out[f[0]] = f[4];
    }
    return out;
}

// Every exercise has a test on seeded inputs: the reference graded with the public seed and with
// --seed sent other inputs in some test of each. The check is proved on a planted pair first.
void check_every_exercise_seeded(Suite& s) {
    const std::set<std::string> planted =
        unseeded_exercises({{"hat: random", "1"}, {"hat: fixed", "2"}, {"vee: fixed", "3"}},
                           {{"hat: random", "9"}, {"hat: fixed", "2"}, {"vee: fixed", "3"}});
    if (planted != std::set<std::string>{"vee"})
        s.problems.push_back("the seeded-inputs check does not flag an exercise whose tests all send the same inputs");
    const auto one = sent_per_test(s.out + "/logs/reference/timing.tsv");
    const auto other = sent_per_test(s.a.work + "/out-seeded/logs/reference/timing.tsv");
    if (one.empty() || other.empty()) return s.problems.push_back("no timing logs of the reference to compare seeds");
    for (const auto& exercise : unseeded_exercises(one, other))
        s.problems.push_back("the exercise " + exercise +
                             " has no test on seeded inputs: a table of the public answers would earn it");
    std::set<std::string> exercises;
    for (const auto& [test, sent] : one) exercises.insert(test.substr(0, test.find(':')));
    std::printf("== Every one of the %zu exercises has a test whose inputs follow the seed (%zu tests compared)\n",
                exercises.size(), one.size());
}

// A file only the suite's user may read, whose content no result and no log may ever hold
// (compile_secret.cpp reads it at compile time).
void plant_secret(Suite& s) {
    const std::string dir = s.a.work + "/secret";
    make_dirs(dir);
    chmod(dir.c_str(), 0700);
    s.secret_path = dir + "/shadow";
    s.secret = "workbook-secret-" + hex(hash(std::to_string(getpid()) + std::to_string(std::time(nullptr))));
    write_file(s.secret_path, s.secret + "\n");
    chmod(s.secret_path.c_str(), 0600);
}

void find_secret(Suite& s, const std::string& path) {
    if (path == s.a.work + "/secret") return;
    if (is_directory(path)) {
        for (const auto& name : list_dir(path)) find_secret(s, path + "/" + name);
    } else if (read_file(path).find(s.secret) != std::string::npos) {
        s.problems.push_back("the secret file's content is in " + path);
    }
}

// Resumed: a second run grades nothing and writes the same class files.
void check_resumed(Suite& s) {
    const std::string csv = read_file(s.out + "/class.csv");
    if (std::count(csv.begin(), csv.end(), '\n') != s.n + 1)
        s.problems.push_back("class.csv does not have one row per submission");
    if (read_file(s.out + "/summary.md").find("| Student | Score |") == std::string::npos)
        s.problems.push_back("summary.md has no table");
    std::printf("== Running again: every submission already graded\n");
    std::fflush(stdout);
    const std::string before = csv + read_file(s.out + "/summary.md");
    const std::string again = s.a.work + "/again.txt";
    if (run_into(s.grade_args(s.out), again) != 0) s.problems.push_back("the resumed run failed");
    if (read_file(again).find("Graded 0 submissions") == std::string::npos)
        s.problems.push_back("the resumed run graded again: " + read_file(again));
    if (read_file(s.out + "/class.csv") + read_file(s.out + "/summary.md") != before)
        s.problems.push_back("the resumed run changed the class files");
}

// Deterministic: a few graded again from scratch give the same bytes.
void check_deterministic(Suite& s) {
    std::vector<std::string> subset;
    for (const auto& [student, c] : s.case_of)
        if (subset.size() < 2 && (c->name == "crash" || c->name == "exit0")) subset.push_back(student);
    std::string only;
    for (const auto& x : subset) only += (only.empty() ? "" : ",") + x;
    std::printf("== Grading %s again from scratch\n", only.c_str());
    std::fflush(stdout);
    const std::string out2 = s.a.work + "/out-again";
    std::vector<std::string> args = s.grade_args(out2);
    args.insert(args.end(), {"--only", only});
    if (run_into(args) != 0) s.problems.push_back("the repeated run failed");
    for (const auto& x : subset)
        for (const char* ext : {".json", ".tsv"})
            if (!same_file(s.out + "/results/" + x + ext, out2 + "/results/" + x + ext))
                s.problems.push_back(x + ext + " differs between two runs");
}

// The student's check reaches the same verdicts as the instructor's run.
void check_student_check(Suite& s) {
    const std::string& work = s.a.work;
    for (const auto& [student, c] : s.case_of) {
        if (c->name != "partial") continue;
        std::printf("== The student's check of %s\n", student.c_str());
        std::fflush(stdout);
        const std::string check_out = work + "/check";
        std::vector<std::string> args = {s.a.harness,   "check",    "--setup",
                                         s.a.setup_dir, "--folder", s.subs + "/" + student + "/exercises",
                                         "--out",       check_out};
        args.insert(args.end(), s.run_args.begin() + 6, s.run_args.end());
        run_into(args, work + "/check.txt");
        const std::string mine = read_file(check_out + "/results.json"),
                          theirs = read_file(s.out + "/results/" + student + ".json");
        const auto from_mine = mine.find("\"tests\": ["), from_theirs = theirs.find("\"tests\": [");
        if (from_mine == std::string::npos || from_theirs == std::string::npos ||
            mine.substr(from_mine) != theirs.substr(from_theirs))
            s.problems.push_back(student + ": the student's check and the grading run disagree");
        if (read_file(work + "/check.txt").find("Chapter 1, ") == std::string::npos)
            s.problems.push_back(student + ": the check printed no progress: " + read_file(work + "/check.txt"));
        // The first failing exercise gets its nudge, Hint 1, and only that (hints.cpp).
        const std::string printed = read_file(work + "/check.txt");
        if (printed.find("Hint 1 of 3 for geodesic_angle") == std::string::npos ||
            printed.find("Hint 2 of") != std::string::npos)
            s.problems.push_back(student +
                                 ": the check did not print Hint 1 (and only Hint 1) of geodesic_angle: " + printed);
        break;
    }
}

// Interrupted: SIGTERM to the main process while it grades stops its workers at once and leaves
// no result of theirs and no process behind; running again grades them as before.
void check_interrupted(Suite& s) {
    std::vector<std::string> some;
    for (const auto& [student, c] : s.case_of)
        if (some.size() < 3 && (c->name == "partial" || c->name == "fail" || c->name == "crash" || c->name == "exit0"))
            some.push_back(student);
    std::string list;
    for (const auto& x : some) list += (list.empty() ? "" : ",") + x;
    const std::string out3 = s.a.work + "/out-interrupted", log3 = s.a.work + "/interrupted.txt";
    std::vector<std::string> args = s.grade_args(out3);
    args.insert(args.end(), {"--only", list});
    std::printf("== SIGTERM to a run grading %s, then the run again\n", list.c_str());
    const pid_t run = start_grading(args, log3);
    if (!wait_for(log3, "Grading ", run, 60))
        s.problems.push_back("the run to interrupt did not start: " + read_file(log3));
    usleep(1500000);  // compiling and testing by now
    kill(run, SIGTERM);
    const int code = wait_exit(run, 10);
    std::printf("%s", read_file(log3).c_str());
    if (code != 128 + SIGTERM || read_file(log3).find("Interrupted by SIGTERM") == std::string::npos)
        s.problems.push_back("the interrupted run did not stop as it should (status " + std::to_string(code) + ")");
    usleep(300000);
    for (const auto& p : processes_mentioning(out3))
        s.problems.push_back("left running after the interrupted run: " + p);
    for (const auto& name : list_dir(out3 + "/.work"))
        s.problems.push_back("left in .work by the interrupted run: " + name);
    const int again = wait_exit(start_grading(args, log3), 600);
    if (again != 0) s.problems.push_back("the run after the interrupted one failed: " + read_file(log3));
    for (const auto& x : some)
        for (const char* ext : {".json", ".tsv"})
            if (!same_file(s.out + "/results/" + x + ext, out3 + "/results/" + x + ext))
                s.problems.push_back(x + ext + ": the run after an interrupted one differs from the first run");
}

// The table, the time per submission and the verdict of the suite.
int finish(const Suite& s, const std::vector<Row>& rows, double wall) {
    for (const auto& name : s.skipped)
        std::printf("== Not run here: the case %s (it needs %s)\n", name.c_str(),
                    s.root ? "the namespaces sandbox" : "root");
    std::printf(
        "\n| Submission | What it does | Exercise | Expected | Got | Tests | Score "
        "|\n|---|---|---|---|---|---:|---:|\n");
    for (const auto& row : rows)
        std::printf("| %s | %s | %s | %s | %s | %d | %s / %s |\n", row.student.c_str(), row.description.c_str(),
                    row.exercise.c_str(), row.expected.c_str(), row.got.c_str(), row.tests,
                    format_number(row.score).c_str(), format_number(row.max_score).c_str());
    std::printf(
        "\n%d submissions graded with -j %d in %s s: %s s per submission (%s/first-run.json has each one's time)\n",
        s.n, s.a.jobs, format_number(wall).c_str(), format_number(wall / s.n).c_str(), s.a.work.c_str());
    if (!s.problems.empty()) {
        std::printf("\ngrading suite FAILED:\n");
        for (const auto& p : s.problems) std::printf("  %s\n", p.c_str());
        return 1;
    }
    std::printf("grading suite: every submission got the expected verdicts; resumed and repeated runs agree\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Suite s;
    if (const int status = parse(argc, argv, s.a); status != 0) return status;
    if (const auto problem = load_setup(s.a.setup_dir, s.setup); !problem.empty())
        return std::fprintf(stderr, "grading_suite: %s\n", problem.c_str()), 2;
    const std::string sandbox = configure_sandbox();
    s.root = geteuid() == 0, s.namespaces = isolation() == Isolation::namespaces;
    std::printf("== %s%s\n", sandbox.c_str(), s.root ? " (running as root)" : "");
    read_cases(s);
    if (s.cases.empty()) return std::fprintf(stderr, "grading_suite: no cases in %s\n", s.a.cases_dir.c_str()), 2;
    s.subs = s.a.work + "/submissions", s.out = s.a.work + "/out";
    remove_tree(s.a.work);
    plant_secret(s);
    if (const auto problem = make_submissions(s); !problem.empty())
        return std::fprintf(stderr, "grading_suite: %s\n", problem.c_str()), 2;
    const std::string jobs = std::to_string(s.a.jobs), max_kb = std::to_string(Suite::max_file_kb);
    s.run_args = {s.a.harness, "grade", "--setup",         s.a.setup_dir, s.subs,           s.out,
                  "-j",        jobs,    "--timeout",       s.a.timeout,   "--wall-timeout", s.a.wall_timeout,
                  "--memory",  "512",   "--max-file-size", max_kb};
    const double wall = first_run(s);
    // Every result as first written, to prove below that nothing rewrote one later.
    std::map<std::string, std::string> written;
    for (const auto& name : list_dir(s.out + "/results")) written[name] = read_file(s.out + "/results/" + name);
    std::vector<Row> rows;
    for (const auto& [student, c] : s.case_of) check_submission(s, student, *c, rows, s.out);
    check_resumed(s);
    check_deterministic(s);
    check_student_check(s);
    check_interrupted(s);
    check_seeded(s, rows);
    check_every_exercise_seeded(s);
    find_secret(s, s.a.work);
    // Nothing rewrote a result after it was written (a process that outlived its test, say).
    for (const auto& [name, text] : written)
        if (read_file(s.out + "/results/" + name) != text)
            s.problems.push_back("results/" + name + " changed after it was written");
    return finish(s, rows, wall);
}
