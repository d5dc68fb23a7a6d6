// The kit's gnuplot scripts and figures (figure.hpp): its own scripts filled by their names (the
// filling itself, and each way of getting it wrong, is tested with the support library:
// cmake/support/support_test.cpp), and a figure drawn, staged and published.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include "figure.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "kit.gp.hpp"

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
