// book --render <root> --runs <runs.txt> [--figures <dir>] --out <dir> [--pandoc <exe>]
//      [--label <text>] [--strict] --contents <contents.json>
// Renders the book: the chapters' README.md files, the contents, the errata and the hints, as
// HTML pages that work offline (pandoc, math as MathML, no script). Pages: index.html (the
// contents), NN_slug.html per chapter, errata.html, hints.html, workbook.html (the top README),
// any other .md the pages link to, and code/<path>.html for each source file they link to.
// A value marker shows the value of its run (run=..., declared in <runs.txt>) from the report
// that run wrote into --figures (the folder of a `cmake/workbook run`, see prose.hpp), else
// from the committed report in <root>/figures (the same run's options, refreshed by the target
// update-figures; shown so, in its own style); never from a run with other options. Without
// either, the committed text stays, marked as not measured (--strict: an error). A value the
// run marks as not measured (null, -1, "not measured") is an error naming the key. Figures
// come from --figures, else from <root>/figures, and are copied next to the pages. Every link is
// mapped to its page, and must exist, fragment and all. Writes <out>/pages.txt for the browser
// test: file, kind, title per line.
#include <algorithm>
#include <cmath>
#include <ctime>
#include <iostream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "book.hpp"
#include "markdown.hpp"
#include "prose.hpp"
#include "run.hpp"

namespace book {

namespace {

using prose::rel;

// A figure of the prose: a paragraph that is one image, alone on its line.
struct Image {
    std::string alt, src;
};

// A paragraph that is one image: a figure when its line is the image alone, as GitHub shows it;
// its alt text as written (the caption), its target as pandoc read it.
std::optional<Image> figure_of(const md::Json& para, const std::vector<std::string>& lines) {
    if (!md::is(para, "Para") || para["c"].size() != 1 || !md::is(para["c"][0], "Image")) return std::nullopt;
    const int at = md::line(para);
    if (at < 1 || static_cast<std::size_t>(at) > lines.size()) return std::nullopt;
    std::string l = lines[static_cast<std::size_t>(at) - 1];
    l.erase(l.find_last_not_of(" \t\r") + 1);
    const std::string src = para["c"][0]["c"][2][0].get<std::string>(), tail = "](" + src + ")";
    if (l.rfind("![", 0) != 0 || l.size() < tail.size() + 2 ||
        l.compare(l.size() - tail.size(), tail.size(), tail) != 0)
        return std::nullopt;
    return Image{l.substr(2, l.size() - tail.size() - 2), src};
}

// A node of raw HTML for pandoc's tree ("RawBlock" or "RawInline").
md::Json raw_html_node(const char* kind, std::string html) {
    html.erase(html.find_last_not_of('\n') + 1);  // pandoc ends a block itself
    return md::Json{{"t", kind}, {"c", md::Json::array({"html", html})}};
}

// Takes out the positions md::read_page gave every node ("line"): they are not pandoc's.
void strip_lines(md::Json& node) {
    if (node.is_object()) node.erase("line");
    if (node.is_array() || node.is_object())
        for (auto& item : node) strip_lines(item);
}

// Whether an array of pandoc's tree is a list of nodes (blocks or inlines), not a tuple such as
// a header's [level, attributes, inlines].
bool is_node_list(const md::Json& a) {
    return a.is_array() && !a.empty() &&
           std::all_of(a.begin(), a.end(), [](const md::Json& n) { return n.is_object() && n.contains("t"); });
}

struct Page {
    std::string file;   // in the book: "01_pure_rotations.html", "code/exercises/rotation.cpp.html"
    fs::path source;    // the markdown or source file it comes from (absolute)
    std::string kind;   // contents | chapter | page | code
    std::string title;  // for <title> and the navigation
    int chapter = 0;    // 1.. for chapters
};

// One page's render in progress: where its quotations' markers are, the figures and motions so
// far, and how many value markers of each source line are done.
struct PageWork {
    const Page& page;
    const md::Page& tree;
    std::string file;                     // the source, relative to the workbook, for messages
    std::map<int, std::string> snippets;  // the line of a quotation's marker -> the snippet's name
    std::set<int> ends;                   // the lines of the quotations' end markers
    int figure = 0, motion = 0;
    std::map<int, std::size_t> values_done;
    std::string where(int line) const { return file + ":" + std::to_string(line); }
    std::string line_text(int line) const {
        return line >= 1 && static_cast<std::size_t>(line) <= tree.lines.size()
                   ? tree.lines[static_cast<std::size_t>(line) - 1]
                   : "";
    }
};

class Book {
public:
    Book(fs::path root, const fs::path& runs, fs::path figures, fs::path out, std::string pandoc, std::string label,
         bool strict, fs::path contents)
        : root_(std::move(root)),
          runs_(runs),
          live_(runs.parent_path() / "live"),
          figures_(std::move(figures)),
          this_run_(figures_),
          committed_(root_ / "figures"),
          out_(std::move(out)),
          pandoc_(std::move(pandoc)),
          label_(std::move(label)),
          strict_(strict),
          contents_(std::move(contents)) {}

