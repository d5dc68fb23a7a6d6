// Headless figures through gnuplot-iostream (its pipe, and its send1d for the data), done one
// way everywhere.
//
//   kit::Figure fig(scene, "omega_error.svg");
//   fig << "set logscale xy\n" << "plot '-' using 1:2 with lines title 'central'\n";
//   fig.data(rows);          // one inline data block, ended by 'e'
//   fig.finish();            // waits for gnuplot, checks the file, stages it
//
// What it guarantees, because gnuplot itself does not (see research/grading-anchors.md, 4):
//   * gnuplot runs as `gnuplot -d` (no user init files) with an explicit terminal (svg or
//     pngcairo, from the file name) and an explicit output file;
//   * text is UTF-8 in DejaVu Sans, a font with the Greek and mathematical signs the figures
//     use (write 'Ω_{fd}', '‖R^T R − 1‖', never gnuplot's escape to the PostScript Symbol
//     font, which browsers show as Latin letters; Debian: fonts-dejavu-core);
//   * the figure is drawn to a temporary name and published by kit::run only when the
//     whole scene succeeded, so bad input or a failure never leaves a partial figure;
//   * finish() throws when gnuplot is missing, reports an error, stops reading, or writes
//     an empty or truncated file, and shows gnuplot's own message;
//   * with --no-figure, a Figure does nothing and gnuplot is never started.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene.hpp"

namespace gnuplotio {
class Gnuplot;
}

namespace kit {

class Figure {
public:
    Figure(Scene& scene, const std::string& file_name, int width = 800, int height = 500);
    ~Figure();
    Figure(const Figure&) = delete;
    Figure& operator=(const Figure&) = delete;

    bool enabled() const { return static_cast<bool>(gp_); }
    Figure& operator<<(const std::string& commands);
    // One inline data block for a `plot '-'` or `splot '-'`, sent with gnuplot-iostream's
    // send1d: one line per row; an empty row makes a blank line (a break between line segments
    // or a new splot curve). Numbers go out in full precision, so a label taken from the data
    // must be formatted in gnuplot: `using 1:2:(sprintf('%d', $3)) with labels`.
    Figure& data(const std::vector<std::vector<double>>& rows);
    void finish();

private:
    Scene& scene_;
    std::string final_path_, staged_path_, log_path_;
    std::unique_ptr<gnuplotio::Gnuplot> gp_;
    bool finished_ = false;
};

// gnuplot's way of writing a string literal: single quotes, inner quotes doubled.
std::string quoted(const std::string& text);

}  // namespace kit
