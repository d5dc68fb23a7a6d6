// The grading harness's own test: bad submissions get the verdicts they deserve.
//
//   grading_suite --setup <build>/grading --harness <workbook_grade> --cases <folder> --work <folder>
//                 [--count <n>] [--jobs <n>] [--timeout <s>]
//
// Builds one submission folder per recipe in tests/grading/cases/ (see its README.md), or
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

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "grading.hpp"

using namespace grading;

namespace {

struct Expect {
    std::string key, verdict, text;
};

struct Case {
    std::string name, description, make, topic = "rotation", body, base = "solutions", student;
    bool needs_root = false, needs_namespaces = false;
    std::vector<std::string> replace;
    std::vector<Expect> expects;
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
        if ((v = field("case")) != "\x01") c.description = v;
        else if ((v = field("make")) != "\x01") c.make = v;
        else if ((v = field("topic")) != "\x01") c.topic = v;
        else if ((v = field("base")) != "\x01") c.base = v;
        else if ((v = field("needs")) != "\x01") c.needs_root = v.find("root") != std::string::npos,
                                                   c.needs_namespaces = v.find("namespaces") != std::string::npos;
        else if ((v = field("replace")) != "\x01") c.replace.push_back(v);
        else if ((v = field("expect")) != "\x01") {
            const auto parts = split(v, '|');
            c.expects.push_back({trim(parts[0]), parts.size() > 1 ? trim(parts[1]) : "", parts.size() > 2 ? trim(parts[2]) : ""});
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
const Expect* expectation(const Case& c, const TestResult& t) {
    const Expect* best = nullptr;
    std::size_t best_length = 0;
    for (const auto& e : c.expects) {
        const bool match = e.key == "*" || e.key == t.exercise || (e.key.find(':') != std::string::npos && starts_with(t.name, e.key));
        const std::size_t length = e.key == "*" ? 0 : e.key.size();
        if (match && (!best || length > best_length)) best = &e, best_length = length;
    }
    return best;
}

std::string quote(const std::string& s) { return "'" + replace_all(s, "'", "'\\''") + "'"; }

// Starts `workbook_grade grade ...` with its output into a file; returns its process id.
pid_t start_grading(const std::vector<std::string>& argv, const std::string& output) {
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
        const int fd = open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) dup2(fd, 1), dup2(fd, 2);
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execv(args[0], args.data());
        _exit(127);
    }
    return pid;
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
int wait_exit(pid_t pid, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    int status = 0;
    while (std::chrono::steady_clock::now() < end) {
        if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        usleep(20000);
    }
    return -1;
}

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

}  // namespace

int main(int argc, char** argv) {
    std::string setup_dir, harness, cases_dir, work;
    int count = 0, jobs = 2;
    std::string timeout = "2";
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string o = argv[i], v = argv[i + 1];
        if (o == "--setup") setup_dir = v;
        else if (o == "--harness") harness = v;
        else if (o == "--cases") cases_dir = v;
        else if (o == "--work") work = v;
        else if (o == "--count") count = std::stoi(v);
        else if (o == "--jobs") jobs = std::stoi(v);
        else if (o == "--timeout") timeout = v;
        else return std::fprintf(stderr, "grading_suite: unknown option %s\n", o.c_str()), 2;
    }
    if (setup_dir.empty() || harness.empty() || cases_dir.empty() || work.empty())
        return std::fprintf(stderr, "usage: grading_suite --setup <dir> --harness <exe> --cases <dir> --work <dir> [--count n]\n"), 2;
    Setup setup;
    if (const auto problem = load_setup(setup_dir, setup); !problem.empty())
        return std::fprintf(stderr, "grading_suite: %s\n", problem.c_str()), 2;

    const std::string sandbox = configure_sandbox();
    const bool root = geteuid() == 0, namespaces = isolation() == Isolation::namespaces;
    std::printf("== %s%s\n", sandbox.c_str(), root ? " (running as root)" : "");
    std::vector<Case> cases;
    std::vector<std::string> skipped;
    for (const auto& name : list_dir(cases_dir)) {
        if (!ends_with(name, ".cpp")) continue;
        Case c = read_case(cases_dir + "/" + name, name.substr(0, name.size() - 4));
        // A trick that needs root (to prove what root cannot do) or the namespaces (to prove what
        // they hide) is graded only where that holds, and named when it is not.
        if ((c.needs_root && !root) || (c.needs_namespaces && !namespaces)) {
            skipped.push_back(c.name);
            continue;
        }
        cases.push_back(c);
    }
    if (cases.empty()) return std::fprintf(stderr, "grading_suite: no cases in %s\n", cases_dir.c_str()), 2;

