// snippets --check, --check-values, --update, --diff: the code snippets quoted in the prose and
// the value markers (see prose.hpp for both), found in each page's document tree as pandoc parses
// it (markdown.hpp): what is in code is code, not a marker.
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "markdown.hpp"
#include "prose.hpp"
#include "snippets.hpp"

namespace snippets {

namespace {

using prose::rel;

// Checks (or refreshes) the quoted code and the value markers of every prose file.
//   runs:  the declared runs (check_values, update with values, diff)
//   smoke: the test suite's reports (check_values; may be null)
//   tree:  a build's figures (diff)
class ProseChecker {
public:
    ProseChecker(const fs::path& root, Mode mode, const prose::Runs* runs, const fs::path* smoke, const fs::path* tree)
        : root_(root),
          mode_(mode),
          runs_(runs),
          smoke_(smoke),
          tree_files_(prose::scan_tree(root)),
          snippets_(prose::collect_snippets(root, tree_files_.sources, problems_)),
          committed_(root / "figures") {
        if (tree) other_.emplace(*tree);
        for (const auto& p : tree_files_.sources)  // a scene is chapters/*/<scene>.cpp
            if (rel(p, root).rfind("chapters/", 0) == 0 && p.extension() == ".cpp") scenes_.insert(p.stem().string());
    }

    int run() {
        for (const auto& p : tree_files_.prose)
            if (fs::exists(p)) file(p);
        if (mode_ == Mode::check)
            for (const auto& [name, s] : snippets_)
                if (!s.used)
                    problems_.push_back(s.file + ":" + std::to_string(s.line) + ": snippet '" + name +
                                        "' is not quoted anywhere in the prose");
        if (mode_ == Mode::diff)
            print_diff();
        else
            print_summary();
        for (const auto& p : problems_) std::cout << "  " << p << "\n";
        return problems_.empty() ? 0 : 1;
    }

private:
    struct Tally {
        int values = 0, same = 0, differ = 0, missing = 0;
    };

    // One prose file, read as pandoc parses it (markdown.hpp): its value markers and its
    // quotations, rewritten in place by --update.
    void file(const fs::path& p) {
        const md::Page page = md::read_page(p);
        std::vector<std::string> lines = page.lines;
        const std::string name = rel(p, root_);
        bool changed = false;
        for (auto& [at, opens] : md::value_marker_lines(page)) {
            if (at < 1 || static_cast<std::size_t>(at) > lines.size()) continue;
            std::string& line = lines[static_cast<std::size_t>(at) - 1];
            // The marker's grammar (prose.hpp) reads its options and text off the line; the tree
            // said which markers of the line are Markdown's (not in code).
            auto markers = prose::find_value_markers(line);
            for (auto v = markers.rbegin(); v != markers.rend(); ++v) {
                const auto it = std::find(opens.begin(), opens.end(), line.substr(v->begin, v->text_begin - v->begin));
                if (it == opens.end()) continue;
                opens.erase(it);
                changed |= value(*v, name, name + ":" + std::to_string(at), line);
            }
        }
        auto quoted = md::quotations(page);  // from the bottom up: an update changes the lines below
        std::sort(quoted.begin(), quoted.end(), [](const auto& a, const auto& b) { return a.line > b.line; });
        for (const auto& q : quoted) changed |= quote(q, name, lines);
        if (mode_ == Mode::update && changed) {
            std::string text;
            for (const auto& l : lines) text += l + "\n";
            prose::write_text(p, text);
            std::cout << "updated " << rel(p, root_) << "\n";
        }
    }

    // One value marker: checked against its run's committed report (refreshed by --update), or
    // compared with another build's report (--diff). Returns whether `line` changed.
    bool value(const prose::ValueMarker& v, const std::string& file, const std::string& where, std::string& line) {
        ++n_values_;
        const std::string at = where + ": value '" + v.path + "'";
        if (!v.error.empty()) return problem(at + ": " + v.error);
        const std::string scene = v.scene();
        if (!scenes_.count(scene))
            return problem(at + ": there is no scene '" + scene + "' (chapters/*/" + scene + ".cpp)");
        if (!runs_) return false;
        const prose::RunDecl* d = runs_->find(scene, v.run);
        if (!d)
            return problem(at + ": the scene " + scene + " has no run '" + v.run +
                           "' (declared: " + runs_->names(scene) + ")");
        try {
            if (mode_ == Mode::diff) return diff(v, *d, file, at);
            if (mode_ == Mode::check_values) still_reported(v, scene, at);
            const prose::Json* r = committed_.report(*d);
            const std::string report = rel(prose::report_path(root_ / "figures", *d), root_);
            if (!r)
                return problem(at + ": no committed report " + report +
                               " (run cmake/workbook run, then the target update-figures)");
            if (v.tol >= 0) {  // typed by hand: checked, never rewritten
                const std::string off = prose::hand_value_problem(v, *r);
                return off.empty() ? false : problem(at + ": " + off + " in its committed report " + report);
            }
            const std::string text = prose::resolve(v, *r);
            if (text == v.text) return false;
            if (mode_ != Mode::update)
                return problem(at + ": the text says '" + v.text + "', its committed report " + report + " says '" +
                               text + "' (run the target update-snippets)");
            line.replace(v.text_begin, v.text_end - v.text_begin, text);
            ++refreshed_;
            return true;
        } catch (const std::exception& e) {
            return problem(at + ": " + e.what());
        }
    }

