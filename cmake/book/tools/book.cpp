// The book tool's command line (CLI11). Its three jobs, each in its own translation unit under
// book/:
//
//   book --render <root> --runs <runs.txt> [--figures <dir>] --out <dir> [--pandoc <exe>]
//        [--label <text>] [--strict] --contents <contents.json>          book/render.cpp
//   book --check-structure <root> --contents <contents.json>             book/structure.cpp
//   book --check-figures <root> <folder>...                              book/figures.cpp
//
// --contents: the table of contents, chapters/README.md, as CMake read it (cmake/contents.cmake
// writes <build>/contents.json): its chapters are the book's, in that order.
//
// Exit status: 0 all is well, 1 a problem found (each printed), 2 a bad command line.
#include "book.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Command {
    std::string render, structure;
    std::vector<std::string> figures;  // <root> <folder>...
    book::RenderOptions options;
    std::string runs, built, out, contents;
};

void declare(CLI::App& app, Command& c) {
    auto* render = app.add_option("--render", c.render, "render the book of the workbook at <root>");
    auto* structure = app.add_option("--check-structure", c.structure, "check that every chapter is a lesson");
    auto* figures = app.add_option("--check-figures", c.figures, "<root> <folder>...: check the figures' fonts")
                        ->expected(1, CLI::detail::expected_max_vector_size);
    render->excludes(structure, figures);
    structure->excludes(figures);
    app.add_option("--runs", c.runs, "the runs CMake declares (<build>/runs.txt)");
    app.add_option("--figures", c.built, "a run's figures and reports (default: <root>/figures)");
    app.add_option("--out", c.out, "the folder to render into");
    app.add_option("--pandoc", c.options.pandoc, "the pandoc program");
    app.add_option("--label", c.options.label, "what the values of this render are");
    app.add_flag("--strict", c.options.strict, "a value without a report is an error");
    app.add_option("--contents", c.contents, "the table of contents (<build>/contents.json)");
}

int usage(const std::string& why) {
    if (!why.empty()) std::cerr << "book: " << why << "\n";
    std::cerr << "usage: book --render <root> --runs <runs.txt> [--figures <dir>] --out <dir> [--pandoc <exe>] "
                 "[--label <text>]\n"
                 "            [--strict] --contents <contents.json>\n"
                 "       book --check-structure <root> --contents <contents.json>\n"
                 "       book --check-figures <root> <folder of SVG figures>...\n";
    return 2;
}

std::optional<fs::path> absolute_or_empty(const std::string& p) {
    return p.empty() ? std::nullopt : std::optional<fs::path>(fs::absolute(p));
}

int run(Command& c) {
    const fs::path contents = absolute_or_empty(c.contents).value_or(fs::path());
    if (!c.structure.empty()) return book::check_structure(fs::absolute(c.structure), contents);
    if (!c.figures.empty()) {
        std::vector<fs::path> trees;
        for (std::size_t i = 1; i < c.figures.size(); ++i) trees.push_back(fs::absolute(c.figures[i]));
        return book::check_figures(fs::absolute(c.figures[0]), trees);
    }
    if (c.render.empty()) return usage("");
    for (const auto& [name, value] : {std::pair{"--runs", &c.runs}, std::pair{"--out", &c.out}})
        if (value->empty()) return usage(std::string(name) + " is required");
    book::RenderOptions& o = c.options;
    o.root = fs::absolute(c.render);
    o.runs = fs::absolute(c.runs);
    o.figures = absolute_or_empty(c.built).value_or(o.root / "figures");
    o.out = fs::absolute(c.out);
    o.contents = contents;
    return book::render(o);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"The Grioli workbook's book: render it, check its structure, check its figures", "book"};
    Command c;
    declare(app, c);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return usage(e.what());
    }
    try {
        return run(c);
    } catch (const std::exception& e) {
        std::cerr << "book: " << e.what() << "\n";
        return 1;
    }
}
