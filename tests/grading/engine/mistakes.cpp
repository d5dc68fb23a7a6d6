// Likely mistakes, named: see mistakes.hpp.
#include "mistakes.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "grading.hpp"

namespace grading::mistakes {

namespace {

constexpr std::size_t kNamed = 3;  // mistakes named for one signature; the rest are counted

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The line with every number replaced by '#', except the grader's line number after ".cpp:".
std::string blank_numbers(const std::string& line) {
    std::string out;
    for (std::size_t i = 0; i < line.size();) {
        if (!digit(line[i])) {
            out += line[i++];
            continue;
        }
        std::size_t end = i;
        while (end < line.size() && (digit(line[end]) || line[end] == '.' || line[end] == 'e' ||
                                     ((line[end] == '-' || line[end] == '+') && end > i && line[end - 1] == 'e')))
            ++end;
        const bool grader_line = out.size() >= 5 && out.compare(out.size() - 5, 5, ".cpp:") == 0;
        out += grader_line ? line.substr(i, end - i) : "#";
        i = end;
    }
    return out;
}

// How the failed check's actual values differ from the expected ones, value by value (".--x"), when
// the message lists both with as many numbers; "" otherwise.
std::string differs_at(const std::vector<std::string>& lines) {
    std::vector<double> expected, actual;
    std::vector<double>* into = nullptr;
    for (const auto& line : lines) {
        const std::string l = trim(line);
        if (l == "expected" || l == "actual") {
            into = l == "expected" ? &expected : &actual;
            continue;
        }
        double e = 0, a = 0;  // a number's check: "expected 1e-14, actual 0, |diff| 1e-14, tolerance 1e-15"
        if (std::sscanf(l.c_str(), "expected %lf, actual %lf,", &e, &a) == 2) {
            expected.push_back(e), actual.push_back(a);
            continue;
        }
        if (!into || l.empty() || starts_with(l, "max |diff|")) {
            into = nullptr;
            continue;
        }
        std::istringstream in(l);
        for (double x; in >> x;) into->push_back(x);
    }
    if (expected.empty() || expected.size() != actual.size()) return "";
    // Each value: '.' right, 'n' not finite, '-' negated, '0' zero where it should not be, 'x' otherwise
    // wrong.
    // (relative: the message prints 6 significant digits, and 1e-14 against 0 is a wrong answer)
    const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b)); };
    std::string mask;
    for (std::size_t k = 0; k < expected.size(); ++k)
        mask += near(actual[k], expected[k])    ? '.'
                : !std::isfinite(actual[k])     ? 'n'
                : near(actual[k], -expected[k]) ? '-'
                : actual[k] == 0                ? '0'
                                                : 'x';
    return mask;
}

}  // namespace

std::string how(const Outcome& o) {
    if (o.verdict == "pass") return "pass";
    if (o.verdict != "fail" || o.not_started) return "";
    const auto lines = split(o.message, '\n');
    std::string h = "fail: " + blank_numbers(trim(lines.empty() ? "" : lines[0]));
    if (const std::string mask = differs_at(lines); !mask.empty()) h += " | values " + mask;
    // "(40 checks failed in this test; the first is shown)": one check or more (how many of a test's
    // random inputs fail depends on the inputs, so on --seed)
    const bool more = std::any_of(lines.begin(), lines.end(), [](const std::string& line) {
        return starts_with(trim(line), "(") && line.find(" checks failed in this test") != std::string::npos;
    });
    return h + (more ? " | more than one check" : " | one check");
}

Signature signature_of(const std::vector<Outcome>& outcomes, const std::string& topic, const std::string& exercise) {
    Signature s;
    bool failing = false;
    for (const auto& o : outcomes) {
        if (o.topic != topic || o.exercise != exercise) continue;
        const std::string h = how(o);
        if (h.empty()) return {};
        failing = failing || h != "pass";
        s[o.test] = h;
    }
    return failing ? s : Signature{};
}

std::string Named::text() const {
    std::string list;
    for (std::size_t k = 0; k < mistakes.size() && k < kNamed; ++k) list += (k == 0 ? "" : "; or ") + mistakes[k];
    if (mistakes.size() > kNamed) list += "; or one of " + std::to_string(mistakes.size() - kNamed) + " more alike";
    return std::string("This pattern of failures is what ") +
           (mistakes.size() == 1 ? "this mistake gives" : "each of these mistakes gives") +
           " (likely, not certain: the mutation gate's plausible wrong answers fail exactly these tests at these "
           "checks): " +
           list + ".";
}

namespace {
// Whether an exercise that o's exercise calls (in the reference) has a test that does not pass.
bool uses_failing(const Catalogue& catalogue, const std::vector<Outcome>& outcomes, const Outcome& o) {
    const auto it = catalogue.uses.find(o.topic + "/" + o.exercise);
    if (it == catalogue.uses.end()) return false;
    return std::any_of(outcomes.begin(), outcomes.end(), [&](const Outcome& x) {
        return x.topic == o.topic && it->second.count(x.exercise) && x.verdict != "pass";
    });
}
}  // namespace