    // --diff: the marker's text against the report of the same run in the other tree.
    bool diff(const prose::ValueMarker& v, const prose::RunDecl& d, const std::string& file, const std::string& at) {
        auto& t = tally_[file];
        ++t.values;
        const prose::Json* r = other_->report(d);
        if (!r) {
            ++t.missing;
            differences_.push_back(at + " (" + v.run + "): no report in " + other_->tree().string());
            return false;
        }
        const std::string text = prose::resolve(v, *r);
        if (v.tol >= 0 ? prose::hand_value_problem(v, *r).empty() : text == v.text) {
            ++t.same;
        } else {
            ++t.differ;
            differences_.push_back(at + " (" + v.run + "): text " + v.text + ", this run " + text);
        }
        return false;
    }

    // --check-values with the test suite's reports: the scene as built still reports the key.
    void still_reported(const prose::ValueMarker& v, const std::string& scene, const std::string& at) {
        const prose::Json* s = smoke_report(scene);
        if (!s) return;
        try {
            prose::lookup(*s, v.path.substr(v.path.find_first_of(".[")));
        } catch (const std::exception& e) {
            problem(at + ": the scene as built no longer reports it (its test run: " + e.what() + ")");
        }
    }

    // A smoke report: <smoke>/<scene>.json, read once.
    const prose::Json* smoke_report(const std::string& scene) {
        if (!smoke_) return nullptr;
        auto it = smoke_reports_.find(scene);
        if (it != smoke_reports_.end()) return it->second.get();
        std::unique_ptr<prose::Json> j;
        const fs::path p = *smoke_ / (scene + ".json");
        if (fs::exists(p)) j = std::make_unique<prose::Json>(prose::read_json(p));
        return (smoke_reports_[scene] = std::move(j)).get();
    }

    // A quotation of a code snippet: checked against the source, or rewritten by --update (the
    // lines between its markers). Returns whether `lines` changed.
    bool quote(const md::Quotation& q, const std::string& file, std::vector<std::string>& lines) {
        const std::string where = file + ":" + std::to_string(q.line);
        if (!q.end_line) return problem(where + ": '<!-- snippet: " + q.name + " -->' has no '<!-- end snippet -->'");
        const auto s = snippets_.find(q.name);
        if (s == snippets_.end())
            return problem(where + ": no source defines snippet '" + q.name + "' (code removed or renamed?)");
        s->second.used = true;
        ++quoted_;
        const std::string& text = s->second.text;
        if (q.one_cpp_block && (q.code.empty() ? text.empty() : q.code + "\n" == text)) return false;
        ++stale_;
        if (mode_ == Mode::check)
            problem(where + ": snippet '" + q.name + "' differs from " + s->second.file + ":" +
                    std::to_string(s->second.line) + " (run: cmake --build <build> --target update-snippets)");
        if (mode_ != Mode::update) return false;
        std::vector<std::string> wanted{"```cpp"};
        std::istringstream w(text);
        for (std::string l; std::getline(w, l);) wanted.push_back(l);
        wanted.push_back("```");
        const auto first = lines.begin() + q.line;  // the line after the marker
        lines.insert(lines.erase(first, lines.begin() + (q.end_line - 1)), wanted.begin(), wanted.end());
        return true;
    }

    bool problem(const std::string& what) {
        problems_.push_back(what);
        return false;
    }

    void print_diff() const {
        Tally all;
        std::cout << "The value markers against the reports in " << other_->tree().string() << ":\n";
        for (const auto& [file, t] : tally_) {
            std::cout << "  " << file << ": " << t.values << " values, " << t.same << " as in the text, " << t.differ
                      << " different, " << t.missing << " without a report\n";
            all.values += t.values, all.same += t.same, all.differ += t.differ, all.missing += t.missing;
        }
        std::cout << "  all: " << all.values << " values, " << all.same << " as in the text, " << all.differ
                  << " different, " << all.missing << " without a report\n";
        for (const auto& d : differences_) std::cout << "  " << d << "\n";
    }

    void print_summary() const {
        const bool update = mode_ == Mode::update;
        std::cout << snippets_.size() << " snippets in the sources, " << quoted_ << " quotations in the prose";
        if (update) std::cout << ", " << stale_ << " refreshed";
        std::cout << "; " << n_values_ << " value markers";
        if (runs_) {
            std::cout << " (committed reports in " << (root_ / "figures").string() << ")";
            if (update) std::cout << ", " << refreshed_ << " refreshed";
        } else if (update) {
            std::cout << " (not refreshed: no list of runs given)";
        }
        std::cout << "\n";
    }

    fs::path root_;
    Mode mode_;
    const prose::Runs* runs_;
    const fs::path* smoke_;
    std::vector<std::string> problems_;
    prose::Tree tree_files_;
    std::map<std::string, prose::Snippet> snippets_;
    prose::Reports committed_;
    std::optional<prose::Reports> other_;
    std::set<std::string> scenes_;
    std::map<std::string, std::unique_ptr<prose::Json>> smoke_reports_;
    int quoted_ = 0, stale_ = 0, n_values_ = 0, refreshed_ = 0;
    std::map<std::string, Tally> tally_;  // diff: per prose file
    std::vector<std::string> differences_;
};

}  // namespace

int snippets_and_values(const fs::path& root, Mode mode, const prose::Runs* runs, const fs::path* smoke,
                        const fs::path* tree) {
    return ProseChecker(root, mode, runs, smoke, tree).run();
}

}  // namespace snippets
