// The kit's gnuplot scripts (figure.hpp): placeholders filled, and each way of filling them
// wrong planted, so that a script never reaches gnuplot half filled.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include "figure.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "kit.gp.hpp"

TEST_CASE("a placeholder is replaced by its value, gnuplot's own braces and brackets stay") {
    const kit::Script s{"t.gp", "set title '@title@'\nset xrange [0:*]\nset ylabel '{/:Bold a}'\nplot @plot@\n"};
    CHECK(kit::filled(s, {{"plot", "'-' with lines"}, {"title", "n = 3"}}) ==
          "set title 'n = 3'\nset xrange [0:*]\nset ylabel '{/:Bold a}'\nplot '-' with lines\n");
}

TEST_CASE("a value is inserted as it is, never scanned for placeholders again") {
    const kit::Script s{"t.gp", "@a@ @b@"};
    CHECK(kit::filled(s, {{"a", "@b@"}, {"b", "x"}}) == "@b@ x");
}

TEST_CASE("an '@' that opens no placeholder (a gnuplot macro, an address) stays") {
    const kit::Script s{"t.gp", "@macro plot\nmail a@b.c\n@1@ @@\n"};
    CHECK(kit::filled(s) == "@macro plot\nmail a@b.c\n@1@ @@\n");
}

TEST_CASE("a comment line may name a placeholder: it stays as it is, and needs no value") {
    const kit::Script s{"t.gp", "# @curves@: one per method\n  # @x@\nplot @curves@\n#"};
    CHECK(kit::filled(s, {{"curves", "'-'"}}) == "# @curves@: one per method\n  # @x@\nplot '-'\n#");
}

TEST_CASE("a placeholder left without a value throws, naming the script and the placeholder") {
    const kit::Script s{"planted.gp", "set title '@title@'\nset xlabel '@xlabel@'\n"};
    CHECK_THROWS_WITH_AS(kit::filled(s, {{"title", "x"}}), doctest::Contains("planted.gp"), std::logic_error);
    CHECK_THROWS_WITH_AS(kit::filled(s, {{"title", "x"}}), doctest::Contains("@xlabel@"), std::logic_error);
}

TEST_CASE("a value for a placeholder the script does not have throws (a misspelt name)") {
    const kit::Script s{"planted.gp", "set title '@title@'\n"};
    CHECK_THROWS_WITH_AS(kit::filled(s, {{"title", "x"}, {"titel", "y"}}), doctest::Contains("@titel@"),
                         std::logic_error);
}

TEST_CASE("the kit's embedded scripts: the style has none, the GIF's are filled by their names") {
    CHECK(kit::gp::style.name == "style.gp");
    CHECK(kit::filled(kit::gp::style).find("set style line 1 ") != std::string::npos);
    CHECK_NOTHROW(kit::filled(kit::gp::motion_gif_frame, {{"t", "0.00"}, {"curves", "'-' with lines ls 101"}}));
    CHECK_THROWS_AS(kit::filled(kit::gp::motion_gif_frame, {{"t", "0.00"}}), std::logic_error);
}

namespace {

// A scene with --out in a fresh folder, as kit::run would make it.
struct TestScene {
    std::string dir;
    kit::Options opts{"figure_test", "kit::Figure's own test"};
    std::unique_ptr<kit::Scene> scene;
    explicit TestScene(const std::string& name) : dir("figure_test_" + name) {
        std::filesystem::remove_all(dir);
        std::vector<std::string> args{"figure_test", "--out", dir};
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        REQUIRE(opts.parse(static_cast<int>(argv.size()), argv.data()));
        scene = std::make_unique<kit::Scene>(opts);
    }
    ~TestScene() { std::filesystem::remove_all(dir); }
    std::size_t files() const {
        std::size_t n = 0;
        for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
        return n;
    }
};

}  // namespace

TEST_CASE("a figure is drawn from its filled script and waits, staged, until the scene succeeds") {
    TestScene t("drawn");
    kit::Figure fig(*t.scene, "x.svg", 320, 200);
    fig.script({"t.gp", "set title '@title@'\nplot '-' with lines\n"}, {{"title", "α = 1"}});
    fig.data({{0, 1}, {1, 2}});
    CHECK(fig.finish() > 0);
    CHECK(t.files() == 1);  // the staged figure alone: no script, no log left
    t.scene->publish_figures();
    CHECK(std::filesystem::exists(t.dir + "/x.svg"));
}

TEST_CASE("a gnuplot error (planted) fails the figure with gnuplot's message, and leaves no file") {
    TestScene t("planted");
    kit::Figure fig(*t.scene, "x.svg", 320, 200);
    fig << "plot '-' with no_such_style\n";
    fig.data({{0, 1}});
    CHECK_THROWS_WITH_AS(fig.finish(), doctest::Contains("gnuplot reported an error"), kit::NumericalFailure);
    CHECK(t.files() == 0);
}
