// What is graded: the manifest (written at build time from the reference graders) and the
// build facts (grading/topics.txt, written by CMake), read back by every grading run.
#include <limits.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "grading.hpp"

namespace grading {

namespace {

// The file a path names, links followed: the build sandbox has /usr, not /etc/alternatives.
std::string real_path(const std::string& path) {
    char buffer[PATH_MAX];
    return realpath(path.c_str(), buffer) ? std::string(buffer) : path;
}

// An include folder of the build's compile command, for a student's compile: the API's as the
// build sandbox sees it (@API@), the system's as it is, nothing else (the compile sees only the API).
void include_folder(const std::string& option, std::string folder, const std::string& root, const std::string& dir,
                    std::vector<std::string>& out) {
    if (!folder.empty() && folder[0] != '/' && !dir.empty()) folder = dir + "/" + folder;
    if (starts_with(folder + "/", root + "/exercises/"))
        folder = "@API@" + folder.substr(root.size());
    else if (!starts_with(folder, "/usr/"))
        return;
    if (option == "-I")
        out.push_back("-I" + folder);
    else
        out.push_back(option), out.push_back(folder);
}

// The compile command of <file> in compile_commands.json, made into a template.
std::string compile_template(const std::string& compile_commands, const std::string& root,
                             const std::vector<std::string>& candidates, std::vector<std::string>& out) {
    bool ok = false;
    const std::string text = read_file(compile_commands, &ok);
    if (!ok) return "cannot read " + compile_commands + " (configure with CMAKE_EXPORT_COMPILE_COMMANDS=ON)";
    const nlohmann::json all = nlohmann::json::parse(text, nullptr, false);
    if (!all.is_array()) return compile_commands + " is not a JSON array";
    for (const auto& file : candidates) {
        for (const auto& entry : all) {
            if (!entry.is_object() || entry.value("file", "") != file) continue;
            std::vector<std::string> words;
            if (entry.contains("arguments") && entry["arguments"].is_array()) {
                for (const auto& a : entry["arguments"])
                    if (a.is_string()) words.push_back(a.get<std::string>());
            } else {
                words = shell_split(entry.value("command", ""));
            }
            const std::string dir = entry.value("directory", "");
            bool have_source = false, have_object = false;
            for (std::size_t k = 0; k < words.size(); ++k) {
                const std::string& w = words[k];
                if (k == 0) {
                    out.push_back(real_path(w));  // /usr/bin/c++ leads through /etc/alternatives
                } else if (w == "-o" && k + 1 < words.size()) {
                    out.push_back("-o"), out.push_back("@OBJECT@"), ++k, have_object = true;
                } else if (w == "-c" && k + 1 < words.size()) {
                    out.push_back("-c"), out.push_back("@SOURCE@"), ++k, have_source = true;
                } else if (w == file) {
                    out.push_back("@SOURCE@"), have_source = true;
                } else if (w == "-Werror" || starts_with(w, "-Werror=") || w == "-MD" || w == "-MMD") {
                    // Warnings never fail a student's build; dependency files are not wanted.
                } else if ((w == "-MT" || w == "-MF" || w == "-MQ") && k + 1 < words.size()) {
                    ++k;
                } else if (starts_with(w, "-I") || w == "-isystem" || w == "-iquote") {
                    const bool separate = w == "-isystem" || w == "-iquote";
                    include_folder(separate ? w : "-I",
                                   separate ? (k + 1 < words.size() ? words[++k] : "") : w.substr(2), root, dir, out);
                } else {
                    out.push_back(w);
                }
            }
            if (!have_source || !have_object) {
                out.clear();
                return "the compile command of " + file + " in " + compile_commands + " has no -c or -o";
            }
            // Tests come from the graders alone: doctest's macros define nothing in an exercise file
            // (including doctest.h is honest; no doctest is linked into the student's process).
            out.push_back("-DDOCTEST_CONFIG_DISABLE");
            out.push_back("-fdiagnostics-color=never");  // diagnostics only: the code is compiled as in the build
            out.push_back("-fmax-errors=20");
            return {};
        }
    }
    return "no compile command for " + candidates.front() + " in " + compile_commands;
}

std::string hash_instructor_files(const std::string& root) {
    std::string all;
    // The likely-mistakes catalogue too: a result names the mistakes of the catalogue it was made with.
    for (const char* folder :
         {"tests", "tests/grading", "tests/grading/engine", "tests/grading/engine/remote", "exercises/rigid",
          "exercises/provided/rigid", "solutions", "tests/include/reference", "tests/grading/mutants/catalogue"}) {
        const std::string dir = root + "/" + folder;
        for (const auto& name : list_dir(dir)) {
            const std::string path = dir + "/" + name;
            if (is_directory(path)) continue;
            bool ok = false;
            const std::string content = read_file(path, &ok);
            if (!ok) continue;
            all += std::string(folder) + "/" + name + "\n" + hex(hash(content)) + "\n";
        }
    }
    return all;
}

}  // namespace

const Chapter* find_chapter(const Setup& setup, const std::string& label) {
    for (const auto& c : setup.chapters)
        if (c.label == label) return &c;
    return nullptr;
}

std::string relative_to_root(const Setup& setup, std::string text) {
    if (!setup.root.empty()) text = replace_all(text, setup.root + "/", "");
    return text;
}

// ---- the manifest ----------------------------------------------------------------------------
namespace {

// A topic as topics.txt lists it: its chapter and its reference grader.
struct Listed {
    std::string topic, chapter, reference;
    std::string private_reference{};  // its private tests on the reference solution (private.cpp), if any
};

// Points per exercise: "<exercise> <points>" lines; 1 point for an exercise not listed. Returns
// an empty string or the error.
std::string read_points(const std::string& points_path, std::map<std::string, double>& points,
                        std::map<std::string, bool>& used) {
    int number = 0;
    for (const auto& raw : split(read_file(points_path), '\n')) {
        ++number;
        const std::string line = trim(raw.substr(0, raw.find('#')));
        if (line.empty()) continue;
        std::istringstream in(line);
        std::string name;
        double p = -1;
        if (!(in >> name >> p) || p < 0)
            return points_path + ":" + std::to_string(number) + ": expected '<exercise> <points>'";
        points[name] = p;
        used[name] = false;
    }
    return {};
}

// Chapter titles from the table of contents, as CMake read it (<build>/contents.json). Returns an
// empty string or the error.
std::string read_contents(const std::string& contents, const std::string& topics_path,
                          std::map<std::string, Chapter>& chapters) {
    bool ok = false;
    const std::string contents_text = read_file(contents, &ok);
    if (!ok) return "cannot read the table of contents " + contents + " (" + topics_path + " names it)";
    const nlohmann::json toc = nlohmann::json::parse(contents_text, nullptr, false);
    if (!toc.is_object() || !toc.contains("chapters") || !toc["chapters"].is_array())
        return contents + ": not the table of contents CMake writes ({\"chapters\": [...]})";
    for (const auto& c : toc["chapters"]) {
        const std::string label = c.value("label", "");
        chapters[label] = Chapter{label, c.value("number", 0), c.value("folder", ""), c.value("title", "")};
    }
    return {};
}

// The exercises and tests of a topic, from its reference grader's list of test cases (JSON
// lines). Returns an empty string or the error.
std::string list_exercises(const Listed& t, const std::string& root, const std::string& work,
                           std::vector<Exercise>& exercises) {
    Limits limits;
    limits.cpu_seconds = 60, limits.wall_seconds = 600;  // a hang catch: the listing takes well under 1 s
    limits.forbid_processes = false;
    const Outcome o =
        run_limited({t.reference, "--list-test-cases", "--reporters=workbook", "--no-version"}, ".", work, limits);
    const std::string listing = read_file(work);
    std::remove(work.c_str());
    if (!o.started || o.exit_code != 0)
        return "cannot list the tests of " + t.reference + (o.error.empty() ? "" : ": " + o.error);
    const std::string test_file = "tests/" + t.topic + "_test.cpp";
    for (const auto& line : split(listing, '\n')) {
        const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
        if (!j.is_object() || !j.contains("test")) continue;
        const std::string filename = j.value("file", "");
        // The path as the compiler saw it: absolute, or relative when a compiler cache rewrote it.
        if (filename != root + "/" + test_file && !ends_with(filename, "/" + test_file) && filename != test_file)
            continue;
        const std::string name = j.value("test", "");
        const auto colon = name.find(':');
        if (colon == std::string::npos || colon == 0 || name.find_first_of(",*?[]\\") != std::string::npos)
            return test_file + ": the test \"" + name +
                   "\" is not named \"<function>: <property>\" (with no comma, *, ?, [, ] or \\ in it: doctest filters "
                   "by name)";
        const std::string exercise = name.substr(0, colon);
        Exercise* e = nullptr;
        for (auto& x : exercises)
            if (x.name == exercise) e = &x;
        if (!e) {
            exercises.push_back({exercise, 1, {}});
            e = &exercises.back();
        }
        e->tests.push_back({name, j.value("line", 0), j.value("timeout", 0.0)});
    }
    if (exercises.empty()) return t.reference + " lists no tests from " + test_file;
    return {};
}

// The private tests of a topic (tests/grading/grading.cmake), from their reference binary: each
// joins its exercise after the public tests. Each must name an exercise of the topic, have a name
// no public test has, and pass on the reference solution. Returns an empty string or the error.
std::string list_private_tests(const Listed& t, const std::string& work, std::vector<Exercise>& exercises) {
    if (t.private_reference.empty()) return {};
    Limits limits;
    limits.cpu_seconds = 600, limits.wall_seconds = 3600;
    limits.forbid_processes = false;
    const Outcome ran = run_limited({t.private_reference, "--no-version", "--no-colors"}, ".", work, limits);
    const std::string said = read_file(work);
    if (!ran.started || ran.exit_code != 0)
        return "a private test of " + t.topic + " fails on the reference solution (" + t.private_reference +
               "), so it would fail every student:\n" + first_lines(said, 4000);
    limits.cpu_seconds = 60, limits.wall_seconds = 600;
    const Outcome o = run_limited({t.private_reference, "--list-test-cases", "--reporters=workbook", "--no-version"},
                                  ".", work, limits);
    const std::string listing = read_file(work);
    std::remove(work.c_str());
    if (!o.started || o.exit_code != 0) return "cannot list the private tests of " + t.private_reference;
    for (const auto& line : split(listing, '\n')) {
        const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
        if (!j.is_object() || !j.contains("test")) continue;
        const std::string name = j.value("test", ""), file = j.value("file", "");
        const auto colon = name.find(':');
        if (colon == std::string::npos || colon == 0 || name.find_first_of(",*?[]\\") != std::string::npos)
            return file + ": the private test \"" + name +
                   "\" is not named \"<function>: <property>\" (with no comma, *, ?, [, ] or \\ in it: doctest filters "
                   "by name)";
        Exercise* e = nullptr;
        for (auto& x : exercises) {
            if (x.name == name.substr(0, colon)) e = &x;
            for (const auto& other : x.tests)
                if (other.name == name) return file + ": the private test \"" + name + "\" has a public test's name";
        }
        if (!e)
            return file + ": the private test \"" + name + "\" names no exercise of " + t.topic +
                   " (a test counts for the function its name starts with)";
        e->tests.push_back({name, j.value("line", 0), j.value("timeout", 0.0), file});
    }
    return {};
}

// The chapter line of the manifest (a chapter not linked from the contents yet: its label).
std::string chapter_line(const std::string& label, const std::map<std::string, Chapter>& chapters) {
    Chapter c{label, 0, label, label};
    const auto digits = label.find_first_of("0123456789");
    if (digits != std::string::npos) c.number = std::atoi(label.c_str() + digits);
    if (const auto it = chapters.find(label); it != chapters.end()) c = it->second;
    return "chapter\t" + c.label + "\t" + std::to_string(c.number) + "\t" + c.slug + "\t" + c.title + "\n";
}

}  // namespace

std::string make_manifest(const std::string& topics_path, const std::string& points_path, const std::string& out_path) {
    bool ok = false;
    const std::string facts = read_file(topics_path, &ok);
    if (!ok) return "cannot read " + topics_path;
    std::string root, contents;
    std::vector<Listed> topics;
    for (const auto& line : split(facts, '\n')) {
        const auto f = split(line, '\t');
        if (f[0] == "root" && f.size() > 1)
            root = f[1];
        else if (f[0] == "contents" && f.size() > 1)
            contents = f[1];
        else if (f[0] == "topic" && f.size() > 2)
            topics.push_back({f[1], f[2], ""});
        else if (f[0] == "reference" && f.size() > 1 && !topics.empty())
            topics.back().reference = f[1];
        else if (f[0] == "private" && f.size() > 1 && !topics.empty())
            topics.back().private_reference = f[1];
    }
    std::map<std::string, double> points;
    std::map<std::string, bool> used;
    std::map<std::string, Chapter> chapters;
    if (auto problem = read_points(points_path, points, used); !problem.empty()) return problem;
    if (auto problem = read_contents(contents, topics_path, chapters); !problem.empty()) return problem;
    std::string out =
        "# The grading manifest: every exercise and test that `cmake/workbook grade` and `check` grade.\n"
        "# Generated at build time from the workbook_topic() declarations and the reference graders'\n"
        "# test lists; points per exercise from tests/grading/points.txt. Do not edit.\n";
    std::set<std::string> chapters_written;
    for (const auto& t : topics) {
        std::vector<Exercise> exercises;
        if (auto problem = list_exercises(t, root, out_path + ".list", exercises); !problem.empty()) return problem;
        if (auto problem = list_private_tests(t, out_path + ".list", exercises); !problem.empty()) return problem;
        if (chapters_written.insert(t.chapter).second) out += chapter_line(t.chapter, chapters);
        out += "topic\t" + t.topic + "\t" + t.chapter + "\ttests/" + t.topic + "_test.cpp\n";
        for (const auto& e : exercises) {
            double p = 1;
            if (points.count(e.name)) p = points[e.name], used[e.name] = true;
            out += "exercise\t" + t.topic + "\t" + e.name + "\t" + format_number(p) + "\n";
            for (const auto& test : e.tests)
                out += (test.private_file.empty() ? "test\t" : "private\t") + t.topic + "\t" + e.name + "\t" +
                       std::to_string(test.line) + "\t" + test.name +
                       (test.private_file.empty() ? (test.seconds > 0 ? "\t" + format_number(test.seconds) : "")
                                                  : "\t" + format_number(test.seconds) + "\t" + test.private_file) +
                       "\n";
        }
    }
    for (const auto& [name, was_used] : used)
        if (!was_used)
            std::fprintf(stderr, "warning: %s gives points to '%s', which is not an exercise of any grader\n",
                         points_path.c_str(), name.c_str());
    return write_file(out_path, out) ? "" : "cannot write " + out_path;
}

// ---- the setup of a grading run ---------------------------------------------------------------
namespace {

// topics.txt: the build's facts, and per topic its reference grader, objects and link line.
void read_build_facts(const std::string& facts, Setup& setup, std::string& compile_commands,
                      std::map<std::string, Topic>& built) {
    std::string current;
    for (const auto& line : split(facts, '\n')) {
        auto f = split(line, '\t');
        if (f[0] == "root" && f.size() > 1)
            setup.root = f[1];
        else if (f[0] == "build" && f.size() > 1)
            setup.build = f[1];
        else if (f[0] == "compiler" && f.size() > 1)
            setup.compiler = real_path(f[1]);
        else if (f[0] == "nm" && f.size() > 1)
            setup.nm = f[1];
        else if (f[0] == "compile_commands" && f.size() > 1)
            compile_commands = f[1];
        else if (f[0] == "link_flags" && f.size() > 1)
            setup.link_flags = shell_split(f[1]);
        else if (f[0] == "topic" && f.size() > 2)
            current = f[1], built[current].name = f[1];
        else if (f[0] == "reference" && f.size() > 1)
            built[current].reference = f[1];
        else if ((f[0] == "objects" || f[0] == "link") && !current.empty()) {
            auto& list = f[0] == "objects" ? built[current].objects : built[current].link;
            for (std::size_t k = 1; k < f.size(); ++k)
                for (const auto& item : split(f[k], ';'))
                    if (!item.empty()) list.push_back(item);
        }
    }
}

// remote.txt: the judge and the student's side per topic (tests/grading/grading.cmake). The
// link inputs outside /usr (the student's side, the reference libraries of the dependencies)
// become @LINK@/<name>, copied there when a run starts. Returns an empty string or the error.
std::string read_remote_facts(const std::string& dir, Setup& setup, std::map<std::string, Topic>& built) {
    bool ok = false;
    const std::string facts = read_file(dir + "/remote.txt", &ok);
    if (!ok) return "cannot read " + dir + "/remote.txt: build the target `grading` first";
    std::map<std::string, std::string> names;  // path -> name under @LINK@
    auto linked = [&](const std::string& item) -> std::string {
        if (item.empty() || item[0] != '/' || starts_with(item, "/usr/")) return item;
        if (!names.count(item)) {
            const std::string name = std::to_string(names.size()) + "-" + item.substr(item.rfind('/') + 1);
            names[item] = name;
            setup.link_inputs.push_back({name, item});
        }
        return "@LINK@/" + names[item];
    };
    std::string current;
    for (const auto& line : split(facts, '\n')) {
        const auto f = split(line, '\t');
        if (f[0] == "topic" && f.size() > 1)
            current = f[1];
        else if (current.empty() || !built.count(current))
            continue;
        else if (f[0] == "judge" && f.size() > 1)
            built[current].judge = f[1];
        else if (f[0] == "serve") {
            std::vector<std::string> link;
            for (std::size_t k = 1; k < f.size(); ++k)
                for (const auto& item : split(f[k], ';'))
                    if (!item.empty()) link.push_back(linked(item));
            for (const auto& item : built[current].link) link.push_back(linked(item));
            built[current].link = link;
        }
    }
    return {};
}

// The manifest: chapters, topics (with how to compile a student's file), exercises and tests.
// Returns an empty string or the error.
std::string read_manifest(const std::string& dir, const std::string& compile_commands,
                          std::map<std::string, Topic>& built, Setup& setup) {
    for (const auto& line : split(setup.manifest_text, '\n')) {
        const auto f = split(line, '\t');
        if (f[0] == "chapter" && f.size() > 4) {
            setup.chapters.push_back({f[1], std::stoi(f[2]), f[3], f[4]});
        } else if (f[0] == "topic" && f.size() > 3) {
            if (!built.count(f[1])) return "the manifest names topic " + f[1] + ", which topics.txt does not";
            Topic t = built[f[1]];
            t.chapter = f[2];
            t.test_file = f[3];
            std::vector<std::string> compile;
            const std::string problem = compile_template(
                compile_commands, setup.root,
                {setup.root + "/exercises/" + t.name + ".cpp", setup.root + "/solutions/" + t.name + ".cpp"}, compile);
            if (!problem.empty()) return problem;
            if (t.judge.empty() || t.link.empty())
                return dir + "/remote.txt has no judge for " + t.name + ": build the target `grading` first";
            t.compile = compile;
            setup.topics.push_back(t);
        } else if (f[0] == "exercise" && f.size() > 3 && !setup.topics.empty()) {
            setup.topics.back().exercises.push_back({f[2], std::stod(f[3]), {}});
        } else if (f[0] == "test" && f.size() > 4 && !setup.topics.empty() && !setup.topics.back().exercises.empty()) {
            setup.topics.back().exercises.back().tests.push_back(
                {f[4], std::stoi(f[3]), f.size() > 5 ? std::stod(f[5]) : 0.0});
        } else if (f[0] == "private" && f.size() > 6 && !setup.topics.empty() &&
                   !setup.topics.back().exercises.empty()) {  // private.cpp: graded in the judge like the rest
            setup.topics.back().exercises.back().tests.push_back({f[4], std::stoi(f[3]), std::stod(f[5]), f[6]});
        }
    }
    if (setup.topics.empty()) return dir + "/manifest.txt lists no topics";
    return {};
}

// The fingerprint of the instructor's side: what is graded, how, and with which sources.
std::string instructor_fingerprint(const std::string& dir, const Setup& setup) {
    std::string all = std::string(harness_version) + "\n" + setup.manifest_text;
    for (const auto& t : setup.topics) {
        for (const auto& w : t.compile) all += relative_to_root(setup, w) + " ";
        all += "\n";
        for (const auto& w : t.link) all += relative_to_root(setup, w) + " ";
        all += "\n";
    }
    for (const auto& w : setup.link_flags) all += w + " ";
    Limits quick;
    quick.forbid_processes = false;
    const std::string version_file = dir + "/compiler-version." + std::to_string(getpid()) + ".txt";
    run_limited({setup.compiler, "--version"}, dir, version_file, quick);
    all += "\n" + split(read_file(version_file), '\n')[0] + "\n";
    std::remove(version_file.c_str());
    all += hash_instructor_files(setup.root);
    return hex(hash(all));
}

}  // namespace

std::string load_setup(const std::string& dir, Setup& setup) {
    setup = Setup{};
    setup.dir = dir;
    bool ok = false;
    const std::string facts = read_file(dir + "/topics.txt", &ok);
    if (!ok) return "cannot read " + dir + "/topics.txt: build the target `grading` first";
    setup.manifest_text = read_file(dir + "/manifest.txt", &ok);
    if (!ok) return "cannot read " + dir + "/manifest.txt: build the target `grading` first";
    std::string compile_commands;
    std::map<std::string, Topic> built;
    read_build_facts(facts, setup, compile_commands, built);
    if (auto problem = read_remote_facts(dir, setup, built); !problem.empty()) return problem;
    if (auto problem = read_manifest(dir, compile_commands, built, setup); !problem.empty()) return problem;
    setup.fingerprint = instructor_fingerprint(dir, setup);
    return {};
}

}  // namespace grading
