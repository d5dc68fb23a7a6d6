// The item analysis on planted classes whose answers are known (item_analysis.hpp): the thirds and
// their ties, the discrimination of a test only the strong pass (1), only the weak pass (-1) and
// everyone passes (0), classes too small or too even to rank, the verdict counts, the most common
// failing check in both forms a message takes (as graded, and flattened by the results .tsv), and
// when an exercise counts as started.
#include "item_analysis.hpp"

#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/process.hpp"

using grading::Verdict;

namespace {

// A setup of one topic "t" (chapter ch01) with one exercise "e" of the given tests; its stub in a
// folder of its own (setup.root/exercises/t.cpp).
grading::Setup one_topic(const std::vector<std::string>& tests) {
    grading::Setup setup;
    setup.root = (std::filesystem::temp_directory_path() / ("item_analysis_" + std::to_string(::getpid()))).string();
    setup.build = setup.root + "/build";
    std::filesystem::create_directories(setup.root + "/exercises");
    grading::write_file(setup.root + "/exercises/t.cpp", "double e(double x) { return todo(\"e\"); }\n");
    grading::Topic topic;
    topic.name = "t", topic.chapter = "ch01";
    grading::Exercise e{"e", 1, {}};
    for (const auto& name : tests) e.tests.push_back({name, 1, 0});
    topic.exercises.push_back(e);
    setup.topics.push_back(topic);
    return setup;
}

grading::TestResult test(const std::string& name, Verdict v, const std::string& message = "",
                         bool not_started = false) {
    return {"ch01", "t", "e", name, v, 0, 1, not_started, message, ""};
}

// A class whose totals are 9, 8, ..., 1: test "a" passed by the top three, "b" by the bottom
// three, "c" by everyone.
std::vector<grading::SubmissionResult> ranked_class() {
    std::vector<grading::SubmissionResult> results;
    for (int k = 0; k < 9; ++k) {
        grading::SubmissionResult r;
        r.student = "s" + std::to_string(k);
        r.score = 9 - k;
        r.tests = {test("e: a", k < 3 ? Verdict::pass : Verdict::fail),
                   test("e: b", k >= 6 ? Verdict::pass : Verdict::fail), test("e: c", Verdict::pass)};
        results.push_back(r);
    }
    return results;
}

}  // namespace

TEST_CASE("item analysis: the thirds share their boundary among tied students") {
    CHECK(grading::third_weights({9, 8, 7, 6, 5, 4, 3, 2, 1}, true) == std::vector<double>{1, 1, 1, 0, 0, 0, 0, 0, 0});
    CHECK(grading::third_weights({9, 8, 7, 6, 5, 4, 3, 2, 1}, false) == std::vector<double>{0, 0, 0, 0, 0, 0, 1, 1, 1});
    // Four tied at the top for three places: 3/4 each; five tied at the bottom: 3/5 each.
    CHECK(grading::third_weights({3, 3, 3, 3, 0, 0, 0, 0, 0}, true) ==
          std::vector<double>{0.75, 0.75, 0.75, 0.75, 0, 0, 0, 0, 0});
    const auto bottom = grading::third_weights({3, 3, 3, 3, 0, 0, 0, 0, 0}, false);
    for (int k = 4; k < 9; ++k) CHECK(bottom[static_cast<std::size_t>(k)] == doctest::Approx(0.6));
    // Ten students: each third is 10/3 students' worth.
    double sum = 0;
    for (const double w : grading::third_weights({10, 9, 8, 7, 6, 5, 4, 3, 2, 1}, true)) sum += w;
    CHECK(sum == doctest::Approx(10.0 / 3));
}

TEST_CASE("item analysis: a planted class gives the discrimination it was made with") {
    const auto setup = one_topic({"e: a", "e: b", "e: c"});
    const auto results = ranked_class();
    const auto a = grading::analyse_items(setup, results, {});
    REQUIRE(a.tests.size() == 3);
    CHECK(a.ranking.empty());
    CHECK(*a.tests[0].discrimination == doctest::Approx(1));
    CHECK(*a.tests[1].discrimination == doctest::Approx(-1));
    CHECK(*a.tests[2].discrimination == doctest::Approx(0));
    CHECK(a.tests[0].counts[0] == 3);  // pass
    CHECK(a.tests[0].counts[1] == 6);  // fail
    CHECK(a.exercises[0].passed == 0);
    // Planted faults: the rows the analysis must tell apart.
    CHECK(grading::item_analysis_csv(a).find(",3,6,0,0,0,0,0,0.33,1.0000,0.0000,1.0000,") != std::string::npos);
    std::filesystem::remove_all(setup.root);
}

TEST_CASE("item analysis: no discrimination below 6 submissions or when every total is the same") {
    const auto setup = one_topic({"e: a", "e: b", "e: c"});
    auto results = ranked_class();
    results.resize(5);
    CHECK(grading::analyse_items(setup, results, {}).ranking.find("fewer than 6") != std::string::npos);
    CHECK(!grading::analyse_items(setup, results, {}).tests[0].discrimination);
    results = ranked_class();
    for (auto& r : results) r.score = 2;
    const auto a = grading::analyse_items(setup, results, {});
    CHECK(a.ranking.find("same total") != std::string::npos);
    CHECK(grading::item_analysis_csv(a).find(",n/a,") != std::string::npos);
    std::filesystem::remove_all(setup.root);
}