    int render();

private:
    std::string page_for(const fs::path& target);  // "" when not a page (yet)
    std::string map_link(const Page& page, const std::string& url, std::vector<std::string>& problems);
    std::string page_document(const Page& page);
    void nodes(md::Json& list, PageWork& w);
    void contents(md::Json& c, PageWork& w);
    void raw_block(const md::Json& list, std::size_t& i, md::Json& out, PageWork& w);
    md::Json live_scene(const std::string& scene, PageWork& w, int at);
    bool inline_marker(const md::Json& list, std::size_t& i, md::Json& out, PageWork& w);
    std::string figure_html(const Page& page, const Image& image, int figure);
    std::string value_html(const prose::ValueMarker& v);
    std::string hand_value_html(const prose::ValueMarker& v, const prose::Json* report);
    std::string numbers_html(std::string line, const std::string& where);
    std::string motion_html(const Page& page, const std::string& path, const std::string& fallback, int motion);
    std::string motion_block(const Page& page, const Image* fallback, const std::string& path, int motion,
                             const std::string& where);
    std::string snippet_source(const Page& page, const std::string& name, const std::string& where);
    std::string rewrite_links(const Page& page, const std::string& html);
    void render_markdown(const Page& page, const Page* prev, const Page* next);
    void render_code(const Page& page);
    std::vector<std::string> pandoc_command(const Page& page, const fs::path& in, const fs::path& out,
                                            const std::string& from);
    std::size_t plan_pages(int& chapters);  // returns how many pages are in reading order
    void prepare_out();
    void render_pages(std::size_t reading_order);
    void check_fragments();
    void copy_viewer();
    void copy_live();
    int summary(int chapters);

