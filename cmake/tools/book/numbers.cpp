// snippets --check-numbers: every number of the prose that looks measured says what it is, and
// every section of the workbook named by number is a link to it (see prose.hpp).
#include <algorithm>
#include <iostream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "../prose.hpp"
#include "snippets.hpp"

namespace snippets {

namespace {

using prose::rel;

// Every number of the prose that looks measured is a value marker or carries a tag that says
// what it is (prose.hpp). Per file: each untagged one, each tag that is malformed or covers
// numbers that are not there, and `once` (measured once, by hand) in a chapter.
class NumberLint {
public:
    explicit NumberLint(const fs::path& root) : root_(root) {}

    int run() {
        for (const auto& p : prose::scan_tree(root_).prose)
            if (fs::exists(p)) file(p);
        std::cout << "Numbers that look measured in " << files_ << " pages of prose: " << markers_ << " value markers ("
                  << hand_ << " of them typed by hand and checked), " << tagged_ << " tagged (";
        for (const auto& k : prose::number_kinds()) std::cout << (k == "exact" ? "" : ", ") << k << " " << kinds_[k];
        std::cout << "), " << problems_.size() << " problems\n";
        for (const auto& p : problems_) std::cout << "  " << p << "\n";
        return problems_.empty() ? 0 : 1;
    }

private:
    struct Pending {
        std::string kind, where;
        int left = 0;
    };

