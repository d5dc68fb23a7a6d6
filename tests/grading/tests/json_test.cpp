// The JSON the tools and the grading run write and read (nlohmann-json) keeps every character:
// a `\u` escape outside the Basic Multilingual Plane (a surrogate pair) reads as its UTF-8, UTF-8
// written out reads back the same, and invalid UTF-8 in a student's output becomes U+FFFD.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "grading.hpp"
#include "prose.hpp"

namespace {

const std::string grinning = "\xF0\x9F\x98\x80";  // U+1F600, outside the BMP: \ud83d\ude00
const std::string omega = "\xCE\xA9";             // U+03A9, inside it

grading::SubmissionResult one_result(const std::string& student, const std::string& output) {
    grading::SubmissionResult r;
    r.student = student;
    r.tests.push_back(
        {"ch01", "rotation", "hat", "hat: is skew", grading::Verdict::fail, 0, 1, false, "expected", output});
    return r;
}

}  // namespace

TEST_CASE("json: a surrogate pair escape reads as the character outside the BMP") {
    const auto file =
        std::filesystem::temp_directory_path() / ("workbook_json_test_" + std::to_string(::getpid()) + ".json");
    prose::write_text(file, R"({"run": {"name": "default", "args": []}, "label": "\ud83d\ude00 \u03a9"})");
    const auto j = prose::read_json(file);
    std::filesystem::remove(file);
    CHECK(j["label"].get<std::string>() == grinning + " " + omega);
}

TEST_CASE("json: results.json keeps UTF-8 outside the BMP and reads back the same") {
    const grading::Setup setup;
    const std::string text = grading::results_json(setup, one_result(grinning + " " + omega, "said " + grinning));
    const auto j = nlohmann::json::parse(text);
    CHECK(j["extra_data"]["student"].get<std::string>() == grinning + " " + omega);
    CHECK(j["tests"][0]["output"].get<std::string>().find("said " + grinning) != std::string::npos);
    // An escaped pair, as another writer may send it, means the same string.
    CHECK(nlohmann::json::parse(R"("\ud83d\ude00")").get<std::string>() == grinning);
    CHECK(nlohmann::json::parse(nlohmann::json(grinning).dump(-1, ' ', true)).get<std::string>() == grinning);
}

TEST_CASE("json: invalid UTF-8 in a student's output becomes U+FFFD, not an exception") {
    const grading::Setup setup;
    const std::string text = grading::results_json(setup, one_result("s", std::string("bad \xFF byte")));
    const auto j = nlohmann::json::parse(text);
    CHECK(j["tests"][0]["output"].get<std::string>().find("bad \xEF\xBF\xBD byte") != std::string::npos);
}

TEST_CASE("json: every verdict reads back from results .tsv as written, and a word that names none is refused") {
    grading::SubmissionResult r = one_result("s", "");
    r.fingerprint = "f";
    r.tests.clear();
    for (const grading::Verdict v : grading::test_verdicts)
        r.tests.push_back({"ch01", "rotation", "hat", "hat: " + grading::to_string(v), v, 0, 1, false, "m", ""});
    const auto file =
        std::filesystem::temp_directory_path() / ("workbook_verdict_test_" + std::to_string(::getpid()) + ".tsv");
    const std::string tsv = grading::results_tsv(r);
    REQUIRE(grading::write_file(file.string(), tsv));
    grading::SubmissionResult back;
    REQUIRE(grading::read_results_tsv(file.string(), back));
    REQUIRE(back.tests.size() == grading::test_verdicts.size());
    for (std::size_t k = 0; k < back.tests.size(); ++k) CHECK(back.tests[k].verdict == grading::test_verdicts[k]);
    CHECK(tsv.find("\tbuild error\t") != std::string::npos);  // the words of the files, unchanged
    CHECK(tsv.find("\tbuild_error\t") == std::string::npos);
    REQUIRE(grading::write_file(file.string(), grading::replace_all(tsv, "\tcrash\t", "\tcrashed\t")));
    CHECK_FALSE(grading::read_results_tsv(file.string(), back));
    std::filesystem::remove(file);
    grading::Verdict v = grading::Verdict::pass;
    CHECK(grading::from_string("not started", v));
    CHECK(v == grading::Verdict::not_started);
    CHECK_FALSE(grading::from_string("Pass", v));
}
