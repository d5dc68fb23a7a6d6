// Headless figures: see figure.hpp.
#include "figure.hpp"

#include <gnuplot-iostream.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#ifndef WORKBOOK_STYLE_GP
#define WORKBOOK_STYLE_GP ""
#endif

namespace kit {

namespace fs = std::filesystem;

namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// gnuplot's complaints that mean "no good figure": errors carry "line N:" without the word
// warning; a missing program shows up as the shell's "not found".
bool gnuplot_failed(const std::string& log) {
    std::istringstream in(log);
    std::string line;
    static const std::regex error_line(R"(line [0-9]+:)");
    while (std::getline(in, line)) {
        const bool warning = line.find("arning") != std::string::npos;
        if (!warning && std::regex_search(line, error_line)) return true;
        if (line.find("not found") != std::string::npos) return true;
    }
    return false;
}

}  // namespace

std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += (c == '\'') ? std::string("''") : std::string(1, c);
    return out + "'";
}

Figure::Figure(Scene& scene, const std::string& file_name, int width, int height) : scene_(scene) {
    if (!scene.options().figures()) return;
    const fs::path dir = scene.options().out_dir();
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw BadInput("--out: cannot create the folder '" + dir.string() + "'");
    final_path_ = (dir / file_name).string();
    staged_path_ = (dir / ("." + file_name + ".partial")).string();
    log_path_ = (dir / ("." + file_name + ".gnuplot.log")).string();
    for (const auto& p : {staged_path_, log_path_})
        if (p.find('\'') != std::string::npos) throw BadInput("--out: the folder name must not contain a quote (')");

    std::string terminal;
    const std::string ext = fs::path(file_name).extension().string();
    const std::string size = std::to_string(width) + "," + std::to_string(height);
    if (ext == ".svg")
        terminal = "set terminal svg size " + size + " dynamic enhanced font 'DejaVu Sans,12' background rgb 'white'";
    else if (ext == ".png")
        terminal = "set terminal pngcairo size " + size + " enhanced font 'DejaVu Sans,11' background rgb 'white'";
    else
        throw std::logic_error("kit::Figure: '" + file_name + "' must end in .svg or .png");

    // A gnuplot that died must make our writes fail, not kill the scene with SIGPIPE.
    std::signal(SIGPIPE, SIG_IGN);
    fs::remove(staged_path_, ec);
    gp_ = std::make_unique<gnuplotio::Gnuplot>("gnuplot -d 2>'" + log_path_ + "'");
    // Greek and mathematical signs are written as UTF-8 (Ω, α, ‖·‖), never with gnuplot's
    // escape to the PostScript Symbol font, which a browser shows as Latin letters (W for Ω).
    *gp_ << terminal << "\n"
         << "set encoding utf8\n"
         << "set output " << quoted(staged_path_) << "\n";
    const std::string style = WORKBOOK_STYLE_GP;
    if (!style.empty() && fs::exists(style)) *gp_ << "load " << quoted(style) << "\n";
}

Figure::~Figure() {
    if (gp_ && !finished_) {
        // Abandoned (an exception is on its way): close gnuplot quietly, leave nothing behind.
        try {
            gp_.reset();
        } catch (...) {
        }
        std::error_code ec;
        fs::remove(staged_path_, ec);
        fs::remove(log_path_, ec);
    }
}

Figure& Figure::operator<<(const std::string& commands) {
    if (gp_) *gp_ << commands;
    return *this;
}

// gnuplot-iostream's send1d writes one line per row (every number with 19 significant digits,
// so gnuplot reads back the very doubles), a blank line for an empty row, and the closing 'e'.
// A number shown as text (`with labels`) must therefore be formatted by gnuplot itself, e.g.
// `using 1:2:(sprintf('%d', $3))`.
Figure& Figure::data(const std::vector<std::vector<double>>& rows) {
    if (gp_) gp_->send1d(rows);
    return *this;
}

void Figure::finish() {
    if (!gp_ || finished_) return;
    finished_ = true;
    *gp_ << "unset output\n";
    gp_->flush();
    const bool stream_ok = gp_->good();
    gp_.reset();  // closes the pipe and waits for gnuplot to exit
    const std::string log = read_file(log_path_);
    std::error_code ec;
    fs::remove(log_path_, ec);
    const auto size = fs::exists(staged_path_) ? fs::file_size(staged_path_) : 0;
    std::string problem;
    if (!stream_ok)
        problem = "gnuplot stopped reading its commands";
    else if (gnuplot_failed(log))
        problem = "gnuplot reported an error";
    else if (size == 0)
        problem = "gnuplot wrote no file";
    else if (fs::path(final_path_).extension() == ".svg" && read_file(staged_path_).find("</svg>") == std::string::npos)
        problem = "the SVG file is truncated";
    if (!problem.empty()) {
        fs::remove(staged_path_, ec);
        throw NumericalFailure("figure " + final_path_ + ": " + problem + (log.empty() ? "" : ":\n" + log));
    }
    scene_.stage_figure(staged_path_, final_path_);
}

}  // namespace kit