    fs::path root_;
    prose::Runs runs_;
    fs::path live_;  // the build's live scenes (cmake/book/live/live.cmake): <build>/live, beside runs.txt
    fs::path figures_;
    prose::Reports this_run_, committed_;
    fs::path out_;
    std::string pandoc_, label_, book_title_;
    bool strict_;
    fs::path contents_;
    std::vector<Page> pages_;
    std::map<std::string, std::size_t> by_source_;  // repo path -> index in pages_
    std::map<std::string, prose::Snippet> snippets_;
    std::vector<std::string> problems_, notes_;
    std::vector<std::tuple<std::string, std::string, std::string, std::string>> fragments_;  // page, link, target, id
    std::vector<std::string> index_lines(const std::vector<std::string>& contents);
    bool own_run() const { return fs::weakly_canonical(figures_) != fs::weakly_canonical(root_ / "figures"); }
    int values_shown_ = 0, values_committed_ = 0, values_unmeasured_ = 0, figures_copied_ = 0;
    int page_values_ = 0, page_committed_ = 0, page_unmeasured_ = 0, page_motions_ = 0, motions_ = 0;
    int page_live_ = 0, lives_ = 0;                   // live scenes (live.cpp) on this page, in the book
    std::map<std::string, int> unmeasured_by_scene_;  // runs without a report: values shown as committed
    std::map<std::string, int> committed_by_scene_;   // runs this build did not make: committed reports
};

// Path of `from` relative to the folder of the book page `page` ("" or "../").
std::string up_to_root(const std::string& page_file) {
    std::string up;
    for (char c : page_file)
        if (c == '/') up += "../";
    return up;
}

std::string Book::page_for(const fs::path& target) {
    const std::string key = rel(target, root_);
    const auto it = by_source_.find(key);
    if (it != by_source_.end()) return pages_[it->second].file;
    const auto ext = target.extension().string();
    const std::string name = target.filename().string();
    if (ext == ".md") {  // another page of prose: render it too
        std::string file = key.substr(0, key.size() - 3);
        std::replace(file.begin(), file.end(), '/', '-');
        pages_.push_back({file + ".html", target, "page", first_heading(target), 0});
    } else if (ext == ".hpp" || ext == ".cpp" || ext == ".h" || ext == ".cmake" || ext == ".gp" || ext == ".sh" ||
               name == "CMakeLists.txt" || key == "cmake/workbook" || key == ".ci/run") {
        pages_.push_back({"code/" + key + ".html", target, "code", key, 0});
    } else {
        return "";
    }
    by_source_[key] = pages_.size() - 1;
    return pages_.back().file;
}

// Maps a link of the prose (relative to its markdown file) to the book.
std::string Book::map_link(const Page& page, const std::string& url, std::vector<std::string>& problems) {
    if (!url.empty() && url[0] == '#') {  // an anchor of this page
        if (url.size() > 1) fragments_.emplace_back(page.file, url, page.file, url.substr(1));
        return url;
    }
    if (url.empty() || url.rfind("http://", 0) == 0 || url.rfind("https://", 0) == 0 || url.rfind("mailto:", 0) == 0 ||
        url.rfind("data:", 0) == 0)
        return url;
    const auto hash = url.find('#');
    const std::string path = url.substr(0, hash), fragment = hash == std::string::npos ? "" : url.substr(hash + 1);
    const fs::path target = (page.source.parent_path() / path).lexically_normal();
    const std::string key = rel(target, root_);
    const std::string up = up_to_root(page.file);
    if (key.rfind("..", 0) == 0) {
        problems.push_back("links outside the workbook: " + url);
        return url;
    }
    // A figure: from the build's figures, else the committed ones; copied next to the pages.
    if (key.rfind("figures/", 0) == 0 && fs::path(key).extension() != ".gp") {
        const fs::path built = figures_ / key.substr(8), committed = root_ / key;
        const fs::path from = fs::exists(built) ? built : committed;
        if (!fs::exists(from)) {
            problems.push_back("the figure " + key + " does not exist (run: cmake/workbook run)");
            return url;
        }
        if (from != built) notes_.push_back(key + ": not drawn by this build, the committed figure is shown");
        fs::create_directories((out_ / key).parent_path());
        fs::copy_file(from, out_ / key, fs::copy_options::overwrite_existing);
        ++figures_copied_;
        return up + key;
    }
    if (!fs::exists(target)) {
        problems.push_back("broken link: " + url + " (" + key + " does not exist)");
        return url;
    }
    if (fs::is_directory(target)) {
        problems.push_back("links to the folder " + key + "/: link a file in it instead");
        return url;
    }
    std::string file = page_for(target);
    if (file.empty()) {  // any other file: copied as it is
        file = "files/" + key;
        fs::create_directories((out_ / file).parent_path());
        fs::copy_file(target, out_ / file, fs::copy_options::overwrite_existing);
    }
    if (!fragment.empty()) fragments_.emplace_back(page.file, url, file, fragment);
    return up + file + (fragment.empty() ? "" : "#" + fragment);
}

// The markdown pandoc sees: snippets named after their source, values of this build, and
// figures with numbered captions.
// A figure: numbered in its chapter, with its caption; one this build should have drawn but did
// not shows the committed one, and says so.
std::string Book::figure_html(const Page& page, const Image& m, int figure) {
    const std::string number =
        page.chapter ? std::to_string(page.chapter) + "." + std::to_string(figure) : std::to_string(figure);
    const std::string key = rel((page.source.parent_path() / m.src).lexically_normal(), root_);
    std::string whose;
    if (key.rfind("figures/", 0) == 0 && own_run() && !fs::exists(figures_ / key.substr(8)))
        whose = " <em>(The committed figure: this build has not drawn it.)</em>";
    return "<figure id=\"figure-" + number + "\">\n<img src=\"" + html_escape(m.src) + "\" alt=\"" +
           html_escape(m.alt) + "\">\n<figcaption><strong>Figure " + number + ".</strong> " + html_escape(m.alt) +
           whose + "</figcaption>\n</figure>\n";
}

// A motion for the viewer (cmake/book/web/motion_viewer.js): the JSON a scene wrote with --motion FILE,
// from this build's figures, else the committed ones (like a figure), put into the page with its
// caption (the scene, its parameters, its error) and its still picture for a reader without
// WebGL (the image line that follows the marker in the prose; GitHub shows only that).
std::string Book::motion_html(const Page& page, const std::string& path, const std::string& fallback, int motion) {
    const std::string number =
        page.chapter ? std::to_string(page.chapter) + "." + std::to_string(motion) : std::to_string(motion);
    const std::string key = rel((page.source.parent_path() / path).lexically_normal(), root_);
    if (key.rfind("figures/", 0) != 0 || fs::path(key).extension() != ".json")
        throw std::runtime_error("a motion is a scene's JSON under figures/, not " + key);
    const fs::path built = figures_ / key.substr(8), committed = root_ / key;
    const fs::path from = fs::exists(built) ? built : committed;
    if (!fs::exists(from)) throw std::runtime_error("the motion " + key + " does not exist (run: cmake/workbook run)");
    if (from != built) notes_.push_back(key + ": not written by this build, the committed motion is shown");
    const auto data = prose::read_json(from);
    for (const char* field : {"scene", "title", "parameters", "error", "error_measure", "t", "R", "body"})
        if (!data.contains(field)) throw std::runtime_error("the motion " + key + " has no '" + field + "'");
    if (!data["error"].is_number() || !std::isfinite(data["error"].get<double>()))
        throw std::runtime_error("the motion " + key + " reports no error (not measured)");
    std::string json = data.dump();  // a script's text ends at "</": write it "<\/"
    for (std::size_t p = 0; (p = json.find("</", p)) != std::string::npos; p += 3) json.replace(p, 2, "<\\/");
    ++page_motions_, ++motions_;
    std::string html = "<figure class=\"motion\" id=\"motion-" + number + "\">\n";
    if (!fallback.empty())
        html += "<img class=\"motion-fallback\" src=\"" + html_escape(fallback) + "\" alt=\"" +
                html_escape(data["title"].get<std::string>()) + "\">\n";
    html += "<script type=\"application/json\" class=\"motion-data\">" + json + "</script>\n";
    html += "<figcaption><strong>Motion " + number + ".</strong> " + html_escape(data["title"].get<std::string>()) +
            ". Scene <code>" + html_escape(data["scene"].get<std::string>()) +
            "</code>: " + html_escape(data["parameters"].get<std::string>()) + "; error " +
            html_escape(prose::sci(data["error"].get<double>(), 2)) + " (" +
            html_escape(data["error_measure"].get<std::string>()) + ").";
    if (from != built) html += " <em>(The committed motion: this build has not written it.)</em>";
    return html + "</figcaption>\n</figure>\n";
}

// A motion marker, and the image after it (the GIF that GitHub shows; `fallback`, may be null),
// which it takes as the viewer's still picture.
std::string Book::motion_block(const Page& page, const Image* fallback, const std::string& path, int motion,
                               const std::string& where) {
    try {
        return motion_html(page, path, fallback ? fallback->src : "", motion);
    } catch (const std::exception& e) {
        problems_.push_back(where + ": " + e.what());
        return "";
    }
}

// A value, from this build's report of its run, else from the committed report of the same run,
// else the text committed with the prose, marked as not measured. Throws what is wrong.
std::string Book::value_html(const prose::ValueMarker& v) {
    const std::string scene = v.scene(), run_key = scene + " (run " + v.run + ")";
    std::string shown;
    const prose::RunDecl* d = runs_.find(scene, v.run);
    if (!d)
        throw std::runtime_error("the scene " + scene + " has no run '" + v.run + "' (declared: " + runs_.names(scene) +
                                 ")");
    // This build's own report of the run; a report made with other options is never read.
    const prose::Json* report = nullptr;
    if (own_run()) {
        try {
            report = this_run_.report(*d);
        } catch (const std::exception& e) {
            notes_.push_back(e.what());
        }
    }
    ++page_values_;
    if (v.tol >= 0) return hand_value_html(v, report ? report : committed_.report(*d));
    if (report) {
        ++values_shown_;
        shown = "<span class=\"value\" title=\"" + html_escape(v.path) + ", run " + v.run +
                ", measured by this build\">" + html_escape(prose::resolve(v, *report)) + "</span>";
    } else if (const prose::Json* c = committed_.report(*d)) {
        const std::string text = prose::resolve(v, *c);
        if (own_run()) {
            ++values_committed_, ++page_committed_;
            ++committed_by_scene_[run_key];
            shown = "<span class=\"value committed\" title=\"" + html_escape(v.path) + ", run " + v.run +
                    ": not run by this build; from the committed report of the same run\">" + html_escape(text) +
                    "</span>";
        } else {
            ++values_shown_;
            shown = "<span class=\"value\" title=\"" + html_escape(v.path) + ", run " + v.run +
                    ", from the committed report\">" + html_escape(text) + "</span>";
        }
    } else {
        ++values_unmeasured_;
        ++page_unmeasured_;
        ++unmeasured_by_scene_[run_key];
        shown = "<span class=\"value unmeasured\" title=\"" + html_escape(v.path) + ", run " + v.run +
                ": no report of this run; the text committed with the prose\">" + v.text + "</span>";
    }
    return shown;
}

// A value typed by hand (tol=): its own text, checked against the report the book reads.
std::string Book::hand_value_html(const prose::ValueMarker& v, const prose::Json* report) {
    if (!report) throw std::runtime_error("a hand value with no report of its run to check it against");
    const std::string off = prose::hand_value_problem(v, *report);
    if (!off.empty()) throw std::runtime_error(off);
    ++values_shown_;
    prose::ValueMarker exact = v;
    exact.fmt = "%.6g";
    return "<span class=\"value hand\" title=\"" + html_escape(v.path) + ", run " + v.run +
           ": typed by hand; the run gives " + html_escape(prose::resolve(exact, *report)) + "\">" + v.text + "</span>";
}

// Where "From <file>" stands for a quoted snippet: a link to the line of its source.
std::string Book::snippet_source(const Page& page, const std::string& name, const std::string& where) {
    const auto s = snippets_.find(name);
    if (s == snippets_.end()) {
        problems_.push_back(where + ": no source defines snippet '" + name + "'");
        return "";
    }
    const std::string link = fs::relative(root_ / s->second.file, page.source.parent_path()).generic_string();
    return "<p class=\"snippet-source\">From <a href=\"" + link + "#src-" + std::to_string(s->second.line + 1) +
           "\"><code>" + html_escape(s->second.file) + "</code></a></p>\n\n";
}

// The page as pandoc's tree (its JSON), with the book's markers done: a quotation's markers become
// a link to the snippet's source, a value marker and its text the value, a number tag nothing (it
// is for the check of numbers), a motion marker the viewer, a paragraph that is one image a
// numbered figure. Everything else is the tree pandoc read from the Markdown (markdown.hpp).
std::string Book::page_document(const Page& page) {
    auto lines = prose::read_lines(page.source);
    page_values_ = page_committed_ = page_unmeasured_ = page_motions_ = page_live_ = 0;
    if (page.kind == "contents") lines = index_lines(lines);
    std::string text;
    for (const auto& l : lines) text += l + "\n";
    const fs::path scratch = out_ / ".work" / (page.file + ".source.md");
    prose::write_text(scratch, text);
    const md::Page tree = md::read_page(scratch, pandoc_);
    PageWork w{page, tree, rel(page.source, root_), {}, {}, 0, 0, {}};
    for (const auto& q : md::quotations(tree)) {
        w.snippets[q.line] = q.name;
        if (q.end_line) w.ends.insert(q.end_line);
    }
    md::Json blocks = tree.blocks;
    nodes(blocks, w);
    strip_lines(blocks);
    return md::Json{{"pandoc-api-version", tree.api_version}, {"meta", md::Json::object()}, {"blocks", blocks}}.dump();
}

// A list of blocks or inlines, done in place (see page_document), with every node's contents.
void Book::nodes(md::Json& list, PageWork& w) {
    md::Json out = md::Json::array();
    for (std::size_t i = 0; i < list.size(); ++i) {
        md::Json& n = list[i];
        if (md::is(n, "RawBlock")) {
            raw_block(list, i, out, w);
            continue;
        }
        if (md::is(n, "RawInline") && inline_marker(list, i, out, w)) continue;
        if (const auto image = figure_of(n, w.tree.lines)) {
            out.push_back(raw_html_node("RawBlock", figure_html(w.page, *image, ++w.figure)));
            continue;
        }
        if (n.contains("c")) contents(n["c"], w);
        out.push_back(std::move(n));
    }
    list = std::move(out);
}

// A node's contents: a list of nodes, or a tuple (a header's level, attributes and inlines; a
// table's parts) whose lists of nodes are somewhere inside.
void Book::contents(md::Json& c, PageWork& w) {
    if (is_node_list(c)) return nodes(c, w);
    if (c.is_object() && c.contains("t") && c.contains("c")) return contents(c["c"], w);
    if (c.is_array())
        for (auto& part : c) contents(part, w);
}

// A block of raw HTML: a quotation's marker (a link to the snippet's source; its end marker goes),
// a motion marker (the viewer, with the figure on the next line as its still picture), or other
// HTML, with the number tags and value markers of its lines done on its text. A line that starts
// with a value marker or a number tag is a problem: CommonMark (GitHub too) reads it as raw HTML.
void Book::raw_block(const md::Json& list, std::size_t& i, md::Json& out, PageWork& w) {
    static const std::regex motion(R"(^<!-- motion: (\S+) -->\s*$)");  // the markers' own grammar
    static const std::regex live(R"(^<!-- live: (\w+) -->\s*$)");
    const int at = md::line(list[i]);
    const std::string html = md::raw_html(list[i]);
    std::smatch m;
    if (w.snippets.count(at) && html.rfind("<!-- snippet:", 0) == 0) {
        out.push_back(raw_html_node("RawBlock", snippet_source(w.page, w.snippets.at(at), w.where(at))));
    } else if (w.ends.count(at)) {
        return;
    } else if (std::regex_match(html, m, motion)) {
        std::optional<Image> still;
        if (i + 1 < list.size() && md::line(list[i + 1]) == at + 1) still = figure_of(list[i + 1], w.tree.lines);
        if (still) ++i;
        const std::string viewer = motion_block(w.page, still ? &*still : nullptr, m[1], ++w.motion, w.where(at));
        if (!viewer.empty()) out.push_back(raw_html_node("RawBlock", viewer));
    } else if (std::regex_match(html, m, live)) {
        out.push_back(live_scene(m[1], w, at));
    } else if (html.find("<!--") == std::string::npos) {
        out.push_back(list[i]);
    } else {
        if (md::starts_with_inline_marker(html))
            problems_.push_back(w.where(at) +
                                ": starts with a value marker or a number tag: CommonMark (GitHub, "
                                "pandoc) takes the whole line for raw HTML; move a word in front of it");
        std::istringstream in(html);
        std::string done;
        int k = at;
        for (std::string l; std::getline(in, l); ++k) done += numbers_html(l, w.where(k)) + "\n";
        out.push_back(raw_html_node("RawBlock", done));
    }
}

// A live scene (live.cpp): its modules and spec from the build's live/ folder; without them (no
// emscripten, or no GSL for a scene that needs it) the block says so.
md::Json Book::live_scene(const std::string& scene, PageWork& w, int at) {
    const LiveBlock b = live_block(live_, out_, scene, up_to_root(w.page.file));
    page_live_ += b.live ? 1 : 0, lives_ += b.live ? 1 : 0;
    if (!b.live)
        notes_.push_back(w.where(at) + ": the live scene " + scene + " is not built (" +
                         live_missing_reason(live_, scene) + ")");
    return raw_html_node("RawBlock", b.html);
}

// An HTML comment inside a paragraph: a number tag goes; a value marker, its text and its end
// marker become the value (the marker read from its source line, prose.hpp's grammar). Returns
// false for any other comment, which stays.
bool Book::inline_marker(const md::Json& list, std::size_t& i, md::Json& out, PageWork& w) {
    const std::string html = md::raw_html(list[i]);
    const int at = md::line(list[i]);
    if (html.rfind("<!-- value:", 0) != 0) {
        const auto tags = prose::find_number_tags(html);
        return tags.size() == 1 && tags[0].begin == 0 && tags[0].end == html.size();
    }
    std::size_t end = i + 1;
    while (end < list.size() && md::raw_html(list[end]).rfind("<!-- end value -->", 0) != 0) ++end;
    const auto markers = prose::find_value_markers(w.line_text(at));
    std::size_t& k = w.values_done[at];
    if (end == list.size() || k >= markers.size()) {
        problems_.push_back(w.where(at) + ": a value marker without its '<!-- end value -->' on the same line");
        return false;
    }
    const prose::ValueMarker& v = markers[k++];
    try {
        if (!v.error.empty()) throw std::runtime_error(v.error);
        out.push_back(raw_html_node("RawInline", value_html(v)));
        i = end;
    } catch (const std::exception& e) {
        problems_.push_back(w.where(at) + ": value '" + v.path + "': " + e.what());
        return false;
    }
    return true;
}

// One line of prose with its numbers as the reader sees them: each value marker replaced by its
// value (problems noted), and the number tags (<!--exact--> ...) dropped: they are for the check of
// numbers, and at the start of a line pandoc would take one for an HTML block and leave the line's
// math as text.
std::string Book::numbers_html(std::string line, const std::string& where) {
    const auto tags = prose::find_number_tags(line);
    for (auto t = tags.rbegin(); t != tags.rend(); ++t) line.erase(t->begin, t->end - t->begin);
    auto markers = prose::find_value_markers(line);
    for (auto v = markers.rbegin(); v != markers.rend(); ++v) {
        if (!v->error.empty()) {
            problems_.push_back(where + ": value '" + v->path + "': " + v->error);
            continue;
        }
        try {
            line.replace(v->begin, v->end - v->begin, value_html(*v));
        } catch (const std::exception& e) {
            problems_.push_back(where + ": value '" + v->path + "': " + e.what());
        }
    }
    return line;
}

// The source lines of the block at `line` (1-based): up to the next blank line.
std::string block_text(const md::Page& page, int line) {
    std::string text;
    for (auto i = static_cast<std::size_t>(std::max(line, 1)) - 1;
         i < page.lines.size() && page.lines[i].find_first_not_of(" \t") != std::string::npos; ++i)
        text += page.lines[i] + "\n";
    return text;
}

// A link "[words](target)" of a Markdown text, written as its words; the tree named the target.
void unlink(std::string& text, const std::string& target) {
    const auto close = text.find("](" + target + ")");
    if (close == std::string::npos) return;
    std::size_t open = close;
    for (int depth = 0; open-- > 0;) {
        if (text[open] == ']') ++depth;
        if (text[open] == '[' && depth-- == 0) break;
    }
    if (open == std::string::npos) return;
    text.replace(open, close + target.size() + 3 - open, text.substr(open + 1, close - open - 1));
}

// The first paragraph after the title of the top README, its links (which lead elsewhere) as
// their words.
std::string lead_paragraph(const fs::path& readme) {
    const md::Page page = md::read_page(readme);
    bool titled = false;
    for (const auto& b : page.blocks) {
        if (!titled) {
            titled = md::is(b, "Header") && b["c"][0] == 1;
            continue;
        }
        if (!md::is(b, "Para")) return "";
        std::string text = block_text(page, md::line(b));
        md::walk(b, [&](const md::Json& n) {
            if (md::is(n, "Link")) unlink(text, n["c"][2][0].get<std::string>());
            return true;
        });
        return text;
    }
    return "";
}

// The contents page opens the book: its title, the first paragraph of the top README (what
// the book is about), a pointer to how to use it, then chapters/README.md under "Contents" (its
// title, the first level-1 heading in its tree, made a section of the opening page).
std::vector<std::string> Book::index_lines(const std::vector<std::string>& contents) {
    std::vector<std::string> out{"# " + book_title_, ""};
    const std::string lead = lead_paragraph(root_ / "README.md");
    if (!lead.empty()) out.push_back("<div class=\"lead\">\n\n" + lead + "\n</div>\n");
    out.push_back(
        "New here? [Using the workbook](../README.md) has the two commands that build, run and test it, "
        "and how students, self-learners and instructors work with it.");
    out.push_back("");
    int title = 0;
    const md::Page page = md::read_page(root_ / "chapters" / "README.md");
    for (const auto& b : page.blocks)
        if (!title && md::is(b, "Header") && b["c"][0] == 1) title = md::line(b);
    for (std::size_t i = 0; i < contents.size(); ++i)
        out.push_back(static_cast<int>(i) + 1 == title ? "#" + contents[i] : contents[i]);
    return out;
}

// MathML that browsers draw better: pandoc writes the dot and double dot accents (\dot R,
// \ddot R) as combining characters, which Chromium places badly; the spacing accents sit right.
std::string better_accents(std::string html) {
    const std::pair<std::string, std::string> swaps[] = {
        {"<mo accent=\"true\">\u0307</mo>", "<mo accent=\"true\">\u02D9</mo>"},
        {"<mo accent=\"true\">\u0308</mo>", "<mo accent=\"true\">\u00A8</mo>"},
    };
    for (const auto& [from, to] : swaps) {
        std::string out;
        std::size_t last = 0;
        for (std::size_t p; (p = html.find(from, last)) != std::string::npos; last = p + from.size())
            out += html.substr(last, p - last) + to;
        html = out + html.substr(last);
    }
    return html;
}

std::string Book::rewrite_links(const Page& page, const std::string& html) {
    // Only the page's own content: the template's navigation is already in book terms.
    const auto begin = html.find("<main>"), end = html.rfind("</main>");
    if (begin == std::string::npos || end == std::string::npos) {
        problems_.push_back(page.file + ": the page template lost its <main>");
        return html;
    }
    const std::string body = html.substr(begin, end - begin);
    const std::regex attr(R"#(\b(href|src)="([^"]*)")#");
    std::string out;
    std::size_t last = 0;
    std::vector<std::string> problems;
    for (auto it = std::sregex_iterator(body.begin(), body.end(), attr); it != std::sregex_iterator(); ++it) {
        const auto& m = *it;
        out += body.substr(last, static_cast<std::size_t>(m.position(0)) - last);
        std::string url;  // pandoc writes & as &amp; in attributes
        const std::string raw = m[2];
        for (std::size_t k = 0; k < raw.size(); ++k) {
            url += raw[k];
            if (raw.compare(k, 5, "&amp;") == 0) k += 4;
        }
        out += m[1].str() + "=\"" + html_escape(map_link(page, url, problems)) + "\"";
        last = static_cast<std::size_t>(m.position(0) + m.length(0));
    }
    out += body.substr(last);
    for (const auto& p : problems) problems_.push_back(rel(page.source, root_) + ": " + p);
    return html.substr(0, begin) + out + html.substr(end);
}

std::vector<std::string> Book::pandoc_command(const Page& page, const fs::path& in, const fs::path& out,
                                              const std::string& from) {
    std::vector<std::string> cmd{pandoc_,
                                 "--from=" + from,
                                 "--to=html5",
                                 "--mathml",
                                 "--standalone",
                                 "--template=" + (root_ / "cmake" / "book" / "web" / "page.html").string(),
                                 "--metadata=pagetitle:" + page.title + " | " + book_title_,
                                 "--variable=root:" + up_to_root(page.file),
                                 "--variable=book-title:" + html_escape(book_title_),
                                 "--variable=page-kind:" + page.kind,
                                 "--variable=page-id:" + fs::path(page.file).stem().string(),
                                 "--variable=source:" + html_escape(rel(page.source, root_))};
    if (page_values_) cmd.push_back("--variable=label:" + html_escape(label_));
    if (page_committed_) cmd.push_back("--variable=committed:yes");
    if (page_unmeasured_) cmd.push_back("--variable=unmeasured:yes");
    if (page_motions_) cmd.push_back("--variable=motion:yes");
    if (page_live_) cmd.push_back("--variable=live:yes");
    if (page.kind == "chapter") cmd.insert(cmd.end(), {"--toc", "--toc-depth=3"});
    cmd.insert(cmd.end(), {"--output=" + out.string(), in.string()});
    return cmd;
}

void Book::render_markdown(const Page& page, const Page* prev, const Page* next) {
    const fs::path tmp = out_ / ".work" / (page.file + ".json");
    prose::write_text(tmp, page_document(page));
    std::vector<std::string> cmd = pandoc_command(page, tmp, out_ / ".work" / page.file, "json");
    auto nav = [&](const std::string& name, const Page* p) {
        if (p)
            cmd.insert(cmd.end() - 1, {"--variable=" + name + "-url:" + up_to_root(page.file) + p->file,
                                       "--variable=" + name + "-title:" + html_escape(p->title)});
    };
    nav("prev", prev);
    nav("next", next);
    const Output o = run(cmd);
    if (o.status != 0) {
        problems_.push_back(rel(page.source, root_) + ": pandoc failed (" + std::to_string(o.status) + "): " + o.text);
        return;
    }
    // pandoc renders math it cannot convert to MathML as TeX, with a warning: that is an error here.
    std::istringstream warnings(o.text);
    for (std::string w; std::getline(warnings, w);)
        if (!w.empty()) problems_.push_back(rel(page.source, root_) + ": pandoc: " + w);
    prose::write_text(out_ / page.file,
                      better_accents(rewrite_links(page, prose::read_text(out_ / ".work" / page.file))));
}

void Book::render_code(const Page& page) {
    page_values_ = page_committed_ = page_unmeasured_ = page_motions_ = page_live_ = 0;
    const std::string text = prose::read_text(page.source);
    std::size_t longest = 2, run_len = 0;
    for (char c : text) {
        run_len = c == '`' ? run_len + 1 : 0;
        longest = std::max(longest, run_len);
    }
    const std::string fence(longest + 1, '`');
    const std::string name = page.source.filename().string(), ext = page.source.extension().string();
    std::string lang = "default";
    if (ext == ".cpp" || ext == ".hpp" || ext == ".h")
        lang = "cpp";
    else if (ext == ".cmake" || name == "CMakeLists.txt")
        lang = "cmake";
    else if (ext == ".sh" || name == "workbook" || name == "run")
        lang = "bash";
    std::string md = "# " + page.title + "\n\nThe file `" + page.title +
                     "` as it is in the workbook's repository.\n\n" + fence + " {#src ." + lang + " .numberLines}\n" +
                     text + (text.empty() || text.back() == '\n' ? "" : "\n") + fence + "\n";
    const fs::path tmp = out_ / ".work" / (page.file + ".md");
    prose::write_text(tmp, md);
    fs::create_directories((out_ / page.file).parent_path());
    const Output o = run(pandoc_command(page, tmp, out_ / page.file, "markdown-tex_math_dollars"));
    if (o.status != 0) problems_.push_back(page.title + ": pandoc failed: " + o.text);
}

// The fixed pages and the reading order: contents, chapters, errata, hints; then the top README.
std::size_t Book::plan_pages(int& chapters) {
    pages_.push_back({"index.html", root_ / "chapters" / "README.md", "contents", "Contents", 0});
    chapters = 0;
    for (const auto& ch : chapter_list(contents_)) {
        const fs::path md = root_ / "chapters" / ch / "README.md";
        if (!fs::exists(md)) {
            problems_.push_back("chapters/README.md links " + ch + "/README.md, which does not exist");
            continue;
        }
        // The chapter's number is the NN of its folder, as in the contents (not its place in the list:
        // a chapter in preparation leaves a gap, and Chapter 8's figures are still 8.x).
        ++chapters;
        pages_.push_back({ch + ".html", md, "chapter", first_heading(md), std::stoi(ch.substr(0, 2))});
    }
    for (const auto& [file, src] : {std::pair<std::string, std::string>{"errata.html", "chapters/errata.md"},
                                    {"hints.html", "exercises/hints.md"}}) {
        if (fs::exists(root_ / src)) pages_.push_back({file, root_ / src, "page", first_heading(root_ / src), 0});
    }
    const std::size_t reading_order = pages_.size();
    pages_.push_back({"workbook.html", root_ / "README.md", "page", "How to use the workbook", 0});
    for (std::size_t i = 0; i < pages_.size(); ++i) by_source_[rel(pages_[i].source, root_)] = i;
    return reading_order;
}

// Starts from an empty folder, so that no page of an earlier render survives; pandoc must run.
void Book::prepare_out() {
    if (fs::exists(out_)) {
        if (!fs::is_directory(out_) || (!fs::is_empty(out_) && !fs::exists(out_ / "pages.txt")))
            throw std::runtime_error(out_.string() + " exists and is not a book rendered before: not touching it");
        fs::remove_all(out_);
    }
    fs::create_directories(out_);
    if (const Output v = run({pandoc_, "--version"}); v.status != 0)
        throw std::runtime_error("cannot run pandoc ('" + pandoc_ +
                                 "'): install it with sudo apt-get install pandoc, "
                                 "or run cmake/workbook, which does");
    fs::copy_file(root_ / "cmake" / "book" / "web" / "book.css", out_ / "book.css",
                  fs::copy_options::overwrite_existing);
}

// The motion viewer of the pages that show a motion: its script, and three.js from Debian's
// libjs-three (r111), copied into the book so that it works offline.
void Book::copy_viewer() {
    if (!motions_) return;
    const fs::path three = "/usr/share/javascript/three/three.min.js";
    if (!fs::exists(three)) {
        problems_.push_back(std::to_string(motions_) + " motion(s) need three.js: " + three.string() +
                            " is missing (Debian: sudo apt-get install libjs-three; cmake/workbook installs it)");
        return;
    }
    fs::copy_file(three, out_ / "three.min.js", fs::copy_options::overwrite_existing);
    fs::copy_file(root_ / "cmake" / "book" / "web" / "motion_viewer.js", out_ / "motion_viewer.js",
                  fs::copy_options::overwrite_existing);
}

// The driver of the live scenes (cmake/book/web/live.js), for the pages that have one.
void Book::copy_live() {
    if (lives_)
        fs::copy_file(root_ / "cmake" / "book" / "web" / "live.js", out_ / "live.js",
                      fs::copy_options::overwrite_existing);
}

// Every page; pages found through links are appended while we go.
void Book::render_pages(std::size_t reading_order) {
    for (std::size_t i = 0; i < pages_.size(); ++i) {
        const Page page = pages_[i];
        if (page.kind == "code") {
            render_code(page);
            continue;
        }
        // Previous and next in reading order; the last page and the pages outside it lead
        // back to the contents.
        const Page* prev = i > 0 && i < reading_order ? &pages_[i - 1] : nullptr;
        const Page* next = i + 1 < reading_order ? &pages_[i + 1] : (i > 0 ? &pages_[0] : nullptr);
        const Page prev_copy = prev ? *prev : Page{}, next_copy = next ? *next : Page{};
        render_markdown(page, prev ? &prev_copy : nullptr, next ? &next_copy : nullptr);
    }
}

// Every link into a page must find its anchor there.
void Book::check_fragments() {
    std::map<std::string, std::set<std::string>> ids;
    const std::regex id_attr(R"#(\bid="([^"]+)")#");
    for (const auto& [from, url, file, id] : fragments_) {
        if (!ids.count(file)) {
            const std::string html = fs::exists(out_ / file) ? prose::read_text(out_ / file) : "";
            auto& s = ids[file];
            for (auto it = std::sregex_iterator(html.begin(), html.end(), id_attr); it != std::sregex_iterator(); ++it)
                s.insert((*it)[1]);
        }
        if (!ids[file].count(id))
            problems_.push_back(from + ": the link " + url + " names #" + id + ", which " + file + " does not have");
    }
}

// pages.txt for the browser test, and what was rendered, with every note and problem.
int Book::summary(int chapters) {
    for (const auto& [what, count] : unmeasured_by_scene_)
        (strict_ ? problems_ : notes_)
            .push_back("no report of " + what + " in " + figures_.string() +
                       " or the committed figures: " + std::to_string(count) +
                       " value(s) show the text committed with the prose, marked as not measured");
    for (const auto& [what, count] : committed_by_scene_)
        notes_.push_back("this build did not run " + what + ": " + std::to_string(count) +
                         " value(s) from its committed report (same options), marked so");
    std::string list;
    for (const auto& p : pages_) list += p.file + "\t" + p.kind + "\t" + p.title + "\n";
    prose::write_text(out_ / "pages.txt", list);
    fs::remove_all(out_ / ".work");
    std::cout << "book: " << pages_.size() << " pages (" << chapters << " chapters), " << figures_copied_
              << " figures, " << motions_ << " motions, " << values_shown_ << " values from "
              << (own_run() ? figures_.string() : "the committed reports");
    if (values_committed_) std::cout << ", " << values_committed_ << " from the committed reports";
    if (values_unmeasured_) std::cout << ", " << values_unmeasured_ << " not measured";
    std::cout << "\n      " << (out_ / "index.html").string() << "\n";
    for (const auto& note : notes_) std::cout << "  note: " << note << "\n";
    for (const auto& p : problems_) std::cout << "  " << p << "\n";
    return problems_.empty() ? 0 : 1;
}

int Book::render() {
    std::vector<std::string> problems;
    snippets_ = prose::collect_snippets(root_, prose::scan_tree(root_).sources, problems);
    for (const auto& p : problems) problems_.push_back(p);
    book_title_ = first_heading(root_ / "README.md");
    if (!label_.empty()) {
        char when[64];
        const std::time_t now = std::time(nullptr);
        std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
        label_ += ", " + std::string(when);
    }
    int chapters = 0;
    const std::size_t reading_order = plan_pages(chapters);
    prepare_out();
    render_pages(reading_order);
    check_fragments();
    copy_viewer();
    copy_live();
    return summary(chapters);
}

}  // namespace

int render(const RenderOptions& o) {
    Book book(o.root, o.runs, o.figures, o.out, o.pandoc, o.label, o.strict, o.contents);
    return book.render();
}

}  // namespace book
