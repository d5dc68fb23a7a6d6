// The stub gate: proves that the graders can fail.
//
//   stub_gate [--stubs <what they are>] <topic> <grader built on solutions/> <grader built on the stubs> ...
//
// Runs both binaries of each topic with the workbook's JSON reporter and compares, test by test:
// every grading test must pass on the reference and fail on the stubs. A test that passes
// on a stub asserts nothing the student has to do; a test that fails on the reference is
// wrong. The second graders are the pristine stubs' (todo(...) throws rigid::not_implemented), or
// (--stubs) the stubs that refuse every input (mutants/refuse.hpp): a test that passes on those
// gives points for refusing. Either is named, and the gate fails. So does a topic with no tests, a test present
// in one binary only, or a test name that doctest's filters would misread.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/process.hpp"

namespace {

// name -> passed, for every test case that ran to its end, from the workbook reporter's JSON
// lines (tests/grading/engine/reporter.cpp).
std::map<std::string, bool> run(const std::string& binary, const std::string& report_path, std::string& problem) {
    std::remove(report_path.c_str());
    // Its own output is not read: the report is.
    const int status = support::run({binary, "--reporters=workbook", "--out=" + report_path, "--no-version"}).status;
    std::ifstream in(report_path);
    std::map<std::string, bool> results;
    bool finished = false;
    for (std::string line; std::getline(in, line);) {
        const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
        if (!j.is_object()) continue;
        const std::string event = j.value("event", "");
        if (event == "end") results[j.value("name", "")] = j.value("success", false);
        if (event == "run") finished = true;
    }
    if (!finished) problem = "the report is incomplete (status " + std::to_string(status) + ")";
    return results;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args;             // topic, solutions grader, stubs grader, ...
    std::string stubs = "the pristine stubs";  // what the second grader of each topic grades
    CLI::App app{"stub_gate"};
    app.set_help_flag();
    app.add_option("--stubs", stubs);
    app.add_option("graders", args)->required();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError&) {
        args.clear();
    }
    if (args.empty() || args.size() % 3 != 0) {
        std::cerr << "usage: stub_gate [--stubs <what they are>] <topic> <solutions grader> <stubs grader> [...]\n";
        return 2;
    }
    int tests = 0;
    std::vector<std::string> problems;
    for (std::size_t i = 0; i < args.size(); i += 3) {
        const std::string topic = args[i];
        std::string p1, p2;
        // Per-process file names: two gates running at once never share a report.
        const std::string tag = "stub_gate_" + topic + "_" + std::to_string(getpid());
        const auto ref = run(args[i + 1], tag + "_solutions.jsonl", p1);
        const auto stub = run(args[i + 2], tag + "_stubs.jsonl", p2);
        std::remove((tag + "_solutions.jsonl").c_str());
        std::remove((tag + "_stubs.jsonl").c_str());
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
            if (s == stub.end())
                problems.push_back(topic + ": did not run on the stubs: \"" + name + "\"");
            else if (s->second)
                problems.push_back(topic + ": PASSES on " + stubs + ": \"" + name + "\"");
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
    std::cout << "stub gate: all " << tests << " grading tests pass on solutions/ and fail on " << stubs << "\n";
    return 0;
}
