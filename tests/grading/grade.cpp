// Grading one submission: take its exercise files (and nothing else), build each topic on its
// own against the instructor's prebuilt objects, run every test in its own process, and decide
// each verdict from the XML file doctest writes for the harness, never from what the student's
// code prints.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "grading.hpp"

namespace grading {

namespace {

// The text of the first <tag>...</tag> in xml[from, to), decoded, without the indentation.
std::string element_text(const std::string& xml, const std::string& tag, std::size_t from, std::size_t to,
                         std::size_t* after = nullptr) {
    const auto open = xml.find("<" + tag, from);
    if (open == std::string::npos || open >= to) return {};
    const auto body = xml.find('>', open);
    const auto close = xml.find("</" + tag + ">", body);
    if (body == std::string::npos || close == std::string::npos || close > to) return {};
    if (after) *after = close + tag.size() + 3;
    // The reporter indents the first line of a text; the others (a matrix's rows) keep their
    // own alignment.
    std::string text;
    for (const auto& line : split(decode_xml(xml.substr(body + 1, close - body - 1)), '\n')) {
        std::string t = line.substr(0, line.find_last_not_of(" \t\r") + 1);
        if (text.empty()) t = trim(t);
        if (t.empty() && text.empty()) continue;
        if (!text.empty()) text += '\n';
        text += t;
    }
    return trim(text);
}

std::string indent(const std::string& text, const std::string& prefix) {
    std::string out;
    for (const auto& line : split(text, '\n')) out += prefix + line + "\n";
    return out;
}

// Why a test case failed, from its part of the XML report: the first failed check (where,
// what, with which values, and what it logged: expected, actual, tolerance) or the exception.
std::string failure_details(const Setup& setup, const std::string& xml, std::size_t from, std::size_t to) {
    const auto expression = xml.find("<Expression success=\"false\"", from);
    const auto exception = xml.find("<Exception", from);
    std::string out;
    if (expression != std::string::npos && expression < to && (exception == std::string::npos || expression < exception)) {
        const std::string head = xml.substr(expression, xml.find('>', expression) - expression);
        const auto end = xml.find("</Expression>", expression);
        const std::size_t stop = end == std::string::npos ? to : end;
        out += relative_to_root(setup, xml_attribute(head, "filename")) + ":" + xml_attribute(head, "line") + ": " +
               xml_attribute(head, "type") + "( " + element_text(xml, "Original", expression, stop) + " ) failed\n";
        const std::string expanded = element_text(xml, "Expanded", expression, stop);
        if (!expanded.empty()) out += "  with values: " + expanded + "\n";
        const std::string thrown = element_text(xml, "Exception", expression, stop);
        const std::string wanted = element_text(xml, "ExpectedException", expression, stop);
        if (!wanted.empty()) out += "  expected it to throw " + wanted + (thrown.empty() ? ", and it did not" : "") + "\n";
        if (!thrown.empty()) out += "  threw: " + thrown + "\n";
        for (std::size_t p = expression, next = 0;; p = next) {
            const std::string info = element_text(xml, "Info", p, stop, &next);
            if (info.empty()) break;
            out += indent(info, "  ");
        }
    } else if (exception != std::string::npos && exception < to) {
        const std::string head = xml.substr(exception, xml.find('>', exception) - exception);
        out += std::string(xml_attribute(head, "crash") == "true" ? "crashed: " : "threw an exception: ") +
               element_text(xml, "Exception", exception, to) + "\n";
    }
    const auto overall = xml.find("<OverallResultsAsserts", from);
    if (overall != std::string::npos && overall < to) {
        const std::string head = xml.substr(overall, xml.find('>', overall) - overall);
        const std::string failures = xml_attribute(head, "failures");
        if (!failures.empty() && failures != "0" && failures != "1")
            out += "(" + failures + " checks failed in this test; the first is shown)\n";
    }
    return out.empty() ? "the test failed\n" : out;
}

std::string first_error(const std::string& log) {
    for (const auto& line : split(log, '\n')) {
        if (starts_with(line, "collect2:")) continue;
        if (line.find("error:") != std::string::npos || line.find("undefined reference") != std::string::npos ||
            line.find("multiple definition") != std::string::npos || line.find("out of memory") != std::string::npos ||
            line.find("memory exhausted") != std::string::npos)
            return trim(line);
    }
    return {};
}

std::string build_problem(const Outcome& o, const std::string& what, const std::string& log, const Limits& limits) {
    if (!o.started) return "could not run the " + what + ": " + o.error;
    if (o.timed_out || o.signal == SIGXCPU)
        return "the " + what + " took longer than " + format_number(limits.wall_seconds) + " s and was stopped";
    const std::string error = first_error(log);
    if (!error.empty()) return error;
    if (o.signal) return "the " + what + " was killed by " + signal_name(o.signal) + " (memory limit " +
                         std::to_string(limits.memory_mb) + " MB?)";
    return "the " + what + " failed with exit status " + std::to_string(o.exit_code);
}

// Tests come from the graders only: an exercise file that uses doctest (to register test
// cases or reporters of its own) is refused, as the symbols of its object show.
std::string test_framework_use(const Setup& setup, const std::string& object, const std::string& work_dir,
                               const Options& options) {
    if (setup.nm.empty()) return {};
    const std::string listing = work_dir + "/logs/symbols.txt";
    const Outcome o = run_limited({setup.nm, "-C", object}, work_dir, listing, options.build_limits);
    if (!o.started || o.exit_code != 0) return {};
    for (const auto& line : split(read_file(listing), '\n'))
        if (line.find(" doctest::") != std::string::npos)
            return "uses the test framework (doctest): exercise files must not define tests or reporters";
    return {};
}

struct Run {
    std::string verdict, message;
    bool not_started = false;
};

// The verdict of one test from how its process ended and from the XML file.
Run decide(const Setup& setup, const Topic& topic, const Test& test,
           const Outcome& o, const std::string& xml, const Options& options) {
    Run r;
    const double limit = options.test_limits.wall_seconds;
    if (!o.started) return {"crash", "could not start the test: " + o.error};
    if (o.timed_out) return {"timeout", "timed out after " + format_number(limit) + " s and was stopped: an endless loop, or far too much work?"};
    if (o.signal == SIGXCPU) return {"timeout", "used more than " + format_number(limit) + " s of processor time and was stopped"};
    if (o.signal == SIGXFSZ)
        return {"crash", "output limit exceeded: the test wrote more than " + std::to_string(options.test_limits.output_bytes) +
                             " bytes and was stopped (SIGXFSZ)"};
    if (o.signal) {
        // doctest's own account of the signal, when it could write one ("SIGSEGV - Segmentation
        // violation signal"), else the signal's name.
        std::string message = "crashed with " + signal_name(o.signal);
        const auto p = xml.find("<Exception crash=\"true\"");
        const std::string doctest_says = p == std::string::npos ? "" : element_text(xml, "Exception", p, xml.size());
        if (starts_with(doctest_says, signal_name(o.signal))) message = "crashed with " + doctest_says;
        return {"crash", message};
    }
    // It exited. Only a test case from the grader's own file, at its own line, closed with its
    // result, counts; and the process must then exit with status 0.
    int found = 0;
    std::size_t start = 0, end = 0;
    bool closed = false, success = false, misplaced = false;
    for (std::size_t pos = 0; (pos = xml.find("<TestCase ", pos)) != std::string::npos; ++pos) {
        const auto head_end = xml.find('>', pos);
        if (head_end == std::string::npos) break;
        const std::string head = xml.substr(pos, head_end - pos);
        if (xml_attribute(head, "name") != test.name || xml_attribute(head, "skipped") == "true") continue;
        ++found;
        start = pos;
        misplaced = xml_attribute(head, "filename") != setup.root + "/" + topic.test_file ||
                    xml_attribute(head, "line") != std::to_string(test.line);
        end = xml.find("</TestCase>", pos);
        closed = false;
        if (end != std::string::npos) {
            const auto overall = xml.find("<OverallResultsAsserts", pos);
            if (overall != std::string::npos && overall < end) {
                closed = true;
                const std::string o_head = xml.substr(overall, xml.find('>', overall) - overall);
                success = xml_attribute(o_head, "test_case_success") == "true";
            }
        }
    }
    const std::string status = "the process exited with status " + std::to_string(o.exit_code);
    if (found > 1) return {"fail", "more than one test case with this name ran; tests are only taken from the graders"};
    if (found == 1 && misplaced) return {"fail", "the test case ran from an unexpected place; tests are only taken from the graders"};
    if (found == 0 || !closed)
        return {"fail", "the test did not report completion: " + status +
                            " before the test finished (exit(), quick_exit() or _exit() in the exercise code?)"};
    if (success) {
        if (o.exit_code == 0) return {"pass", ""};
        return {"fail", "the test passed but then " + status};
    }
    r.verdict = "fail";
    r.message = failure_details(setup, xml, start, end);
    if (!r.message.empty() && r.message.back() == '\n') r.message.pop_back();
    return r;
}

}  // namespace

std::string Selection::key() const {
    std::string k;
    for (const auto& t : topics) k += t + ",";
    return k + "/" + exercise;
}

std::string exercise_folder(const std::string& dir) {
    return is_directory(dir + "/exercises") ? dir + "/exercises" : dir;
}

std::vector<SubmittedFile> collect_files(const Setup& setup, const Options& options, const std::string& dir) {
    std::vector<SubmittedFile> files;
    struct stat st;
    const bool linked_folder = lstat((dir + "/exercises").c_str(), &st) == 0 && S_ISLNK(st.st_mode);
    const bool linked_submission = lstat(dir.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
    const std::string folder = exercise_folder(dir);
    for (const auto& topic : setup.topics) {
        SubmittedFile f{topic.name, "ok", "", ""};
        const std::string shown = "exercises/" + topic.name + ".cpp";
        const std::string path = folder + "/" + topic.name + ".cpp";
        if (linked_submission || linked_folder) {
            f.state = "refused", f.reason = std::string(linked_submission ? "the submission folder" : "exercises/") +
                                            " is a symbolic link: refused";
        } else if (lstat(path.c_str(), &st) != 0) {
            f.state = "missing", f.reason = shown + " is not in the submission";
        } else if (S_ISLNK(st.st_mode)) {
            f.state = "refused", f.reason = shown + " is a symbolic link: refused (submit the file itself)";
        } else if (!S_ISREG(st.st_mode)) {
            f.state = "refused", f.reason = shown + " is not a regular file: refused";
        } else if (st.st_size > options.max_file_bytes) {
            f.state = "refused", f.reason = shown + " is " + std::to_string(st.st_size) + " bytes, more than the limit of " +
                                            std::to_string(options.max_file_bytes) + ": refused";
        } else {
            const int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK);
            std::string content;
            if (fd >= 0) {
                char buffer[65536];
                ssize_t n;
                while ((n = read(fd, buffer, sizeof buffer)) > 0 &&
                       content.size() <= static_cast<std::size_t>(options.max_file_bytes))
                    content.append(buffer, static_cast<std::size_t>(n));
                close(fd);
            }
            if (fd < 0) {
                f.state = "refused", f.reason = shown + " cannot be read: " + std::strerror(errno);
            } else if (content.size() > static_cast<std::size_t>(options.max_file_bytes)) {
                f.state = "refused", f.reason = shown + " is more than " + std::to_string(options.max_file_bytes) + " bytes: refused";
            } else if (content.find('\0') != std::string::npos) {
                f.state = "refused", f.reason = shown + " is not a text file (it holds NUL bytes): refused";
            } else {
                f.content = content;
            }
        }
        files.push_back(f);
    }
    return files;
}

std::string fingerprint(const Setup& setup, const Options& options, const std::vector<SubmittedFile>& files,
                        const std::string& selection) {
    std::ostringstream all;
    all << setup.fingerprint << "\n" << selection << "\n"
        << options.test_limits.wall_seconds << " " << options.test_limits.memory_mb << " "
        << options.test_limits.output_bytes << " " << options.build_limits.wall_seconds << " "
        << options.build_limits.memory_mb << " " << options.max_file_bytes << "\n";
    for (const auto& f : files) all << f.topic << " " << f.state << " " << f.reason << " " << hex(hash(f.content)) << "\n";
    return hex(hash(all.str()));
}

SubmissionResult grade_submission(const Setup& setup, const Options& options, const std::string& student,
                                  const std::vector<SubmittedFile>& files, const Selection& selection,
                                  const std::string& work_dir, const std::string& log_dir) {
    SubmissionResult result;
    result.student = student;
    result.fingerprint = fingerprint(setup, options, files, selection.key());
    remove_tree(work_dir);
    for (const char* sub : {"exercises", "obj", "bin", "run", "logs"}) make_dirs(work_dir + "/" + sub);
    if (!log_dir.empty()) make_dirs(log_dir);
    // Messages name the student's file as exercises/<topic>.cpp and the workbook's files by
    // their paths in the workbook, whatever folders the run uses.
    auto relative = [&](const std::string& text) { return relative_to_root(setup, replace_all(text, work_dir + "/", "")); };

    for (std::size_t k = 0; k < setup.topics.size(); ++k) {
        const Topic& topic = setup.topics[k];
        const SubmittedFile& file = files[k];
        if (!selection.topics.empty() && !selection.topics.count(topic.name)) continue;
        std::string problem, verdict;
        if (file.state != "ok") {
            verdict = "missing", problem = file.reason;
        } else {
            const std::string source = work_dir + "/exercises/" + topic.name + ".cpp";
            const std::string object = work_dir + "/obj/" + topic.name + ".o";
            const std::string binary = work_dir + "/bin/grade_" + topic.name;
            const std::string log = work_dir + "/logs/" + topic.name + ".txt";
            write_file(source, file.content);
            std::vector<std::string> compile;
            for (const auto& w : topic.compile) compile.push_back(w == "@SOURCE@" ? source : w == "@OBJECT@" ? object : w);
            Outcome o = run_limited(compile, work_dir, log, options.build_limits);
            std::string text = relative(read_file(log));
            std::string build_log = "$ compile exercises/" + topic.name + ".cpp\n" + first_lines(text, 200000);
            if (!o.started || o.timed_out || o.signal || o.exit_code != 0) {
                verdict = "build error", problem = build_problem(o, "compiler", text, options.build_limits);
            } else if (const std::string why = test_framework_use(setup, object, work_dir, options); !why.empty()) {
                verdict = "build error", problem = "exercises/" + topic.name + ".cpp " + why;
                build_log += "$ nm exercises/" + topic.name + ".o\n" + problem + "\n";
            } else {
                std::vector<std::string> link = {setup.compiler};
                link.insert(link.end(), setup.link_flags.begin(), setup.link_flags.end());
                link.insert(link.end(), topic.objects.begin(), topic.objects.end());
                link.push_back(object);
                link.insert(link.end(), topic.link.begin(), topic.link.end());
                link.push_back("-o");
                link.push_back(binary);
                o = run_limited(link, work_dir, log, options.build_limits);
                text = relative(read_file(log));
                build_log += "$ link with the graders of " + topic.name + "\n" + first_lines(text, 200000);
                if (!o.started || o.timed_out || o.signal || o.exit_code != 0)
                    verdict = "build error", problem = build_problem(o, "linker", text, options.build_limits);
            }
            if (!log_dir.empty()) write_file(log_dir + "/" + topic.name + ".build.txt", build_log);
            if (verdict.empty()) {
                // Every test in its own process.
                const std::string run_dir = work_dir + "/run";
                const std::string output_path = work_dir + "/logs/output.txt";
                std::string file_filter = setup.root + "/" + topic.test_file;
                if (file_filter.find_first_of(",*?[]\\") != std::string::npos)
                    file_filter = "*" + topic.test_file.substr(topic.test_file.rfind('/'));
                for (const auto& exercise : topic.exercises) {
                    if (!selection.exercise.empty() && exercise.name != selection.exercise) continue;
                    for (const auto& test : exercise.tests) {
                        remove_tree(run_dir);
                        make_dirs(run_dir);
                        std::string xml;
                        const Outcome t = run_limited({binary, "-tc=" + test.name, "-sf=" + file_filter, "--reporters=xml",
                                                       "--out=/dev/fd/3", "--no-colors"},
                                                      run_dir, output_path, options.test_limits, &xml);
                        Run r = decide(setup, topic, test, t, xml, options);
                        // An exercise whose body is still the stub's todo("<name>") is not started.
                        if (r.verdict == "fail" && file.content.find("todo(\"" + exercise.name + "\")") != std::string::npos) {
                            r.not_started = true;
                            r.message = "not started: todo(\"" + exercise.name + "\") is still in place";
                        }
                        TestResult tr{topic.chapter, topic.name, exercise.name, test.name, r.verdict, 0,
                                      exercise.points / static_cast<double>(exercise.tests.size()), r.not_started,
                                      relative(r.message), ""};
                        if (tr.verdict == "pass") tr.score = tr.max_score;
                        std::string printed = read_file(output_path);
                        if (printed.size() > 500) printed = first_lines(printed, 500);
                        tr.output = printed;
                        result.tests.push_back(tr);
                    }
                }
                continue;
            }
        }
        result.notes.push_back((verdict == "build error" ? "exercises/" + topic.name + ".cpp does not build: " : "") + problem);
        for (const auto& exercise : topic.exercises) {
            if (!selection.exercise.empty() && exercise.name != selection.exercise) continue;
            for (const auto& test : exercise.tests)
                result.tests.push_back({topic.chapter, topic.name, exercise.name, test.name, verdict, 0,
                                        exercise.points / static_cast<double>(exercise.tests.size()), false,
                                        problem, ""});
        }
    }
    for (const auto& t : result.tests) result.score += t.score, result.max_score += t.max_score;
    if (!options.keep_work) remove_tree(work_dir);
    return result;
}

// ---- results -----------------------------------------------------------------------------------

// Gradescope's results.json: a total, and per test its score, maximum, status and output.
// Everything in it follows from the inputs alone, so a repeated run writes the same bytes.
std::string results_json(const Setup& setup, const SubmissionResult& r) {
    int passed = 0;
    for (const auto& t : r.tests) passed += t.verdict == "pass";
    std::string summary = std::to_string(passed) + " of " + std::to_string(r.tests.size()) + " tests pass; score " +
                          format_number(r.score) + " of " + format_number(r.max_score) + ".";
    for (const auto& n : r.notes) summary += "\n" + n;
    std::string out = "{\n";
    out += "  \"score\": " + format_number(r.score) + ",\n";
    out += "  \"output\": " + json_string(summary) + ",\n";
    out += "  \"visibility\": \"visible\",\n";
    out += "  \"stdout_visibility\": \"hidden\",\n";
    out += "  \"extra_data\": {\"student\": " + json_string(r.student) + ", \"max_score\": " + format_number(r.max_score) +
           ", \"harness\": " + json_string(harness_version) + ", \"fingerprint\": " + json_string(r.fingerprint) + "},\n";
    out += "  \"tests\": [";
    std::string chapter;
    int in_chapter = 0;
    for (std::size_t k = 0; k < r.tests.size(); ++k) {
        const TestResult& t = r.tests[k];
        const Chapter* c = find_chapter(setup, t.chapter);
        in_chapter = t.chapter == chapter ? in_chapter + 1 : 1;
        chapter = t.chapter;
        std::string text = t.verdict == "pass" ? "pass" : t.verdict + ": " + t.message;
        if (!t.output.empty()) text += "\n\nThe test printed:\n" + t.output;
        out += k ? ",\n" : "\n";
        out += "    {\"name\": " + json_string(t.name) + ", \"score\": " + format_number(t.score) +
               ", \"max_score\": " + format_number(t.max_score) + ", \"status\": \"" +
               (t.verdict == "pass" ? "passed" : "failed") + "\",\n";
        out += "     \"number\": " + json_string((c ? std::to_string(c->number) : t.chapter) + "." + std::to_string(in_chapter)) +
               ", \"tags\": [" + json_string(t.chapter) + ", " + json_string(t.topic) + ", " + json_string(t.exercise) +
               "], \"visibility\": \"visible\",\n";
        out += "     \"output\": " + json_string(text) + ",\n";
        out += "     \"extra_data\": {\"verdict\": " + json_string(t.verdict) + ", \"chapter\": " + json_string(t.chapter) +
               ", \"topic\": " + json_string(t.topic) + ", \"exercise\": " + json_string(t.exercise) +
               ", \"not_started\": " + (t.not_started ? "true" : "false") + "}}";
    }
    out += "\n  ]\n}\n";
    return out;
}

namespace {
std::string flat(const std::string& s) {
    std::string out = s;
    for (char& c : out)
        if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    return out;
}
}  // namespace

std::string results_tsv(const SubmissionResult& r) {
    std::string out = "fingerprint\t" + r.fingerprint + "\nstudent\t" + flat(r.student) + "\n";
    for (const auto& n : r.notes) out += "note\t" + flat(n) + "\n";
    for (const auto& t : r.tests) {
        char score[64], max_score[64];
        std::snprintf(score, sizeof score, "%.17g", t.score);
        std::snprintf(max_score, sizeof max_score, "%.17g", t.max_score);
        out += "test\t" + t.chapter + "\t" + t.topic + "\t" + t.exercise + "\t" + t.verdict + "\t" + score + "\t" +
               max_score + "\t" + (t.not_started ? "1" : "0") + "\t" + flat(t.name) + "\t" +
               flat(first_lines(t.message, 300)) + "\n";
    }
    return out;
}

bool read_results_tsv(const std::string& path, SubmissionResult& r) {
    bool ok = false;
    const std::string text = read_file(path, &ok);
    if (!ok) return false;
    r = SubmissionResult{};
    for (const auto& line : split(text, '\n')) {
        const auto f = split(line, '\t');
        if (f[0] == "fingerprint" && f.size() > 1) r.fingerprint = f[1];
        else if (f[0] == "student" && f.size() > 1) r.student = f[1];
        else if (f[0] == "note" && f.size() > 1) r.notes.push_back(f[1]);
        else if (f[0] == "test" && f.size() > 9) {
            TestResult t{f[1], f[2], f[3], f[8], f[4], std::stod(f[5]), std::stod(f[6]), f[7] == "1", f[9], ""};
            r.tests.push_back(t);
            r.score += t.score;
            r.max_score += t.max_score;
        }
    }
    return !r.fingerprint.empty();
}

}  // namespace grading
