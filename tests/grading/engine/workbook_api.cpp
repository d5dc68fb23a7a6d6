// workbook_api: a build step of the grading run (tests/grading/grading.cmake), apart from
// workbook_grade so that the judges and the student's side of a topic compile while the rest of
// the engine is still being built (a first `check` waits less: issue 41).
//
//   workbook_api --topic <t> --nm <nm> --library <lib.a> --out <dir> --objects <o>...
//
// Writes <dir>/judge_<t>.cpp and <dir>/serve_<t>.cpp (api.cpp, make_api).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "grading.hpp"

int main(int argc, char** argv) {
    std::string topic, nm, library, out;
    std::vector<std::string> objects;
    CLI::App app{"workbook_api: the two sides of one topic's API in a graded test (api.cpp)"};
    for (const auto& [name, value] :
         {std::pair{"--topic", &topic}, {"--nm", &nm}, {"--library", &library}, {"--out", &out}})
        app.add_option(name, *value)->required();
    app.add_option("--objects", objects)->required();
    CLI11_PARSE(app, argc, argv);
    const std::string problem = grading::make_api(topic, nm, library, objects, out);
    if (problem.empty()) return 0;
    std::fprintf(stderr, "workbook_api: %s\n", problem.c_str());
    return 1;
}
