// The scene kit's figures, for a live scene in the book (compiled with emscripten instead of
// chapters/kit/figure.cpp): there is no gnuplot in a page, so a Figure records what the scene's
// own drawing code sends it (its gnuplot commands and its inline data blocks) and the page draws
// the same data (cmake/book/live.js). A Figure always records, also under --no-figure: the live
// module runs the scene with --no-figure so that --motion writes no GIF.
#include <map>
#include <string>
#include <vector>

#include "figure.hpp"
#include "live.hpp"

namespace gnuplotio {
// The recorder in place of gnuplot-iostream's pipe to gnuplot.
class Gnuplot {
public:
    live::Plot plot;
};
}  // namespace gnuplotio

namespace kit {

Figure::Figure(Scene& scene, const std::string& file_name, int width, int height)
    : scene_(scene), final_path_(file_name), gp_(std::make_unique<gnuplotio::Gnuplot>()) {
    gp_->plot.file = file_name;
    gp_->plot.width = width;
    gp_->plot.height = height;
}

Figure::~Figure() = default;

Figure& Figure::operator<<(const std::string& commands) {
    gp_->plot.commands += commands;
    return *this;
}

Figure& Figure::data(const std::vector<std::vector<double>>& rows) {
    gp_->plot.blocks.push_back(rows);
    return *this;
}

// The figure is complete: the page may draw it.
void Figure::finish() {
    finished_ = true;
    live::plots().push_back(gp_->plot);
}

std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += (c == '\'') ? std::string("''") : std::string(1, c);
    return out + "'";
}

}  // namespace kit
