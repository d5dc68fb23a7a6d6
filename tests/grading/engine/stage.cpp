// The folder a run builds students' files in (grading.hpp, Stage): made when the run starts,
// removed when it ends. The build sandbox sees nothing of the workbook but these copies of the
// API headers and of the link inputs, and the submission's own job folder. It lives in /tmp
// (TMPDIR when not root), where the sandbox's user can reach it: the workbook, the build and the
// out folder may be in folders only their owner can enter.
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "grading.hpp"

namespace grading {

namespace {

std::string copy_into(const std::string& from, const std::string& to) {
    bool ok = false;
    const std::string content = read_file(from, &ok);
    if (!ok) return "cannot read " + from;
    if (!write_file(to, content) || chmod(to.c_str(), 0644) != 0) return "cannot write " + to;
    return {};
}

std::string make_folder(const std::string& path, mode_t mode) {
    if (!make_dirs(path) || chmod(path.c_str(), mode) != 0)
        return "cannot create " + path + ": " + std::strerror(errno);
    return {};
}

}  // namespace

std::string make_stage(const Setup& setup, Stage& stage) {
    const char* tmp = geteuid() == 0 ? nullptr : std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/workbook-grade-XXXXXX";
    if (!mkdtemp(pattern.data())) return "cannot create a folder in /tmp: " + std::string(std::strerror(errno));
    stage.dir = pattern;
    std::string problem;
    if (chmod(stage.dir.c_str(), 0711) != 0) problem = "cannot set the mode of " + stage.dir;
    for (const char* api : {"exercises/rigid", "exercises/provided/rigid"}) {
        const std::string from = setup.root + "/" + api, to = stage.dir + "/api/" + api;
        if (problem.empty()) problem = make_folder(to, 0755);
        for (const auto& name : list_dir(from))
            if (problem.empty() && ends_with(name, ".hpp")) problem = copy_into(from + "/" + name, to + "/" + name);
    }
    for (const char* sub : {"api", "api/exercises", "api/exercises/provided"})
        if (problem.empty()) chmod((stage.dir + "/" + sub).c_str(), 0755);
    if (problem.empty()) problem = make_folder(stage.dir + "/link", 0755);
    for (const auto& input : setup.link_inputs)
        if (problem.empty()) problem = copy_into(input.path, stage.dir + "/link/" + input.name);
    if (problem.empty()) problem = make_folder(stage.dir + "/jobs", 0711);
    if (!problem.empty()) remove_stage(stage);
    return problem;
}

void remove_stage(const Stage& stage) {
    if (!stage.dir.empty()) remove_tree(stage.dir);
}

std::string make_job(const Stage& stage, std::string& job) {
    static std::atomic<unsigned> count{0};
    job = stage.dir + "/jobs/" + std::to_string(getpid()) + "-" + std::to_string(count++);
    remove_tree(job);
    for (const char* sub : {"", "/exercises", "/obj", "/bin"})
        if (auto problem = make_folder(job + sub, 0700); !problem.empty()) return problem;
    if (geteuid() == 0)
        for (const char* sub : {"", "/exercises", "/obj", "/bin"})
            if (chown((job + sub).c_str(), sandbox_uid(), sandbox_uid()) != 0)
                return "cannot give " + job + sub + " to the sandbox's user: " + std::strerror(errno);
    return {};
}

View view_of(const Stage& stage, const std::string& job) {
    if (isolation() == Isolation::namespaces) return {"/workbook", "/link", "/submission"};
    return {stage.dir + "/api", stage.dir + "/link", job};
}

}  // namespace grading