std::vector<Named> name(const Catalogue& catalogue, const std::vector<Outcome>& outcomes) {
    std::vector<Named> named;
    std::set<std::pair<std::string, std::string>> seen;
    for (const auto& o : outcomes) {
        if (!seen.insert({o.topic, o.exercise}).second) continue;
        const Signature s = signature_of(outcomes, o.topic, o.exercise);
        if (s.empty() || uses_failing(catalogue, outcomes, o)) continue;
        std::set<std::string> found, ids;
        for (const auto& e : catalogue.entries)
            if (e.topic == o.topic && e.exercise == o.exercise && e.signature == s)
                found.insert(e.mistake), ids.insert(e.mutant);
        if (!found.empty())
            named.push_back({o.topic, o.exercise, {found.begin(), found.end()}, {ids.begin(), ids.end()}});
    }
    return named;
}

std::vector<Outcome> outcomes_of(const SubmissionResult& r) {
    std::vector<Outcome> out;
    for (const auto& t : r.tests)
        out.push_back({t.topic, t.exercise, t.name, to_string(t.verdict), t.not_started, t.message});
    return out;
}

std::vector<Outcome> outcomes_of(const nlohmann::json& results) {
    std::vector<Outcome> out;
    if (!results.contains("tests") || !results["tests"].is_array()) return out;
    for (const auto& t : results["tests"]) {
        const auto& x = t.value("extra_data", nlohmann::json::object());
        Outcome o{x.value("topic", ""),   x.value("exercise", ""),       t.value("name", ""),
                  x.value("verdict", ""), x.value("not_started", false), t.value("output", "")};
        // The output is "<verdict>: <message>", then what the test printed.
        const std::string prefix = o.verdict + ": ";
        if (o.message.compare(0, prefix.size(), prefix) == 0) o.message = o.message.substr(prefix.size());
        out.push_back(std::move(o));
    }
    return out;
}

nlohmann::ordered_json to_json(const std::vector<Named>& named) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const auto& n : named) out.push_back({{"topic", n.topic}, {"exercise", n.exercise}, {"mistakes", n.mistakes}});
    return out;
}

nlohmann::ordered_json with_likely_mistakes(nlohmann::ordered_json results, const std::vector<Named>& named) {
    if (!named.empty()) results["extra_data"]["likely_mistakes"] = to_json(named);
    return results;
}

// ---- the catalogue's files ----

nlohmann::ordered_json to_json(const std::string& topic, const std::string& hash, const std::vector<Entry>& entries,
                               const std::map<std::string, std::set<std::string>>& uses) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& e : entries) {
        nlohmann::ordered_json sig = nlohmann::ordered_json::object();
        for (const auto& [test, h] : e.signature) sig[test] = h;
        list.push_back({{"exercise", e.exercise}, {"mutant", e.mutant}, {"mistake", e.mistake}, {"signature", sig}});
    }
    return {{"topic", topic},
            {"hash", hash},
            {"about",
             "Written by workbook_mutants catalogue from a run of the mutation gate (tests/grading/README.md, "
             "\"Likely mistakes, named\"); the hash is of the graders and the solution it came from."},
            {"uses", uses},
            {"entries", list}};
}

Catalogue load(const std::string& dir) {
    Catalogue c;
    if (!is_directory(dir)) return c;
    for (const auto& file : list_dir(dir)) {
        if (!ends_with(file, ".json")) continue;
        bool ok = false;
        const std::string text = read_file(dir + "/" + file, &ok);
        const auto j = nlohmann::json::parse(text, nullptr, false);
        if (!ok || j.is_discarded() || !j.contains("entries")) {
            c.error = "cannot read the catalogue of likely mistakes " + dir + "/" + file;
            continue;
        }
        const std::string topic = j.value("topic", "");
        c.hashes[topic] = j.value("hash", "");
        const auto uses = j.value("uses", nlohmann::json::object());  // (items() of a temporary dangles)
        for (const auto& [exercise, others] : uses.items())
            for (const auto& other : others) c.uses[topic + "/" + exercise].insert(other.get<std::string>());
        for (const auto& e : j["entries"]) {
            Entry entry{topic, e.value("exercise", ""), e.value("mutant", ""), e.value("mistake", ""), {}};
            for (const auto& [test, h] : e.at("signature").items()) entry.signature[test] = h.get<std::string>();
            c.entries.push_back(std::move(entry));
        }
    }
    return c;
}

const Catalogue& for_root(const std::string& root) {
    static std::map<std::string, Catalogue> loaded;
    auto it = loaded.find(root);
    if (it == loaded.end()) it = loaded.emplace(root, load(root + "/tests/grading/mutants/catalogue")).first;
    return it->second;
}

std::vector<ClassCount> count_in_class(const std::string& results_dir) {
    std::map<std::tuple<std::string, std::string, std::string>, int> count;
    for (const auto& file : list_dir(results_dir)) {
        if (!ends_with(file, ".json")) continue;
        const auto j = nlohmann::json::parse(read_file(results_dir + "/" + file), nullptr, false);
        if (j.is_discarded() || !j.contains("extra_data")) continue;
        for (const auto& n : j["extra_data"].value("likely_mistakes", nlohmann::json::array()))
            for (const auto& m : n.value("mistakes", nlohmann::json::array()))
                ++count[{n.value("topic", ""), n.value("exercise", ""), m.get<std::string>()}];
    }
    std::vector<ClassCount> out;
    for (const auto& [key, n] : count) out.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), n});
    std::stable_sort(out.begin(), out.end(),
                     [](const ClassCount& a, const ClassCount& b) { return a.students > b.students; });
    return out;
}

}  // namespace grading::mistakes
