// The keys a user types, read once (catalog.hpp).
#include "catalog.hpp"

#include <nlohmann/json.hpp>
#include <regex>

#include "support/file.hpp"

namespace grading {

namespace {

// The names of the todo("<name>") calls of a stub, in order, each once.
std::vector<std::string> todo_names(const std::string& text) {
    static const std::regex todo(R"re(todo\("([A-Za-z_][A-Za-z0-9_]*)"\))re");
    std::vector<std::string> names;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), todo); it != std::sregex_iterator(); ++it) {
        const std::string name = (*it)[1];
        bool seen = false;
        for (const auto& n : names) seen = seen || n == name;
        if (!seen) names.push_back(name);
    }
    return names;
}

// The chapters of the table of contents, as CMake read it (<build>/contents.json).
std::string read_chapters(const std::string& path, Catalog& catalog) {
    bool ok = false;
    const std::string text = support::read_file(path, &ok);
    if (!ok) return "cannot read the table of contents " + path + ": configure the build folder again";
    const nlohmann::json toc = nlohmann::json::parse(text, nullptr, false);
    if (!toc.is_object() || !toc.contains("chapters") || !toc["chapters"].is_array())
        return path + ": not the table of contents CMake writes ({\"chapters\": [...]})";
    for (const auto& c : toc["chapters"])
        catalog.chapters.push_back(
            {c.value("label", ""), c.value("number", 0), c.value("folder", ""), c.value("title", "")});
    return {};
}

// The error for a key that names nothing: every chapter, and every topic with its exercises.
std::string unknown_key(const Catalog& catalog, const std::string& key) {
    std::string text = "'" + key + "' is not a chapter, topic or exercise.\nChapters:";
    for (const auto& c : catalog.chapters) text += " " + std::to_string(c.number);
    if (!catalog.chapters.empty()) {
        const CatalogChapter& c = catalog.chapters.front();
        text += " (Chapter " + std::to_string(c.number) + " is also " + c.label + " or " + c.folder + ")";
    }
    text += "\nTopics (exercises/<topic>.cpp) and their exercises:";
    for (const auto& t : catalog.topics) text += "\n  " + t.name + ": " + joined(t.exercises, " ");
    return text;
}

}  // namespace

std::string load_catalog(const std::string& path, Catalog& catalog) {
    catalog = Catalog{};
    bool ok = false;
    const std::string text = support::read_file(path, &ok);
    if (!ok) return "cannot read " + path + ": configure the build folder (cmake -S . -B <build>) first";
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (!j.is_object() || !j.contains("topics") || !j["topics"].is_array())
        return path + ": not the catalogue CMake writes ({\"topics\": [...]})";
    catalog.root = j.value("root", "");
    if (auto problem = read_chapters(j.value("contents", ""), catalog); !problem.empty()) return problem;
    for (const auto& t : j["topics"]) {
        CatalogTopic topic{
            t.value("name", ""), t.value("chapter", ""), t.value("stub", ""), t.value("stub_from_git", true), {}};
        const std::string stub = support::read_file(topic.stub, &ok);
        if (!ok) return "cannot read the stub as committed " + topic.stub + ": configure the build folder again";
        topic.exercises = todo_names(stub);
        catalog.topics.push_back(topic);
    }
    return {};
}

const CatalogChapter* chapter_of_key(const Catalog& catalog, const std::string& key) {
    for (const auto& c : catalog.chapters) {
        const std::string n = std::to_string(c.number);
        if (key == c.label || key == c.folder || key == n || (key.size() == 2 && key == "0" + n)) return &c;
    }
    return nullptr;
}

std::string select_key(const Catalog& catalog, const std::string& key, KeySelection& selection) {
    selection = KeySelection{};
    if (const CatalogChapter* c = chapter_of_key(catalog, key)) {
        for (const auto& t : catalog.topics)
            if (t.chapter == c->label) selection.topics.push_back(t.name);
        selection.what = "Chapter " + std::to_string(c->number);
        if (selection.topics.empty()) return "Chapter " + std::to_string(c->number) + " has no exercises";
        return {};
    }
    for (const auto& t : catalog.topics) {
        if (t.name == key) {
            selection.topics = {t.name};
            selection.what = "exercises/" + t.name + ".cpp";
            return {};
        }
        for (const auto& e : t.exercises)
            if (e == key) {
                selection.topics = {t.name};
                selection.exercise = e;
                selection.what = "the exercise " + e;
                return {};
            }
    }
    return unknown_key(catalog, key);
}

bool started(const CatalogTopic& topic, const std::string& folder) {
    if (!topic.stub_from_git) return true;
    bool ok = false;
    const std::string mine = support::read_file(folder + "/" + topic.name + ".cpp", &ok);
    return !ok || mine != support::read_file(topic.stub);
}

std::string joined(const std::vector<std::string>& names, const std::string& separator) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : separator) + n;
    return out;
}

std::string cmake_list(const std::vector<std::string>& names) { return joined(names, ";"); }

}  // namespace grading
