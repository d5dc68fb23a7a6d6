// Where a result came from (provenance.hpp).
#include "provenance.hpp"

namespace grading {

namespace {

nlohmann::ordered_json limits(const Options& o) {
    return {{"test_cpu_seconds", o.test_limits.cpu_seconds},
            {"test_wall_seconds", o.test_limits.wall_seconds},
            {"test_memory_mb", o.test_limits.memory_mb},
            {"test_output_bytes", o.test_limits.output_bytes},
            {"test_threads", o.test_limits.threads},
            {"build_cpu_seconds", o.build_limits.cpu_seconds},
            {"build_wall_seconds", o.build_limits.wall_seconds},
            {"build_memory_mb", o.build_limits.memory_mb},
            {"max_file_bytes", o.max_file_bytes},
            {"test_environment", o.test_environment}};
}

// Hashes of the graders: their compiled judges, and their sources, each with the manifest.
std::pair<std::string, std::string> grader_hashes(const Setup& setup) {
    std::string judges = setup.manifest_text, sources = setup.manifest_text;
    for (const auto& t : setup.topics) {
        bool ok = false;
        const std::string judge = read_file(t.judge, &ok);
        judges += t.name + "\n" + (ok ? hex(hash(judge)) : "unreadable") + "\n";
        const std::string source = read_file(setup.root + "/" + t.test_file, &ok);
        sources += t.test_file + "\n" + (ok ? hex(hash(source)) : "unreadable") + "\n";
    }
    return {hex(hash(judges)), hex(hash(sources))};
}

}  // namespace

nlohmann::ordered_json provenance(const Setup& setup, const Options& options) {
    nlohmann::ordered_json p = nlohmann::ordered_json::object();
    for (const char* key : {"compiler", "compiler_path", "eigen", "gsl", "doctest", "commit", "modified"})
        p[key] = "unknown";
    bool ok = false;
    const std::string text = read_file(setup.dir + "/provenance.txt", &ok);
    for (const auto& line : split(text, '\n')) {
        const auto f = split(line, '\t');
        if (f.size() == 2 && !f[0].empty() && f[0][0] != '#') p[f[0]] = f[1];
    }
    if (!ok) p["packages_from"] = "unknown: " + setup.dir + "/provenance.txt is missing (build the target grading)";
    const auto [judges, sources] = grader_hashes(setup);
    p["graders"] = judges;
    p["grader_sources"] = sources;
    p["limits"] = limits(options);
    p["limits_hash"] = hex(hash(p["limits"].dump()));
    return p;
}

}  // namespace grading
