// The entry point of a live scene's module: runs the scene's own main() (compiled with
// -Dmain=workbook_scene_main) on an argument list from the page, and returns one JSON text:
//   {"status": exit status, "report": the scene's --json report (or null), "stderr": its
//    messages, "plots": the figures its drawing code made, "motion": its --motion data (or null)}.
// The page never computes: every number and every point it shows comes from here.
#include <emscripten/emscripten.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "live.hpp"

int workbook_scene_main(int argc, char** argv);

namespace live {

std::vector<Plot>& plots() {
    static std::vector<Plot> all;
    return all;
}

namespace {

using Json = nlohmann::json;

// Runs main() with stdout and stderr caught in strings.
int run_main(std::vector<std::string> args, std::string& out, std::string& err) {
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::ostringstream o, e;
    std::streambuf* const old_out = std::cout.rdbuf(o.rdbuf());
    std::streambuf* const old_err = std::cerr.rdbuf(e.rdbuf());
    const int status = workbook_scene_main(static_cast<int>(args.size()), argv.data());
    std::cout.rdbuf(old_out);
    std::cerr.rdbuf(old_err);
    out = o.str();
    err = e.str();
    return status;
}

Json plots_json() {
    Json all = Json::array();
    for (const Plot& p : plots())
        all.push_back({{"file", p.file},
                       {"width", p.width},
                       {"height", p.height},
                       {"commands", p.commands},
                       {"blocks", p.blocks}});
    return all;
}

}  // namespace
}  // namespace live

// args: the scene's command line, one argument a line (the scene's name first). The module's
// --out folder is /live in emscripten's memory file system; --motion FILE lands there.
extern "C" EMSCRIPTEN_KEEPALIVE const char* live_run(const char* args) {
    static std::string result;
    std::vector<std::string> argv;
    std::istringstream lines(args);
    for (std::string a; std::getline(lines, a);) argv.push_back(a);
    std::filesystem::remove_all("/live");
    std::filesystem::create_directories("/live");
    argv.insert(argv.begin() + 1, {"--out", "/live", "--json", "--no-figure"});
    live::plots().clear();
    std::string out, err;
    const int status = live::run_main(argv, out, err);
    using Json = nlohmann::json;
    Json r = {
        {"status", status}, {"stderr", err}, {"plots", live::plots_json()}, {"report", nullptr}, {"motion", nullptr}};
    if (status == 0) r["report"] = Json::parse(out, nullptr, false);
    for (const auto& f : std::filesystem::directory_iterator("/live"))
        if (f.path().extension() == ".json") r["motion"] = Json::parse(std::ifstream(f.path()), nullptr, false);
    result = r.dump(-1, ' ', false, Json::error_handler_t::replace);
    return result.c_str();
}