    // The submissions: one per case, or <count> cycling through them.
    const long max_file_kb = 64;
    remove_tree(work);
    const std::string subs = work + "/submissions", out = work + "/out";

    make_dirs(subs);
    std::map<std::string, const Case*> case_of;
    const int n = count > 0 ? count : static_cast<int>(cases.size());
    for (int k = 0; k < n; ++k) {
        const Case& c = cases[static_cast<std::size_t>(k) % cases.size()];
        char prefix[16];
        std::snprintf(prefix, sizeof prefix, "s%02d_", k + 1);
        const std::string student = count > 0 ? prefix + c.name : c.name;
        case_of[student] = &c;
        const std::string folder = subs + "/" + student + "/exercises";
        make_dirs(folder);
        const std::string file = folder + "/" + c.topic + ".cpp";
        const std::string reference = setup.root + "/solutions/" + c.topic + ".cpp";
        if (c.make == "reference" || c.make == "stubs") {
            for (const auto& t : setup.topics)
                if (c.make == "reference" || t.name == c.topic)
                    write_file(folder + "/" + t.name + ".cpp",
                               read_file(c.make == "reference" ? setup.root + "/solutions/" + t.name + ".cpp" : pristine_stub(setup, t.name)));
        } else if (c.make == "missing") {
        } else if (c.make == "symlink") {
            if (symlink(reference.c_str(), file.c_str()) != 0) return std::perror("symlink"), 2;
        } else if (c.make == "oversized") {
            std::string text = read_file(reference) + "\n/*";
            while (text.size() <= static_cast<std::size_t>(max_file_kb * 1024)) text += " padding padding padding padding\n";
            write_file(file, text + "*/\n");
        } else if (!c.make.empty()) {
            return std::fprintf(stderr, "grading_suite: %s: unknown make: %s\n", c.name.c_str(), c.make.c_str()), 2;
        } else {
            // The case's code after solutions/<topic>.cpp (or the stub, with base: stubs).
            const std::string base = c.base == "stubs" ? pristine_stub(setup, c.topic) : reference;
            std::string text = "// Generated by grading_suite from tests/grading/cases/" + c.name + ".cpp and " +
                               relative_to_root(setup, base) + "\n";
            for (const auto& f : c.replace) text += "#define " + f + " " + f + "_reference_unused\n";
            text += read_file(base);
            for (const auto& f : c.replace) text += "#undef " + f + "\n";
            std::string body = replace_all(c.body, "@ROOT@", setup.root);
            body = replace_all(body, "@BUILD@", setup.build);
            body = replace_all(body, "@OUT@", out);
            body = replace_all(body, "@STUDENT@", student);
            write_file(file, text + "\n// The case:\n" + body);
        }
    }

    const std::string options = " -j " + std::to_string(jobs) + " --timeout " + timeout +
                                " --memory 512 --max-file-size " + std::to_string(max_file_kb);
    const std::string grade = quote(harness) + " grade --setup " + quote(setup_dir) + " " + quote(subs) + " ";
    std::printf("== Grading %d bad and good submissions\n", n);
    std::fflush(stdout);
    std::vector<std::string> problems;
    std::vector<std::string> run_args = {harness, "grade", "--setup", setup_dir, subs, out, "-j", std::to_string(jobs),
                                         "--timeout", timeout, "--memory", "512", "--max-file-size", std::to_string(max_file_kb)};
    const auto start = std::chrono::steady_clock::now();
    const std::string main_log = work + "/grade.txt", overlap_log = work + "/overlap.txt";
    const pid_t main_run = start_grading(run_args, main_log);
    // An overlapping run on the same out folder, while the first one grades: refused, with the reason.
    if (!wait_for(main_log, "Grading ", main_run, 60)) problems.push_back("the grading run did not start: " + read_file(main_log));
    const int overlap = wait_exit(start_grading(run_args, overlap_log), 60);
    if (overlap != 2 || read_file(overlap_log).find("another grading run is writing to") == std::string::npos)
        problems.push_back("an overlapping run on the same out folder was not refused (status " + std::to_string(overlap) +
                           "): " + read_file(overlap_log));
    const int status = wait_exit(main_run, 3600);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s", read_file(main_log).c_str());
    std::printf("== An overlapping run on the same out folder: %s", read_file(overlap_log).c_str());
    if (status != 0) problems.push_back("the grading run failed (status " + std::to_string(status) + ")");
    // The first run's timings (run.json is rewritten by every run), and every result as first
    // written, to prove below that nothing rewrote one later.
    write_file(work + "/first-run.json", read_file(out + "/run.json"));
    std::map<std::string, std::string> written;
    for (const auto& name : list_dir(out + "/results")) written[name] = read_file(out + "/results/" + name);

