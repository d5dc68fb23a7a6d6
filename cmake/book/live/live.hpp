// What a live scene's module hands the page besides the scene's report: the figures its drawing
// code made (figure_live.cpp records them), to be drawn in the page by cmake/book/web/live.js.
#pragma once

#include <string>
#include <vector>

namespace live {

struct Plot {
    std::string file;  // the figure's file name in the native scene ("precession_cones.svg")
    int width = 800, height = 500;
    std::string commands;                                  // the gnuplot commands the scene wrote, in order
    std::vector<std::vector<std::vector<double>>> blocks;  // its inline data blocks, in order
};

// The figures finished during the current run.
std::vector<Plot>& plots();

}  // namespace live
