// Likely mistakes, named (mistakes.hpp): the signature of a failure, the matching and what it says.
#include "mistakes.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "grading.hpp"

namespace m = grading::mistakes;

namespace {

const std::string kVector =
    "../../tests/rotation_test.cpp:44: CHECK( checks::max_abs_diff(check_a_, check_b_) <= check_tol_ ) failed\n"
    "  with values: 0.224027 <= 1e-15\n  expected\n  -1.68776\n  -5.20921\n   3.90881\n  actual\n  1.68776\n"
    "  -5.20921\n  0\n  max |diff| 3.9, tolerance 1e-15\n(40 checks failed in this test; the first is shown)";

std::vector<m::Outcome> hat(const std::string& message, const std::string& verdict = "fail") {
    return {{"rotation", "hat", "hat: a", verdict, false, message}, {"rotation", "hat", "hat: b", "pass", false, ""}};
}

m::Catalogue one(const std::vector<m::Outcome>& outcomes, const std::string& mistake) {
    m::Catalogue c;
    c.entries.push_back({"rotation", "hat", "rotation-1", mistake, m::signature_of(outcomes, "rotation", "hat")});
    return c;
}

}  // namespace

TEST_CASE("mistakes: a failure's signature keeps the grader's line and how the values are wrong, not the numbers") {
    const std::string h = m::how({"rotation", "hat", "t", "fail", false, kVector});
    CHECK(h.find("rotation_test.cpp:44:") != std::string::npos);
    CHECK(h.find("values -.0") != std::string::npos);  // negated, right, zero
    CHECK(h.find("more than one check") != std::string::npos);
    CHECK(h.find("0.224027") == std::string::npos);
    std::string other_inputs = kVector;
    other_inputs.replace(other_inputs.find("0.224027"), 8, "7.5");
    other_inputs.replace(other_inputs.find("(40"), 3, "(39");
    CHECK(m::how({"rotation", "hat", "t", "fail", false, other_inputs}) == h);
    CHECK(m::how({"rotation", "hat", "t", "fail", false, "expected 1e-14, actual 0, |diff| 1e-14"}) ==
          "fail: expected #, actual #, |diff| # | values 0 | one check");
}

TEST_CASE("mistakes: a crash, a timeout, a build error or a stub is never matched") {
    for (const char* verdict : {"crash", "timeout", "build error", "missing"})
        CHECK(m::signature_of(hat(kVector, verdict), "rotation", "hat").empty());
    auto stub = hat(kVector);
    stub[0].not_started = true;
    CHECK(m::signature_of(stub, "rotation", "hat").empty());
    CHECK(m::signature_of(hat("", "pass"), "rotation", "hat").empty());  // passing: nothing to name
}

TEST_CASE("mistakes: a matching failure is named as a likely pattern, every mistake that gives it") {
    auto c = one(hat(kVector), "in hat: a minus sign dropped");
    auto named = m::name(c, hat(kVector));
    REQUIRE(named.size() == 1);
    CHECK(named[0].text().find("This pattern of failures is what this mistake gives") == 0);
    CHECK(named[0].text().find("likely, not certain") != std::string::npos);
    c.entries.push_back(c.entries[0]);
    c.entries.back().mistake = "in hat: a constant off (one too many, or twice what it should be)";
    named = m::name(c, hat(kVector));
    REQUIRE(named.size() == 1);
    CHECK(named[0].mistakes.size() == 2);
    CHECK(named[0].text().find("; or ") != std::string::npos);
    std::string elsewhere = kVector;
    elsewhere.replace(elsewhere.find(":44:"), 4, ":45:");
    CHECK(m::name(c, hat(elsewhere)).empty());  // another check failed
    CHECK(m::name(c, hat("the test did not finish")).empty());
    // hat's reference calls vee (say): while vee fails, hat's failures may be vee's, so none is named
    c.uses["rotation/hat"] = {"vee"};
    auto with_vee = hat(kVector);
    with_vee.push_back({"rotation", "vee", "vee: a", "pass", false, ""});
    CHECK(m::name(c, with_vee).size() == 1);
    with_vee.back().verdict = "fail";
    CHECK(m::name(c, with_vee).empty());
}

TEST_CASE("mistakes: the class count reads each result's likely mistakes") {
    const std::string dir = "mistakes-test-results";
    grading::remove_tree(dir);
    grading::make_dirs(dir);
    const std::string result =
        R"({"extra_data": {"likely_mistakes": [{"topic": "rotation", "exercise": "hat", "mistakes": ["a", "b"]}]}})";
    grading::write_file(dir + "/s1.json", result);
    grading::write_file(dir + "/s2.json", result);
    grading::write_file(dir + "/s3.json", R"({"extra_data": {}})");
    const auto counts = m::count_in_class(dir);
    REQUIRE(counts.size() == 2);
    CHECK(counts[0].students == 2);
    CHECK(counts[0].exercise == "hat");
    grading::remove_tree(dir);
}
