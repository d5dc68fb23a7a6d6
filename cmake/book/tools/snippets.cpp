// Keeps the prose of the book honest about the code and the numbers it quotes. The command line
// (CLI11); the checks are in book/snippet_values.cpp, book/numbers.cpp and book/names.cpp.
//
//   snippets --check        <root>        fail on a missing, stale or unused code snippet, or a
//                                         malformed value marker (see prose.hpp for both)
//   snippets --check-names  <root>        fail on prose that names code which does not exist:
//                                         `identifiers_with_underscores` and `ns::names` (not
//                                         std::, Eigen::, boost::, doctest::, gsl_), `test:`
//                                         prefixes, `paths/to/files.cpp`, and the scenes, options
//                                         and graders of the ```sh examples
//   snippets --check-numbers <root>       fail on a number of the prose that looks measured and is
//                                         neither a value marker nor tagged with what it is, on a
//                                         malformed or stale tag (see prose.hpp), and on a section
//                                         of the workbook named by number (section 5.6) that is
//                                         not a link to it
//   snippets --check-values <root> <runs.txt> [<smoke>]
//                                         fail on a value marker whose run is not declared, whose
//                                         committed report (<root>/figures/...) is missing, made
//                                         with other options, lacks the key or marks it as not
//                                         measured, or whose text differs from that report; with
//                                         <smoke> (the test suite's reports, <scene>.json), also
//                                         on a key the scenes as built no longer report
//   snippets --update       <root> [<runs.txt>]
//                                         rewrite the quoted code from the sources and, with
//                                         <runs.txt>, the quoted values from the committed reports
//   snippets --diff         <root> <runs.txt> <tree>
//                                         compare every value marker with its run's report in
//                                         <tree> (a build's figures): per chapter, how many agree
//                                         with the committed text, and each one that does not
//
// The committed prose carries the values of the committed reports, which the target
// update-figures copies, with the figures, from a `cmake/workbook run`; the rendered book shows
// the values of its own run. Run times change from run to run and round-off from machine to
// machine, so a fresh run may differ from the text: --diff lists where.
//
// Exit status: 0 all is well, 1 a problem found (each printed), 2 a bad command line.
#include "snippets.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

int usage(const std::string& why) {
    if (!why.empty()) std::cerr << "snippets: " << why << "\n";
    std::cerr << "usage: snippets --check <root> | --check-names <root> | --check-numbers <root>\n"
                 "                | --check-values <root> <runs.txt> [<smoke>]\n"
                 "                | --update <root> [<runs.txt>] | --diff <root> <runs.txt> <tree>\n";
    return 2;
}

// The mode given and its arguments: <root> first.
int run(const std::string& mode, const std::vector<std::string>& a) {
    using snippets::Mode;
    const fs::path root = fs::absolute(a.at(0));
    if (mode == "--check") return snippets::snippets_and_values(root, Mode::check, nullptr, nullptr, nullptr);
    if (mode == "--check-names") return snippets::check_names(root);
    if (mode == "--check-numbers") return snippets::check_numbers(root);
    if (mode == "--update" && a.size() == 1)
        return snippets::snippets_and_values(root, Mode::update, nullptr, nullptr, nullptr);
    const prose::Runs runs(a.at(1));
    if (mode == "--update") return snippets::snippets_and_values(root, Mode::update, &runs, nullptr, nullptr);
    const fs::path other = a.size() == 3 ? fs::absolute(a[2]) : fs::path();
    if (mode == "--check-values")
        return snippets::snippets_and_values(root, Mode::check_values, &runs, a.size() == 3 ? &other : nullptr,
                                             nullptr);
    return snippets::snippets_and_values(root, Mode::diff, &runs, nullptr, &other);  // --diff
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Keeps the prose of the book honest about the code and the numbers it quotes", "snippets"};
    // Each mode takes <root> and its own arguments: how many, at least and at most.
    const std::map<std::string, std::pair<int, int>> modes{{"--check", {1, 1}},         {"--check-names", {1, 1}},
                                                           {"--check-numbers", {1, 1}}, {"--check-values", {2, 3}},
                                                           {"--update", {1, 2}},        {"--diff", {3, 3}}};
    std::map<std::string, std::vector<std::string>> given;
    for (const auto& [name, count] : modes)
        app.add_option(name, given[name], "<root> ...")->expected(count.first, count.second);
    app.require_option(1);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return usage(e.what());
    }
    try {
        for (const auto& [name, args] : given)
            if (!args.empty()) return run(name, args);
    } catch (const std::exception& e) {
        std::cerr << "snippets: " << e.what() << "\n";
        return 1;
    }
    return usage("");
}