TEST_CASE("item analysis: the failing check and its value, as graded and as the .tsv flattens them") {
    const std::string graded =
        "tests/t_test.cpp:12: CHECK( e(1) == doctest::Approx(2) ) failed\n  with values: 3.0 == Approx( 2.0 )\n"
        "  this test also uses your f";
    const std::string flat =
        "tests/t_test.cpp:12: CHECK( e(1) == doctest::Approx(2) ) failed   with values: 3.0 == "
        "Approx( 2.0 )   this test also uses your f";
    for (const auto& m : {graded, flat}) {
        CHECK(grading::failing_check(m) == "tests/t_test.cpp:12: CHECK( e(1) == doctest::Approx(2) ) failed");
        CHECK(grading::check_values(m) == "3.0 == Approx( 2.0 )");
    }
    CHECK(grading::failing_check("threw an exception: bad   this test also uses your f") == "threw an exception: bad");
    CHECK(grading::check_values("threw an exception: bad") == "");
}

TEST_CASE("item analysis: counts every verdict once, and names the most common failing check") {
    const auto setup = one_topic({"e: a"});
    const std::string one = "x.cpp:1: CHECK( a ) failed\n  with values: ",
                      two = "x.cpp:2: CHECK( b ) failed\n  with values: ";
    const std::vector<std::pair<Verdict, std::string>> verdicts = {{Verdict::fail, two + "7"},
                                                                   {Verdict::fail, one + "5"},
                                                                   {Verdict::fail, one + "6"},
                                                                   {Verdict::fail, one + "6"},
                                                                   {Verdict::crash, "crashed with SIGSEGV"},
                                                                   {Verdict::timeout, "timed out"},
                                                                   {Verdict::build_error, "error"},
                                                                   {Verdict::missing, "missing"},
                                                                   {Verdict::pass, ""}};
    std::vector<grading::SubmissionResult> results;
    for (const auto& [v, m] : verdicts) {
        grading::SubmissionResult r;
        r.score = static_cast<double>(results.size());
        r.tests = {test("e: a", v, m)};
        results.push_back(r);
    }
    results.push_back(results.back());
    results.back().tests = {test("e: a", Verdict::fail, "not started: todo(\"e\") is still in place", true)};
    const auto a = grading::analyse_items(setup, results, {});
    const auto& row = a.tests.at(0);
    CHECK(row.results == 10);
    CHECK(row.counts == std::array<int, 7>{1, 4, 1, 1, 1, 1, 1});
    CHECK(row.check == "x.cpp:1: CHECK( a ) failed");
    CHECK(row.check_count == 3);
    CHECK(row.typical == "6");
    std::filesystem::remove_all(setup.root);
}

TEST_CASE("item analysis: an exercise is started when its file differs from the stub and its todo is gone") {
    const auto setup = one_topic({"e: a"});
    const std::string stub = grading::read_file(setup.root + "/exercises/t.cpp");
    auto with = [](const std::string& content, const std::string& state = "ok") {
        return grading::ClassFiles{"s", {{"t", state, "", content}}};
    };
    const auto run = [&](const grading::ClassFiles& files, const grading::TestResult& t) {
        grading::SubmissionResult r;
        r.tests = {t};
        return grading::analyse_items(setup, {r}, {files}).exercises.at(0).started;
    };
    CHECK(run(with(stub), test("e: a", Verdict::fail, "", true)) == 0);                            // the stub
    CHECK(run(with("  " + stub + "\n\n"), test("e: a", Verdict::fail, "", true)) == 0);            // re-spaced
    CHECK(run(with(stub + "// notes\n"), test("e: a", Verdict::fail, "", true)) == 0);             // todo reached
    CHECK(run(with("double e(double x) { return x; }"), test("e: a", Verdict::fail, "m")) == 1);   // written
    CHECK(run(with("double e(double x) { return x }"), test("e: a", Verdict::build_error)) == 1);  // no build, no todo
    CHECK(run(with(stub + "int f( {"), test("e: a", Verdict::build_error)) == 0);  // its todo still there
    CHECK(run(with("", "missing"), test("e: a", Verdict::missing)) == 0);
    std::filesystem::remove_all(setup.root);
}

TEST_CASE("item analysis: the class report draws its plots with gnuplot, and without it says so and keeps the tables") {
    const auto setup = one_topic({"e: a", "e: b", "e: c"});
    const std::string out = setup.root + "/out";
    std::filesystem::create_directories(out);
    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    ::setenv("PATH", (setup.root + "/no-programs-here").c_str(), 1);
    const std::string line = grading::write_item_analysis(setup, ranked_class(), {}, out);
    ::setenv("PATH", path.c_str(), 1);
    CHECK(line.find("no plots: gnuplot could not start") != std::string::npos);
    std::string page = grading::read_file(out + "/class_report.html");
    CHECK(page.find("No plots: gnuplot could not start") != std::string::npos);
    CHECK(page.find("<img") == std::string::npos);
    CHECK(page.find("<td>e: a</td>") != std::string::npos);
    CHECK(grading::read_file(out + "/item_analysis.csv").find("e: c") != std::string::npos);
    if (support::run({"gnuplot", "--version"}).status == 0) {
        CHECK(grading::write_item_analysis(setup, ranked_class(), {}, out).find("no plots") == std::string::npos);
        page = grading::read_file(out + "/class_report.html");
        for (const std::string svg : {"totals", "exercises", "tests_t"}) {
            CHECK(page.find("src=\"report/" + svg + ".svg\"") != std::string::npos);
            CHECK(grading::read_file(out + "/report/" + svg + ".svg").find("<svg") != std::string::npos);
            CHECK(grading::read_file(out + "/report/" + svg + ".gp").find(out) == std::string::npos);  // no path
        }
    }
    std::filesystem::remove_all(setup.root);
}
