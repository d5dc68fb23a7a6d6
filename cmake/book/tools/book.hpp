// What the book tool's jobs share (cmake/book/tools/book.cpp is its command line): the pages' titles,
// the table of contents, HTML escaping; and the three jobs, each in its own translation unit:
// render.cpp (--render), structure.cpp (--check-structure), figures.cpp (--check-figures).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace book {

namespace fs = std::filesystem;

std::string html_escape(const std::string& s);

// The first "# Heading" of a markdown file, without markdown (its stem when it has none).
std::string first_heading(const fs::path& file);

// The chapters' folders, in the order of the table of contents as CMake read it from
// chapters/README.md (cmake/contents.cmake writes <build>/contents.json).
std::vector<std::string> chapter_list(const fs::path& contents);

// --check-structure: every chapter a lesson, the notation page, the errata rows. 0 when all is well.
int check_structure(const fs::path& root, const fs::path& contents);

// --check-figures: no Symbol-font escape in the sources, fonts that have the SVGs' characters.
int check_figures(const fs::path& root, const std::vector<fs::path>& trees);

struct RenderOptions {
    fs::path root, runs, figures, out, contents;
    std::string pandoc = "pandoc", label;
    bool strict = false;
};

// A live scene's block on a page (live.cpp): its HTML, and whether its module is in the book.
struct LiveBlock {
    std::string html;
    bool live;
};
LiveBlock live_block(const fs::path& live_dir, const fs::path& out, const std::string& scene, const std::string& root);
// Why a live scene has no module, in a few words: "no emscripten" or its SCENE.missing.txt.
std::string live_missing_reason(const fs::path& live_dir, const std::string& scene);

// --render: the book as HTML pages in options.out.
int render(const RenderOptions& options);

}  // namespace book