    // Every verdict, message and partial score as expected.
    struct Row {
        std::string student, description, exercise, expected, got;
        int tests = 0;
        double score = 0, max_score = 0;
    };
    std::vector<Row> rows;
    for (const auto& [student, c] : case_of) {
        SubmissionResult r;
        if (!read_results_tsv(out + "/results/" + student + ".tsv", r)) {
            problems.push_back(student + ": no results");
            continue;
        }
        const std::string json = read_file(out + "/results/" + student + ".json");
        if (json.find("\"tests\": [") == std::string::npos || json.find("\"score\": ") == std::string::npos)
            problems.push_back(student + ": results.json lacks score or tests");
        std::map<std::string, double> exercise_score;
        std::map<std::string, Row> by_key;  // rows of the table: one per expectation of the case
        for (const auto& t : r.tests) {
            std::string want = "missing", text;
            if (t.topic == c->topic || c->make == "reference") want = "pass";
            if (t.topic == c->topic)
                if (const Expect* e = expectation(*c, t)) want = e->verdict, text = e->text;
            const std::string got = t.not_started ? "not started" : t.verdict;
            if (got != want) problems.push_back(student + ": \"" + t.name + "\": expected " + want + ", got " + got + ": " + t.message);
            else if (!text.empty() && t.message.find(text) == std::string::npos)
                problems.push_back(student + ": \"" + t.name + "\": the message lacks \"" + text + "\": " + t.message);
            exercise_score[t.exercise] += t.score;
            if (const Expect* e = t.topic == c->topic ? expectation(*c, t) : nullptr) {
                Row& row = by_key[e->key];
                row.exercise = e->key == "*" ? "every exercise of " + c->topic : e->key;
                if (row.expected.find(want) == std::string::npos) row.expected += (row.expected.empty() ? "" : ", ") + want;
                if (row.got.find(got) == std::string::npos) row.got += (row.got.empty() ? "" : ", ") + got;
                ++row.tests;
                row.score += t.score;
                row.max_score += t.max_score;
            }
        }
        for (const auto& [exercise, points] : c->scores)
            if (std::abs(exercise_score[exercise] - points) > 1e-9)
                problems.push_back(student + ": " + exercise + " scored " + format_number(exercise_score[exercise]) +
                                   ", expected " + format_number(points));
        if (r.tests.empty()) problems.push_back(student + ": no tests graded");
        for (auto& [key, row] : by_key) {
            row.student = student;
            row.description = c->description;
            rows.push_back(row);
        }
    }

    // The class files.
    const std::string csv = read_file(out + "/class.csv");
    if (std::count(csv.begin(), csv.end(), '\n') != n + 1) problems.push_back("class.csv does not have one row per submission");
    if (read_file(out + "/summary.md").find("| Student | Score |") == std::string::npos) problems.push_back("summary.md has no table");

    // Resumed: a second run grades nothing and writes the same class files.
    std::printf("== Running again: every submission already graded\n");
    std::fflush(stdout);
    const std::string before = csv + read_file(out + "/summary.md");
    const std::string again = work + "/again.txt";
    if (std::system((grade + quote(out) + options + " > " + quote(again)).c_str()) != 0) problems.push_back("the resumed run failed");
    if (read_file(again).find("Graded 0 submissions") == std::string::npos) problems.push_back("the resumed run graded again: " + read_file(again));
    if (read_file(out + "/class.csv") + read_file(out + "/summary.md") != before) problems.push_back("the resumed run changed the class files");

    // Deterministic: a few graded again from scratch give the same bytes.
    std::vector<std::string> subset;
    for (const auto& [student, c] : case_of)
        if (subset.size() < 2 && (c->name == "crash" || c->name == "exit0")) subset.push_back(student);
    std::string only;
    for (const auto& s : subset) only += (only.empty() ? "" : ",") + s;
    std::printf("== Grading %s again from scratch\n", only.c_str());
    std::fflush(stdout);
    const std::string out2 = work + "/out-again";
    if (std::system((grade + quote(out2) + options + " --only " + quote(only)).c_str()) != 0) problems.push_back("the repeated run failed");
    for (const auto& s : subset)
        for (const char* ext : {".json", ".tsv"})
            if (!same_file(out + "/results/" + s + ext, out2 + "/results/" + s + ext))
                problems.push_back(s + ext + " differs between two runs");

