// The scene kit's figures, for a live scene in the book (compiled with emscripten instead of
// chapters/kit/figure.cpp): there is no gnuplot in a page, so a Figure records what the scene's
// own drawing code sends it (its filled gnuplot scripts and commands, cmake/support/script.cpp,
// and its inline data blocks) and the page draws the same data (cmake/book/web/live.js). A Figure
// always records, also under --no-figure: the live module runs the scene with --no-figure so that
// --motion writes no GIF.
#include <map>
#include <string>
#include <vector>

#include "figure.hpp"
#include "live.hpp"

namespace kit {

namespace {

// The plot each figure of the run is recording (figure.hpp's members stay those of the native
// figure, which runs gnuplot).
std::map<const Figure*, live::Plot>& recording() {
    static std::map<const Figure*, live::Plot> plots;
    return plots;
}

}  // namespace

Figure::Figure(Scene& scene, const std::string& file_name, int width, int height)
    : scene_(scene), final_path_(file_name) {
    enabled_ = true;
    live::Plot& plot = recording()[this] = live::Plot{};  // an unfinished figure's leftovers go
    plot.file = file_name;
    plot.width = width;
    plot.height = height;
}

Figure::Figure(Scene& scene, const std::string& path, Terminal) : Figure(scene, path) {}

Figure& Figure::script(const Script& script, const Fill& values) {
    recording()[this].commands += filled(script, values);
    return *this;
}

Figure& Figure::operator<<(const std::string& commands) {
    recording()[this].commands += commands;
    return *this;
}

Figure& Figure::data(const std::vector<std::vector<double>>& rows) {
    recording()[this].blocks.push_back(rows);
    return *this;
}

// The figure is complete: the page may draw it.
std::uintmax_t Figure::finish() {
    if (finished_) return 0;
    finished_ = true;
    auto it = recording().find(this);
    live::plots().push_back(std::move(it->second));
    recording().erase(it);
    return 0;
}

}  // namespace kit
