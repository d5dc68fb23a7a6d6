// The catalogue of likely mistakes, made from a run of the mutation gate: see catalogue.hpp.
#include "catalogue.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "grading.hpp"
#include "mistakes.hpp"

namespace mutants {

// The mistake in the student's terms, from the gate's operator: what went wrong, never the
// reference's code or its right token (feedback names the slip; the fix stays the student's, as
// with the hints).
std::string describe(const Listed& m) {
    const std::string in = "in " + m.function + ": ";
    if (m.op == "transpose") return in + "a `.transpose()` left out";
    if (m.op == "sincos") return in + "a sine and a cosine swapped";
    if (m.op == "sign" && m.after.size() < m.before.size()) return in + "a minus sign left out";
    if (m.op == "sign") return in + "an arithmetic sign flipped (a `+` for a `-`, or the other way)";
    if (m.op == "compare") return in + "a comparison turned around, or off by its boundary (`<` for `<=`, ...)";
    if (m.op == "index") return in + "two indices of a matrix, or two components of a vector, swapped";
    if (m.op == "constant") return in + "a constant off (one too many, or twice what it should be)";
    if (m.op == "return")
        return in +
               (m.after.find("return !(") != std::string::npos ? "the answer negated" : "the result's sign flipped");
    if (m.op == "condition") return in + "a condition turned around";
    return in + "a one-token slip";
}

std::string topic_hash(const std::string& root, const std::string& manifest, const std::string& topic,
                       const std::vector<Listed>& mutants) {
    std::string all;
    for (const std::string& file : {"solutions/" + topic + ".cpp", "tests/" + topic + "_test.cpp",
                                    std::string("tests/checks.hpp"), "exercises/rigid/" + topic + ".hpp"})
        all += file + "\n" + grading::hex(grading::hash(grading::read_file(root + "/" + file))) + "\n";
    for (const auto& line : grading::split(manifest, '\n')) {
        const auto f = grading::split(line, '\t');
        if (f.size() > 1 && f[1] == topic) all += line + "\n";
    }
    for (const auto& m : mutants)
        if (m.topic == topic) all += m.id + "\t" + m.function + "\t" + m.op + "\t" + m.after + "\n";
    return grading::hex(grading::hash(all));
}

int write_catalogue(const std::string& root, const std::string& manifest, const std::string& gate_out,
                    const std::string& catalogue, const std::vector<Listed>& mutants,
                    const std::map<std::string, std::map<std::string, std::set<std::string>>>& uses) {
    bool ok = false;
    const auto statuses = nlohmann::json::parse(grading::read_file(gate_out + "/mutants.json", &ok), nullptr, false);
    if (!ok || statuses.is_discarded())
        return std::fprintf(stderr, "cannot read %s/mutants.json\n", gate_out.c_str()), 2;
    std::map<std::string, std::string> status;
    for (const auto& s : statuses) status[s.value("id", "")] = s.value("status", "");
    std::map<std::string, std::vector<grading::mistakes::Entry>> by_topic;
    for (const auto& m : mutants) by_topic[m.topic];
    for (const auto& m : mutants) {
        if (!status.count(m.id)) return std::fprintf(stderr, "the gate's run has no mutant %s\n", m.id.c_str()), 2;
        if (status[m.id] != "killed" || !m.exercise) continue;  // a helper's mutant fails tests of many exercises
        const auto result = nlohmann::json::parse(
            grading::read_file(gate_out + "/checks/" + m.id + "/results.json", &ok), nullptr, false);
        if (!ok || result.is_discarded()) return std::fprintf(stderr, "no results for mutant %s\n", m.id.c_str()), 2;
        const auto signature =
            grading::mistakes::signature_of(grading::mistakes::outcomes_of(result), m.topic, m.function);
        if (signature.empty()) continue;  // it crashed or timed out: such a failure is never named
        by_topic[m.topic].push_back({m.topic, m.function, m.id, describe(m), signature});
    }
    grading::make_dirs(catalogue);
    for (const auto& [topic, entries] : by_topic) {
        const std::string path = catalogue + "/" + topic + ".json";
        if (!grading::write_file(
                path, grading::json_text(grading::mistakes::to_json(
                          topic, topic_hash(root, manifest, topic, mutants), entries,
                          uses.count(topic) ? uses.at(topic) : std::map<std::string, std::set<std::string>>{}))))
            return std::fprintf(stderr, "cannot write %s\n", path.c_str()), 2;
        std::fprintf(stderr, "workbook_mutants: %s: %zu likely mistakes catalogued\n", path.c_str(), entries.size());
    }
    return 0;
}

int check_fresh(const std::string& root, const std::string& manifest, const std::string& catalogue,
                const std::vector<Listed>& mutants) {
    const auto c = grading::mistakes::load(catalogue);
    if (!c.error.empty()) return std::fprintf(stderr, "%s\n", c.error.c_str()), 2;
    int stale = 0;
    for (const auto& [name, hash] : c.hashes) {
        const std::string& topic = name;  // (a lambda may not capture a structured binding in clang 14)
        if (std::none_of(mutants.begin(), mutants.end(), [&](const Listed& m) { return m.topic == topic; })) {
            std::printf("%s: not graded by this build, not checked\n", topic.c_str());
            continue;
        }
        const std::string now = topic_hash(root, manifest, topic, mutants);
        if (now == hash) continue;
        ++stale;
        std::fprintf(stderr,
                     "%s/%s.json is stale: its graders, solution or mutants changed since it was made (hash %s, now "
                     "%s). Make it again: cmake/workbook mutants %s, then workbook_mutants catalogue (README.md, "
                     "\"Likely mistakes, named\")\n",
                     catalogue.c_str(), topic.c_str(), hash.c_str(), now.c_str(), topic.c_str());
    }
    if (!stale) std::printf("%zu catalogue(s) of likely mistakes match this tree\n", c.hashes.size());
    return stale ? 1 : 0;
}

}  // namespace mutants