    void file(const fs::path& p) {
        ++files_;
        const std::string name = rel(p, root_);
        const bool manual = name.rfind("chapters/", 0) != 0 && name.rfind("exercises/", 0) != 0;
        bool in_fence = false, in_comment = false;
        Pending pending;
        const auto lines = prose::read_lines(p);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string where = name + ":" + std::to_string(i + 1);
            const std::string& line = lines[i];
            if (prose::is_fence(line)) in_fence = !in_fence;
            if (in_fence || prose::is_fence(line)) continue;
            if (line.find_first_not_of(" \t") == std::string::npos) {
                stale(pending);
                continue;
            }
            auto skip = masked(line, in_comment);
            sections(line, skip, where);
            struct Event {
                std::size_t at;
                const prose::NumberTag* tag;
                const prose::ProseNumber* number;
            };
            std::vector<Event> events;
            const auto tags = prose::find_number_tags(line);
            for (const auto& t : tags) events.push_back({t.begin, &t, nullptr});
            const auto numbers = prose::measured_numbers(line, skip);
            for (const auto& n : numbers) events.push_back({n.begin, nullptr, &n});
            std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.at < b.at; });
            for (const Event& e : events) {
                if (e.tag)
                    open_tag(*e.tag, where, manual, pending);
                else if (pending.left > 0)
                    --pending.left, ++tagged_, ++kinds_[pending.kind];
                else
                    problems_.push_back(where + ": " + e.number->text +
                                        " looks measured: make it a value marker, or tag it "
                                        "(<!--exact-->, <!--input-->, <!--const-->, <!--P-->)");
            }
        }
        stale(pending);
    }

    // Characters that are not prose: code spans, HTML comments (tags included; also one that
    // runs on from an earlier line), value markers (counted here) and link targets.
    std::vector<bool> masked(const std::string& line, bool& in_comment) {
        auto skip = prose::code_span_mask(line);
        std::size_t from = 0;
        if (in_comment) {
            const auto close = line.find("-->");
            from = close == std::string::npos ? line.size() : close + 3;
            std::fill(skip.begin(), skip.begin() + static_cast<std::ptrdiff_t>(from), true);
            in_comment = close == std::string::npos;
        }
        for (const auto& v : prose::find_value_markers(line)) {
            ++markers_;
            if (v.tol >= 0) ++hand_;
            std::fill(skip.begin() + static_cast<std::ptrdiff_t>(v.begin),
                      skip.begin() + static_cast<std::ptrdiff_t>(v.end), true);
        }
        for (std::size_t open; !in_comment && (open = line.find("<!--", from)) != std::string::npos;) {
            if (skip[open]) {
                from = open + 4;
                continue;
            }
            const auto close = line.find("-->", open + 4);
            const std::size_t end = close == std::string::npos ? line.size() : close + 3;
            std::fill(skip.begin() + static_cast<std::ptrdiff_t>(open), skip.begin() + static_cast<std::ptrdiff_t>(end),
                      true);
            in_comment = close == std::string::npos;
            from = end;
        }
        static const std::regex target(R"(\]\([^)]*\))");
        for (auto it = std::sregex_iterator(line.begin(), line.end(), target); it != std::sregex_iterator(); ++it)
            std::fill(skip.begin() + it->position(0), skip.begin() + it->position(0) + it->length(0), true);
        return skip;
    }

    // A section of the workbook named by its number (section 5.6, sections 6.1-6.3, §6.2; [P]'s
    // sections have no subsections) is the text of a link, which the book's render checks leads
    // to a real heading: a number alone would dangle when the sections move.
    void sections(const std::string& line, const std::vector<bool>& skip, const std::string& where) {
        static const std::regex link(R"(\[((?:[^\[\]]|\[[^\]]*\])*)\]\([^)]*\))");
        static const std::regex section(R"((?:[Ss]ections?|§)\s*[0-9]+\.[0-9]+)");
        static const std::regex number(R"(([0-9]+)\.([0-9]+))");
        std::vector<bool> in_link(line.size(), false);
        for (auto it = std::sregex_iterator(line.begin(), line.end(), link); it != std::sregex_iterator(); ++it) {
            std::fill(in_link.begin() + it->position(1), in_link.begin() + it->position(1) + it->length(1), true);
            // The heading it leads to has the number it names: #56-... for section 5.6.
            const std::string text = (*it)[1], whole = it->str();
            std::smatch m, n;
            if (!std::regex_search(text, m, section)) continue;
            const std::string ref = m.str();
            std::regex_search(ref, n, number);
            const std::string want = "#" + n[1].str() + n[2].str() + "-";
            if (whole.find(want) == std::string::npos)
                problems_.push_back(where + ": the link '" + whole + "' names " + ref +
                                    " but does not lead to its heading (#" + n[1].str() + n[2].str() + "-...)");
        }
        for (auto it = std::sregex_iterator(line.begin(), line.end(), section); it != std::sregex_iterator(); ++it) {
            const auto at = static_cast<std::size_t>(it->position(0));
            if (!skip[at] && !in_link[at])
                problems_.push_back(where + ": '" + it->str() + "' is not a link: write [" + it->str() +
                                    "](page.md#its-heading), which the "
                                    "book's render checks");
        }
    }

    void open_tag(const prose::NumberTag& t, const std::string& where, bool manual, Pending& pending) {
        stale(pending);
        if (!t.error.empty()) {
            problems_.push_back(where + ": " + t.error);
            return;
        }
        if (t.kind == "once" && !manual) {
            problems_.push_back(where +
                                ": <!--once--> (measured once, by hand) belongs in the manuals, never in a "
                                "chapter: make the number a value marker");
            return;
        }
        pending = {t.kind, where, t.count};
    }

    void stale(Pending& pending) {
        if (pending.left > 0)
            problems_.push_back(pending.where + ": the tag <!--" + pending.kind + "--> has " +
                                std::to_string(pending.left) +
                                " number(s) left to cover in its paragraph, and there are none (a stale tag)");
        pending = {};
    }

    fs::path root_;
    std::vector<std::string> problems_;
    std::map<std::string, int> kinds_;
    int files_ = 0, markers_ = 0, hand_ = 0, tagged_ = 0;
};

}  // namespace

int check_numbers(const fs::path& root) { return NumberLint(root).run(); }

}  // namespace snippets