    // The student's check reaches the same verdicts as the instructor's run.
    for (const auto& [student, c] : case_of) {
        if (c->name != "partial") continue;
        std::printf("== The student's check of %s\n", student.c_str());
        std::fflush(stdout);
        const std::string check_out = work + "/check";
        std::system((quote(harness) + " check --setup " + quote(setup_dir) + " --folder " +
                     quote(subs + "/" + student + "/exercises") + " --out " + quote(check_out) + options + " > " +
                     quote(work + "/check.txt"))
                        .c_str());
        const std::string mine = read_file(check_out + "/results.json"), theirs = read_file(out + "/results/" + student + ".json");
        const auto from_mine = mine.find("\"tests\": ["), from_theirs = theirs.find("\"tests\": [");
        if (from_mine == std::string::npos || from_theirs == std::string::npos ||
            mine.substr(from_mine) != theirs.substr(from_theirs))
            problems.push_back(student + ": the student's check and the grading run disagree");
        if (read_file(work + "/check.txt").find("Chapter 1, ") == std::string::npos)
            problems.push_back(student + ": the check printed no progress: " + read_file(work + "/check.txt"));
        // The first failing exercise gets its nudge, Hint 1, and only that (hints.cpp).
        const std::string printed = read_file(work + "/check.txt");
        if (printed.find("Hint 1 of 3 for geodesic_angle") == std::string::npos || printed.find("Hint 2 of") != std::string::npos)
            problems.push_back(student + ": the check did not print Hint 1 (and only Hint 1) of geodesic_angle: " + printed);
        break;
    }

    // Interrupted: SIGTERM to the main process while it grades stops its workers at once and
    // leaves no result of theirs and no process behind; running again grades them as before.
    {
        std::vector<std::string> some;
        for (const auto& [student, c] : case_of)
            if (some.size() < 3 && (c->name == "partial" || c->name == "fail" || c->name == "crash" || c->name == "exit0"))
                some.push_back(student);
        std::string list;
        for (const auto& s : some) list += (list.empty() ? "" : ",") + s;
        const std::string out3 = work + "/out-interrupted", log3 = work + "/interrupted.txt";
        std::vector<std::string> args = run_args;
        args[5] = out3;
        args.insert(args.end(), {"--only", list});
        std::printf("== SIGTERM to a run grading %s, then the run again\n", list.c_str());
        const pid_t run = start_grading(args, log3);
        if (!wait_for(log3, "Grading ", run, 60)) problems.push_back("the run to interrupt did not start: " + read_file(log3));
        usleep(1500000);  // compiling and testing by now
        kill(run, SIGTERM);
        const int code = wait_exit(run, 10);
        std::printf("%s", read_file(log3).c_str());
        if (code != 128 + SIGTERM || read_file(log3).find("Interrupted by SIGTERM") == std::string::npos)
            problems.push_back("the interrupted run did not stop as it should (status " + std::to_string(code) + ")");
        usleep(300000);
        for (const auto& p : processes_mentioning(out3)) problems.push_back("left running after the interrupted run: " + p);
        for (const auto& name : list_dir(out3 + "/.work")) problems.push_back("left in .work by the interrupted run: " + name);
        const int again = wait_exit(start_grading(args, log3), 600);
        if (again != 0) problems.push_back("the run after the interrupted one failed: " + read_file(log3));
        for (const auto& s : some)
            for (const char* ext : {".json", ".tsv"})
                if (!same_file(out + "/results/" + s + ext, out3 + "/results/" + s + ext))
                    problems.push_back(s + ext + ": the run after an interrupted one differs from the first run");
    }

    // Nothing rewrote a result after it was written (a process that outlived its test, say).
    for (const auto& [name, text] : written)
        if (read_file(out + "/results/" + name) != text) problems.push_back("results/" + name + " changed after it was written");
    for (const auto& name : skipped)
        std::printf("== Not run here: the case %s (it needs %s)\n", name.c_str(), root ? "the namespaces sandbox" : "root");

    // The table, and the time per submission.
    std::printf("\n| Submission | What it does | Exercise | Expected | Got | Tests | Score |\n|---|---|---|---|---|---:|---:|\n");
    for (const auto& row : rows)
        std::printf("| %s | %s | %s | %s | %s | %d | %s / %s |\n", row.student.c_str(), row.description.c_str(),
                    row.exercise.c_str(), row.expected.c_str(), row.got.c_str(), row.tests, format_number(row.score).c_str(),
                    format_number(row.max_score).c_str());
    std::printf("\n%d submissions graded with -j %d in %s s: %s s per submission (%s/first-run.json has each one's time)\n", n, jobs,
                format_number(wall).c_str(), format_number(wall / n).c_str(), work.c_str());
    if (!problems.empty()) {
        std::printf("\ngrading suite FAILED:\n");
        for (const auto& p : problems) std::printf("  %s\n", p.c_str());
        return 1;
    }
    std::printf("grading suite: every submission got the expected verdicts; resumed and repeated runs agree\n");
    return 0;
}
