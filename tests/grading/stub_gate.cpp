// The stub gate: proves that the graders can fail.
//
//   stub_gate <topic> <grader built on solutions/> <grader built on the pristine stubs> ...
//
// Runs both binaries of each topic with doctest's XML reporter and compares, test by test:
// every grading test must pass on the reference and fail on the stubs. A test that passes
// on a stub asserts nothing the student has to do; a test that fails on the reference is
// wrong. Either is named, and the gate fails. So does a topic with no tests, a test present
// in one binary only, or a test name that doctest's filters would misread.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>


namespace {

std::string decode(std::string s) {
    const std::pair<const char*, const char*> entities[] = {
        {"&quot;", "\""}, {"&apos;", "'"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}};
    for (const auto& [from, to] : entities)
        for (std::size_t p; (p = s.find(from)) != std::string::npos;) s.replace(p, std::string(from).size(), to);
    return s;
}

std::string attribute(const std::string& element, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const auto p = element.find(key);
    if (p == std::string::npos) return {};
    const auto q = element.find('"', p + key.size());
    return decode(element.substr(p + key.size(), q - p - key.size()));
}

// name -> passed, for every <TestCase> that ran to its end in doctest's XML report.
std::map<std::string, bool> run(const std::string& binary, const std::string& xml_path, std::string& problem) {
    std::remove(xml_path.c_str());
    const std::string command = "'" + binary + "' --reporters=xml --out='" + xml_path + "' --no-version >/dev/null 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(xml_path);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string xml = buffer.str();
    std::map<std::string, bool> results;
    if (xml.find("</doctest>") == std::string::npos) problem = "the XML report is incomplete (status " + std::to_string(status) + ")";
    std::size_t pos = 0;
    while ((pos = xml.find("<TestCase ", pos)) != std::string::npos) {
        const auto head_end = xml.find('>', pos);
        const auto end = xml.find("</TestCase>", pos);
        if (end == std::string::npos) break;
        const std::string name = attribute(xml.substr(pos, head_end - pos), "name");
        const auto overall = xml.find("<OverallResultsAsserts", pos);
        bool passed = false;
        if (overall != std::string::npos && overall < end) {
            const auto overall_end = xml.find("/>", overall);
            passed = attribute(xml.substr(overall, overall_end - overall), "test_case_success") == "true";
        }
        results[name] = passed;
        pos = end;
    }
    return results;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4 || (argc - 1) % 3 != 0) {
        std::cerr << "usage: stub_gate <topic> <solutions grader> <stubs grader> [...]\n";
        return 2;
    }
    int tests = 0;
    std::vector<std::string> problems;
    for (int i = 1; i < argc; i += 3) {
        const std::string topic = argv[i];
        std::string p1, p2;
        // Per-process file names: two gates running at once never share a report.
        const std::string tag = "stub_gate_" + topic + "_" + std::to_string(getpid());
        const auto ref = run(argv[i + 1], tag + "_solutions.xml", p1);
        const auto stub = run(argv[i + 2], tag + "_stubs.xml", p2);
        std::remove((tag + "_solutions.xml").c_str());
        std::remove((tag + "_stubs.xml").c_str());
        if (!p1.empty()) problems.push_back(topic + ": solutions grader: " + p1);
        if (!p2.empty()) problems.push_back(topic + ": stubs grader: " + p2);
        if (ref.empty()) problems.push_back(topic + ": no grading tests ran");
        int topic_tests = 0;
        for (const auto& [name, passed] : ref) {
            ++topic_tests;
            if (name.find_first_of(",*?[]\\") != std::string::npos)
                problems.push_back(topic + ": test name uses a doctest filter character: \"" + name + "\"");
            if (!passed) problems.push_back(topic + ": FAILS on solutions/: \"" + name + "\"");
            const auto s = stub.find(name);
            if (s == stub.end()) problems.push_back(topic + ": did not run on the stubs: \"" + name + "\"");
            else if (s->second) problems.push_back(topic + ": PASSES on the pristine stubs: \"" + name + "\"");
        }
        for (const auto& [name, passed] : stub)
            if (!ref.count(name)) problems.push_back(topic + ": ran on the stubs only: \"" + name + "\"");
        std::cout << "  " << topic << ": " << topic_tests << " grading tests\n";
        tests += topic_tests;
    }
    if (!problems.empty()) {
        std::cout << "stub gate FAILED:\n";
        for (const auto& p : problems) std::cout << "  " << p << "\n";
        return 1;
    }
    std::cout << "stub gate: all " << tests << " grading tests pass on solutions/ and fail on the pristine stubs\n";
    return 0;
}
