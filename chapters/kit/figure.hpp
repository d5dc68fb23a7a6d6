// Headless figures, done one way everywhere: a scene's gnuplot text lives in .gp files beside
// it, embedded into the scene at build time; the kit fills their placeholders, adds the data,
// and runs gnuplot once the script is whole.
//
//   // omega_finite_difference.error_vs_step.gp, beside the scene: fixed gnuplot text, with
//   // @name@ where the run decides (a title's number, a range, a plot clause).
//   #include "omega_finite_difference.gp.hpp"  // kit::gp::error_vs_step, one per .gp (generated)
//   kit::Figure fig(scene, "omega_error.svg");
//   fig.script(kit::gp::error_vs_step, {{"title", title}});
//   fig.data(rows);          // one inline data block, ended by 'e' (gnuplot-iostream's send1d text)
//   fig.finish();            // ends any multiplot (kit figure_end.gp), runs gnuplot, checks the file, stages it
//
// A plot of as many curves as the run has: the curve's clause is a .gp of its own (one line,
// after its comments), filled once per curve and joined into a placeholder of the plot's script:
//
//   // omega_finite_difference.stencil.gp: '-' using 1:2 with linespoints ls @ls@ title '@title@'
//   std::vector<kit::Fill> curves;
//   for (...) curves.push_back({{"ls", ...}, {"title", ...}});
//   fig.script(kit::gp::error_vs_step, {{"stencils", kit::joined(kit::gp::stencil, curves)}});
//
// (the same text a gnuplot loop would give, but spelt out: the live book reads each plot's '-'.)
//
// The scripts: every <scene>.<figure>.gp (or <scene>.gp) in a scene's folder becomes
// kit::gp::<figure> (or kit::gp::<scene>) in the generated header <scene>.gp.hpp
// (workbook_scene, cmake/Workbook.cmake), so a scene needs no path at run time. A placeholder
// is @name@ (letters, digits, _), a syntax gnuplot's own text never has; a placeholder left
// unfilled, or a value for one the script does not have, throws std::logic_error. The filling is
// the support library's (cmake/support/include/support/script.hpp), which the grading run's class report
// uses too: kit::Script, kit::Fill, kit::filled and kit::joined are its names here.
//
// What it guarantees, because gnuplot itself does not (see research/grading-anchors.md, 4):
//   * gnuplot runs as `gnuplot -d SCRIPT` (no user init files; started from its argument
//     vector, no shell) with an explicit terminal (svg or pngcairo, from the file name) and an
//     explicit output file;
//   * text is UTF-8 in DejaVu Sans, a font with the Greek and mathematical signs the figures
//     use (write 'Ω_{fd}', '‖R^T R − 1‖', never gnuplot's escape to the PostScript Symbol
//     font, which browsers show as Latin letters; Debian: fonts-dejavu-core);
//   * the figure is drawn to a temporary name and published by kit::run only when the
//     whole scene succeeded, so bad input or a failure never leaves a partial figure;
//   * finish() throws when gnuplot is missing, reports an error, or writes an empty or
//     truncated file, and shows gnuplot's own message;
//   * with --no-figure, a Figure does nothing and gnuplot is never started.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene.hpp"
#include "support/script.hpp"

namespace kit {

// A gnuplot script embedded from its .gp file, the values of its placeholders, and its text
// filled in (support/script.hpp).
using Script = support::Script;
using Fill = support::Fill;
using support::filled;
using support::joined;

// How a figure is drawn: gnuplot's `set terminal` line, and whether the workbook's one style
// (figures/style.gp) is loaded after it.
struct Terminal {
    std::string line;
    bool style = true;
};

class Figure {
public:
    // An SVG or PNG of width x height pixels, in the --out folder.
    Figure(Scene& scene, const std::string& file_name, int width = 800, int height = 500);
    // Any terminal; `path` relative: in the --out folder.
    Figure(Scene& scene, const std::string& path, Terminal terminal);
    ~Figure() = default;
    Figure(const Figure&) = delete;
    Figure& operator=(const Figure&) = delete;

    bool enabled() const { return enabled_; }
    // The script, filled (see filled()).
    Figure& script(const Script& script, const Fill& values = {});
    // Text the kit builds itself (the motion GIF's frames); a scene's gnuplot is in its .gp files.
    Figure& operator<<(const std::string& commands);
    // One inline data block for a `plot '-'` or `splot '-'`: one line per row, every number
    // with 19 significant digits (gnuplot reads back the very doubles); an empty row makes a
    // blank line (a break between line segments or a new splot curve); then 'e'. A label taken
    // from the data must be formatted in gnuplot: `using 1:2:(sprintf('%d', $3)) with labels`.
    Figure& data(const std::vector<std::vector<double>>& rows);
    // Runs gnuplot on the whole script and stages the figure; returns its size in bytes (0 when
    // the figure is off).
    std::uintmax_t finish();

private:
    Scene& scene_;
    std::string final_path_, staged_path_, script_path_;
    std::string text_;
    bool enabled_ = false, finished_ = false;
};

// gnuplot's way of writing a string literal: single quotes, inner quotes doubled.
inline std::string quoted(const std::string& text) { return support::gnuplot_quoted(text); }

}  // namespace kit
