// workbook_hints: the hint ladders of exercises/hints.md, without building the graders.
//
//   workbook_hints show <hints.md> <exercise> <level>   one level as the terminal shows it
//                                                        (cmake/workbook check <exercise> --hint N)
//   workbook_hints lint <hints.md> [--manifest <manifest.txt>]
//                                                        every ladder follows the rules (hints.hpp),
//                                                        and every graded exercise has one
//   workbook_hints text <hints.md>                       every level as the terminal shows it
#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "hints.hpp"

namespace {

int usage() {
    std::fprintf(stderr,
                 "usage: workbook_hints show <hints.md> <exercise> <level>\n"
                 "       workbook_hints lint <hints.md> [--manifest <manifest.txt>]\n"
                 "       workbook_hints text <hints.md>\n");
    return 2;
}

int show(const hints::Hints& h, const std::string& exercise, const std::string& level_text) {
    const hints::Ladder* ladder = hints::find(h, exercise);
    if (!ladder) {
        std::string known;
        for (const auto& l : h.ladders) known += " " + l.exercise;
        std::fprintf(stderr, "workbook_hints: no hints for '%s'. Exercises with hints:%s\n", exercise.c_str(),
                     known.c_str());
        return 2;
    }
    int level = 0;
    try {
        std::size_t used = 0;
        level = std::stoi(level_text, &used);
        if (used != level_text.size()) level = 0;
    } catch (...) {
        level = 0;
    }
    if (level < 1 || level > static_cast<int>(ladder->levels.size())) {
        std::fprintf(stderr, "workbook_hints: --hint takes a level from 1 to %zu for %s, not '%s'\n",
                     ladder->levels.size(), exercise.c_str(), level_text.c_str());
        return 2;
    }
    std::printf("%s", hints::for_terminal(*ladder, level).c_str());
    return 0;
}

int lint(const hints::Hints& h, const std::string& file, const std::string& manifest) {
    int problems = 0;
    for (const auto& l : h.ladders)
        for (const auto& p : hints::lint(l, file)) std::printf("%s\n", p.c_str()), ++problems;
    if (!manifest.empty()) {
        std::ifstream in(manifest);
        if (!in) return std::fprintf(stderr, "workbook_hints: cannot read %s\n", manifest.c_str()), 2;
        std::string line;
        int graded = 0;
        while (std::getline(in, line)) {
            std::istringstream f(line);
            std::string kind, topic, name;
            if (!(f >> kind >> topic >> name) || kind != "exercise") continue;
            ++graded;
            if (!hints::find(h, name))
                std::printf("%s: no hints for the graded exercise %s (topic %s)\n", file.c_str(), name.c_str(),
                            topic.c_str()),
                    ++problems;
        }
        std::printf("%d graded exercises in %s\n", graded, manifest.c_str());
    }
    std::printf("%zu ladders in %s, %d problem(s)\n", h.ladders.size(), file.c_str(), problems);
    return problems ? 1 : 0;
}

// The command line (CLI11): one subcommand each, its arguments positional; anything else gets
// the usage and status 2.
struct Command {
    std::string file, exercise, level, manifest;
};

CLI::App* subcommand(CLI::App& app, const std::string& name, Command& c) {
    CLI::App* sub = app.add_subcommand(name);
    sub->add_option("hints", c.file)->required();
    return sub;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"workbook_hints"};
    app.set_help_flag();
    app.require_subcommand(1);
    Command c;
    CLI::App* show_command = subcommand(app, "show", c);
    show_command->add_option("exercise", c.exercise)->required();
    show_command->add_option("level", c.level)->required();
    CLI::App* lint_command = subcommand(app, "lint", c);
    lint_command->add_option("--manifest", c.manifest);
    CLI::App* text = subcommand(app, "text", c);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError&) {
        return usage();
    }
    const hints::Hints h = hints::read(c.file);
    if (!h.error.empty()) return std::fprintf(stderr, "workbook_hints: %s\n", h.error.c_str()), 2;
    if (show_command->parsed()) return show(h, c.exercise, c.level);
    if (lint_command->parsed()) return lint(h, c.file, c.manifest);
    if (text->parsed())
        for (const auto& l : h.ladders)
            for (std::size_t k = 1; k <= l.levels.size(); ++k)
                std::printf("%s", hints::for_terminal(l, static_cast<int>(k)).c_str());
    return 0;
}