namespace mutants {

namespace {

// A planted entry: the signature of the first failing exercise of the results that is matchable.
bool plant_on(grading::mistakes::Catalogue& c, const std::vector<std::pair<std::string, nlohmann::json>>& results) {
    for (const auto& [student, j] : results) {
        const auto outcomes = grading::mistakes::outcomes_of(j);
        for (const auto& o : outcomes) {
            const auto s = grading::mistakes::signature_of(outcomes, o.topic, o.exercise);
            if (s.empty()) continue;
            c.entries.push_back({o.topic, o.exercise, "planted", "a planted mistake (" + student + "'s failures)", s});
            std::printf("planted an entry with the signature of %s's %s\n", student.c_str(), o.exercise.c_str());
            return true;
        }
    }
    return false;
}

std::string join(const std::vector<std::string>& words) {
    std::string out;
    for (const auto& w : words) out += (out.empty() ? "" : " ") + w;
    return out;
}

std::vector<std::pair<std::string, nlohmann::json>> read_results(const std::string& results,
                                                                 const std::vector<std::string>& skip) {
    std::vector<std::pair<std::string, nlohmann::json>> out;
    for (const auto& file : grading::list_dir(results)) {
        if (!grading::ends_with(file, ".json")) continue;
        const std::string student = file.substr(0, file.size() - 5);
        if (std::find(skip.begin(), skip.end(), student) != skip.end()) continue;
        out.emplace_back(student, nlohmann::json::parse(grading::read_file(results + "/" + file), nullptr, false));
    }
    return out;
}

}  // namespace

int measure(const std::string& catalogue, const std::string& results) {
    const auto c = grading::mistakes::load(catalogue);
    std::map<std::string, const grading::mistakes::Entry*> by_id;
    for (const auto& e : c.entries) by_id[e.mutant] = &e;
    int mutants = 0, failing = 0, named = 0, right = 0, names = 0, elsewhere = 0, others = 0, others_named = 0;
    for (const auto& [student, j] : read_results(results, {})) {
        const auto found = grading::mistakes::name(c, grading::mistakes::outcomes_of(j));
        const auto it = by_id.find(student);
        if (it == by_id.end()) {  // not a catalogued mutant: an honest or unrelated submission
            ++others, others_named += !found.empty();
            std::printf("%-28s %s\n", student.c_str(), found.empty() ? "no likely mistake" : "GIVEN A LIKELY MISTAKE");
            continue;
        }
        ++mutants;
        const auto outcomes = grading::mistakes::outcomes_of(j);
        failing += std::any_of(outcomes.begin(), outcomes.end(), [](const auto& o) { return o.verdict != "pass"; });
        named += !found.empty();
        for (const auto& n : found) {
            elsewhere += n.exercise != it->second->exercise;  // a mistake named where the mutant is not
            if (n.exercise != it->second->exercise) continue;
            const bool own = std::find(n.mutants.begin(), n.mutants.end(), student) != n.mutants.end();
            right += own, names += own ? static_cast<int>(n.mutants.size()) : 0;
        }
    }
    std::printf(
        "measure: %d catalogued mutants graded, %d fail a test, %d given a likely mistake, %d named correctly (their "
        "own mistake among those named; %.2f named on average when so), %d names given to an exercise the mutant "
        "did not change; %d other submissions, %d given one\n",
        mutants, failing, named, right, right ? static_cast<double>(names) / right : 0.0, elsewhere, others,
        others_named);
    return others_named ? 1 : 0;
}

int audit(const std::string& catalogue, const std::string& results, const std::vector<std::string>& may_name,
          bool plant) {
    auto c = grading::mistakes::load(catalogue);
    if (!c.error.empty() || c.entries.empty())
        return std::fprintf(stderr, "audit: no catalogue in %s %s\n", catalogue.c_str(), c.error.c_str()), 2;
    const auto audited = read_results(results, may_name);
    if (plant && !plant_on(c, audited)) return std::fprintf(stderr, "audit: nothing to plant on\n"), 3;
    int named = 0;
    for (const auto& [student, j] : audited) {
        const auto again = grading::mistakes::name(c, grading::mistakes::outcomes_of(j));
        const bool in_file = j.contains("extra_data") && j["extra_data"].contains("likely_mistakes");
        for (const auto& n : again)
            std::printf("%s: %s is given a likely mistake (%s): %s\n", student.c_str(), n.exercise.c_str(),
                        join(n.mutants).c_str(), n.text().c_str());
        if (in_file) std::printf("%s: its results name a likely mistake\n", student.c_str());
        named += !again.empty() || in_file;
    }
    std::printf("audit: %zu results, %d given a likely mistake\n", audited.size(), named);
    return named ? 1 : 0;
}

}  // namespace mutants
