// workbook_topics: what a key the user typed means, for the front door (cmake/workbook), which
// asks before it builds anything: which graders `check` builds, which chapter `scenes` runs and
// which topics come from the student's exercises/, which topics `gradescope` packs. The grammar
// is catalog.hpp's, the same that `workbook_grade check` reads. It builds in seconds, with no
// grader. Each command writes its answer into --out (one line, for the front door to pass on as
// it is) and says what it found on the terminal.
//
//   workbook_topics check --catalog <build>/grading/catalog.json --out <file> [--folder <exercises>] [KEY]
//       the topics KEY names (a chapter, a topic or an exercise), or, with no KEY, those started;
//       exit 1 when nothing is started, 2 when KEY names nothing
//   workbook_topics scenes --catalog <file> --out <file> [--folder <exercises>] CHAPTER
//       "<NN>\t<chapter folder>\t<topics started>"; exit 2 when CHAPTER is not a chapter
//   workbook_topics topics --catalog <file> --out <file> [TOPIC...]
//       the topics given, each checked to have graders (none given: every topic with graders)
//   workbook_topics exercises --catalog <file>
//       "<topic>\t<exercise>" per line: what the stubs as committed name (a test compares the manifest)
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "catalog.hpp"
#include "support/file.hpp"

using namespace grading;

namespace {

struct Command {
    std::string catalog, out, folder;
    std::vector<std::string> keys;
};

int fail(const std::string& message) {
    std::fprintf(stderr, "cmake/workbook: %s\n", message.c_str());
    return 2;
}

bool answer(const Command& c, const std::string& line) {
    if (support::write_file(c.out, line + "\n")) return true;
    fail("cannot write " + c.out);
    return false;
}

std::string folder_of(const Catalog& catalog, const Command& c) {
    return c.folder.empty() ? catalog.root + "/exercises" : c.folder;
}

// check with no key: the topics started, or how to start.
int check_started(const Catalog& catalog, const Command& c) {
    std::vector<std::string> own, untouched;
    for (const auto& t : catalog.topics) (started(t, folder_of(catalog, c)) ? own : untouched).push_back(t.name);
    if (own.empty()) {
        std::printf("\033[1m== Nothing started yet: every exercises/*.cpp is still the stub as committed\033[0m\n");
        for (const auto& t : catalog.topics) {
            const CatalogChapter* ch = chapter_of_key(catalog, t.chapter);
            std::printf("  Chapter %d: exercises/%s.cpp, %zu exercises not started\n", ch ? ch->number : 0,
                        t.name.c_str(), t.exercises.size());
        }
        std::printf("\nStart with Chapter 1 (exercises/rotation.cpp); cmake/workbook check 1 grades it at any time.\n");
        return 1;
    }
    if (!untouched.empty()) {
        std::printf("Not started (still the stub as committed, not graded): %s\n", joined(untouched, " ").c_str());
    }
    return answer(c, cmake_list(own)) ? 0 : 2;
}

int check(const Catalog& catalog, const Command& c) {
    if (c.keys.size() > 1) return fail("check takes at most one chapter, topic or exercise");
    if (c.keys.empty()) return check_started(catalog, c);
    KeySelection selection;
    if (auto problem = select_key(catalog, c.keys[0], selection); !problem.empty()) return fail(problem);
    return answer(c, cmake_list(selection.topics)) ? 0 : 2;
}

int scenes(const Catalog& catalog, const Command& c) {
    if (c.keys.size() != 1) return fail("usage: cmake/workbook scenes <chapter>");
    const CatalogChapter* chapter = chapter_of_key(catalog, c.keys[0]);
    if (!chapter) {
        std::vector<std::string> known;
        for (const auto& ch : catalog.chapters) known.push_back(std::to_string(ch.number));
        return fail("'" + c.keys[0] + "' is not a chapter (" + joined(known, " ") + ")");
    }
    // Which topics come from where, both lists in full: the scenes build from exactly these.
    std::vector<std::string> own, reference;
    for (const auto& t : catalog.topics) (started(t, folder_of(catalog, c)) ? own : reference).push_back(t.name);
    if (own.empty()) {
        std::printf("\033[1m== No exercises/*.cpp started yet: the scenes run on the reference solutions\033[0m\n");
    } else if (reference.empty()) {
        std::printf("\033[1m== Your code: %s (exercises/); every topic is yours\033[0m\n", joined(own, " ").c_str());
    } else {
        std::printf("\033[1m== Your code: %s (exercises/); from solutions/: %s\033[0m\n", joined(own, " ").c_str(),
                    joined(reference, " ").c_str());
    }
    const std::string nn = (chapter->number < 10 ? "0" : "") + std::to_string(chapter->number);
    return answer(c, nn + "\t" + chapter->folder + "\t" + cmake_list(own)) ? 0 : 2;
}

int topics(const Catalog& catalog, const Command& c) {
    std::vector<std::string> known;
    for (const auto& t : catalog.topics) known.push_back(t.name);
    for (const auto& key : c.keys)
        if (std::find(known.begin(), known.end(), key) == known.end())
            return fail("'" + key + "' is not a topic with graders (they are: " + joined(known, " ") + ")");
    return answer(c, cmake_list(c.keys.empty() ? known : c.keys)) ? 0 : 2;
}

int exercises(const Catalog& catalog) {
    for (const auto& t : catalog.topics)
        for (const auto& e : t.exercises) std::printf("%s\t%s\n", t.name.c_str(), e.c_str());
    return 0;
}

CLI::App* subcommand(CLI::App& app, const std::string& name, const std::string& what, Command& c, bool out) {
    CLI::App* sub = app.add_subcommand(name, what);
    sub->add_option("--catalog", c.catalog, "<build>/grading/catalog.json")->required();
    if (out) sub->add_option("--out", c.out, "the file the answer is written to")->required();
    return sub;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"workbook_topics: what a chapter, topic or exercise named on the command line means"};
    app.require_subcommand(1);
    Command c;
    CLI::App* check_command = subcommand(app, "check", "the topics `cmake/workbook check [KEY]` grades", c, true);
    CLI::App* scenes_command = subcommand(app, "scenes", "the chapter and the student's topics of `scenes`", c, true);
    CLI::App* topics_command = subcommand(app, "topics", "topics with graders (`gradescope`)", c, true);
    subcommand(app, "exercises", "every topic's exercises, as the stubs name them", c, false);
    for (CLI::App* sub : {check_command, scenes_command})
        sub->add_option("--folder", c.folder, "the exercises/ folder");
    check_command->add_option("key", c.keys, "a chapter, topic or exercise");
    scenes_command->add_option("chapter", c.keys, "a chapter");
    topics_command->add_option("topic", c.keys, "topics");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help
        return fail(e.what());
    }
    Catalog catalog;
    if (auto problem = load_catalog(c.catalog, catalog); !problem.empty()) return fail(problem);
    if (check_command->parsed()) return check(catalog, c);
    if (scenes_command->parsed()) return scenes(catalog, c);
    if (topics_command->parsed()) return topics(catalog, c);
    return exercises(catalog);
}
