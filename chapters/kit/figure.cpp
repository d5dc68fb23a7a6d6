// Headless figures: see figure.hpp.
#include "figure.hpp"

#include <fmt/format.h>
#include <gnuplot-iostream.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iomanip>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "kit.gp.hpp"  // kit::gp::style, from figures/style.gp
#include "support/file.hpp"
#include "support/process.hpp"

namespace kit {

namespace fs = std::filesystem;

namespace {

// gnuplot's complaints that mean "no good figure": errors carry "line N:" without the word
// warning.
bool gnuplot_failed(const std::string& log) {
    std::istringstream in(log);
    std::string line;
    static const std::regex error_line(R"(line [0-9]+:)");
    while (std::getline(in, line)) {
        const bool warning = line.find("arning") != std::string::npos;
        if (!warning && std::regex_search(line, error_line)) return true;
    }
    return false;
}

std::string terminal_for(const std::string& file_name, int width, int height) {
    const std::string ext = fs::path(file_name).extension().string();
    const std::string size = std::to_string(width) + "," + std::to_string(height);
    if (ext == ".svg")
        return "set terminal svg size " + size + " dynamic enhanced font 'DejaVu Sans,12' background rgb 'white'";
    if (ext == ".png")
        return "set terminal pngcairo size " + size + " enhanced font 'DejaVu Sans,11' background rgb 'white'";
    throw std::logic_error("kit::Figure: '" + file_name + "' must end in .svg or .png");
}

}  // namespace

Figure::Figure(Scene& scene, const std::string& file_name, int width, int height)
    : Figure(scene, file_name, Terminal{terminal_for(file_name, width, height)}) {}

Figure::Figure(Scene& scene, const std::string& path, Terminal terminal) : scene_(scene) {
    if (!scene.options().figures()) return;
    const fs::path final_path =
        fs::path(path).is_absolute() ? fs::path(path) : fs::path(scene.options().out_dir()) / path;
    const fs::path dir = final_path.parent_path(), name = final_path.filename();
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw BadInput("--out: cannot create the folder '" + dir.string() + "'");
    final_path_ = final_path.string();
    staged_path_ = (dir / ("." + name.string() + ".partial")).string();
    script_path_ = (dir / ("." + name.string() + ".gp")).string();
    if (staged_path_.find('\'') != std::string::npos)
        throw BadInput("--out: the folder name must not contain a quote (')");
    enabled_ = true;
    // Greek and mathematical signs are written as UTF-8 (Ω, α, ‖·‖), never with gnuplot's
    // escape to the PostScript Symbol font, which a browser shows as Latin letters (W for Ω).
    text_ = terminal.line + "\nset encoding utf8\nset output " + kit::quoted(staged_path_) + "\n";
    if (terminal.style) text_ += gp::style.text;
}

Figure& Figure::script(const Script& script, const Fill& values) {
    if (enabled_) text_ += filled(script, values);
    return *this;
}

Figure& Figure::operator<<(const std::string& commands) {
    if (enabled_) text_ += commands;
    return *this;
}

// An inline data block as gnuplot-iostream's send1d writes one (its text sender, into the script
// rather than down its pipe, which it would open through a shell): scientific with 18 digits after
// the point, so that gnuplot reads back the very doubles; an empty row is a blank line.
Figure& Figure::data(const std::vector<std::vector<double>>& rows) {
    if (!enabled_) return *this;
    std::ostringstream block;
    block << std::scientific << std::setprecision(18);
    gnuplotio::top_level_array_sender(block, rows, gnuplotio::Mode1D(), gnuplotio::ModeText());
    text_ += block.str() + "e\n";
    return *this;
}

std::uintmax_t Figure::finish() {
    if (!enabled_ || finished_) return 0;
    finished_ = true;
    text_ += gp::figure_end.text;
    std::error_code ec;
    fs::remove(staged_path_, ec);
    if (!support::write_file(script_path_, text_))
        throw NumericalFailure("figure " + final_path_ + ": cannot write its script " + script_path_);
    // gnuplot from its argument vector, no shell between (cmake/support/include/support/process.hpp).
    const support::Result r = support::run({"gnuplot", "-d", script_path_});
    fs::remove(script_path_, ec);
    const auto size = fs::exists(staged_path_) ? fs::file_size(staged_path_) : 0;
    std::string problem;
    if (r.status == -1)
        problem = "gnuplot did not start (" + r.error + ")";
    else if (r.status != 0 || gnuplot_failed(r.err))
        problem = "gnuplot reported an error (exit status " + std::to_string(r.status) + ")";
    else if (size == 0)
        problem = "gnuplot wrote no file";
    else if (fs::path(final_path_).extension() == ".svg" &&
             support::read_file(staged_path_).find("</svg>") == std::string::npos)
        problem = "the SVG file is truncated";
    if (!problem.empty()) {
        fs::remove(staged_path_, ec);
        throw NumericalFailure("figure " + final_path_ + ": " + problem + (r.err.empty() ? "" : ":\n" + r.err));
    }
    scene_.stage_figure(staged_path_, final_path_);
    return size;
}

}  // namespace kit
