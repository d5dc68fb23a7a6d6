// A live scene on a page: the prose's `<!-- live: SCENE -->` becomes the block that
// cmake/book/web/live.js fills (controls, numbers, plot), with the scene's page spec in it and its
// module copied into the book's live/ folder. The spec and the module come from the build's
// live/ folder (cmake/book/live/live.cmake: <build>/live/SCENE.live.json and SCENE.js); without them
// the block says that this book has no live version and why: no emscripten, or the reason in
// SCENE.missing.txt (a scene that needs GSL, left out when the build has no GSL for WebAssembly).
#include <filesystem>
#include <string>

#include "book.hpp"
#include "prose.hpp"
#include "support/file.hpp"

namespace book {

std::string live_missing_reason(const fs::path& live_dir, const std::string& scene) {
    bool ok = false;
    std::string why = support::read_file((live_dir / (scene + ".missing.txt")).string(), &ok);
    while (!why.empty() && why.back() == '\n') why.pop_back();
    return ok && !why.empty() ? why : "no emscripten";
}

namespace {

// Why the scene has no module, for its page: the live build's own words, or no emscripten.
std::string missing_html(const fs::path& live_dir, const std::string& scene) {
    const std::string why = live_missing_reason(live_dir, scene);
    if (why != "no emscripten")
        return html_escape(why) +
               " (<code>cmake/workbook run</code> builds Debian's GSL with emscripten where it can "
               "fetch Debian's source package)";
    return "it was built without emscripten (Debian: <code>sudo apt-get install emscripten</code>; "
           "<code>cmake/workbook run</code> installs it)";
}

}  // namespace

LiveBlock live_block(const fs::path& live_dir, const fs::path& out, const std::string& scene, const std::string& root) {
    const fs::path spec = live_dir / (scene + ".live.json"), module = live_dir / (scene + ".js");
    if (!fs::exists(spec) || !fs::exists(module))
        return {"<div class=\"live live-missing\" id=\"live-" + html_escape(scene) +
                    "\">\n<p class=\"live-status\">This book has no live version of the scene <code>" +
                    html_escape(scene) + "</code>: " + missing_html(live_dir, scene) +
                    ". The figure and the numbers of the text are the scene's own run.</p>\n</div>\n",
                false};
    const auto data = prose::read_json(spec);
    if (!data.contains("scene") || data["scene"] != scene)
        throw std::runtime_error(spec.string() + " is not the live spec of " + scene);
    fs::create_directories(out / "live");
    fs::copy_file(module, out / "live" / (scene + ".js"), fs::copy_options::overwrite_existing);
    std::string json = data.dump();  // a script's text ends at "</": write it "<\/"
    for (std::size_t p = 0; (p = json.find("</", p)) != std::string::npos; p += 3) json.replace(p, 2, "<\\/");
    return {"<div class=\"live\" id=\"live-" + html_escape(scene) + "\" data-module=\"" + html_escape(root) + "live/" +
                html_escape(scene) + ".js\">\n<script type=\"application/json\" class=\"live-spec\">" + json +
                "</script>\n<p class=\"live-status\">The live scene needs JavaScript; the figure and the numbers of "
                "the text are the scene's own run.</p>\n</div>\n",
            true};
}

}  // namespace book
