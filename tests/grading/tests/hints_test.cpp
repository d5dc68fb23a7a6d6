// The hint ladders' own tests (hints.hpp): the nudge rule catches planted code, the printer
// leaves no TeX, and the reader rejects a malformed file with a message naming the line.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include "hints.hpp"

#include <doctest/doctest.h>

namespace {
const char* good =
    "# Hints\n\nIntro text.\n\n## Chapter 1\n\nA chapter note.\n\n"
    "### hat\n\n#### Hint 1\nThe matrix $\\hat{w}$ is defined by $\\hat{w}\\,x = w \\times x$; see "
    "`rigid/rotation.hpp`.\n\n"
    "#### Hint 2\nPlace $w_1$, $w_2$, $w_3$.\n\n#### Hint 3\nCheck: $\\hat{w}\\,w = 0$ for every $w$.\n\n"
    "### vee\n\n#### Hint 1\nUse `hat` backwards: $\\Omega_k = -\\tfrac{1}{2}\\epsilon_{kij}W_{ij}$.\n\n"
    "#### Hint 2\nAverage the pair.\n";
}  // namespace

TEST_CASE("the reader finds every ladder and its levels") {
    const hints::Hints h = hints::parse(good, "hints.md");
    REQUIRE(h.error.empty());
    REQUIRE(h.ladders.size() == 2);
    CHECK(h.ladders[0].exercise == "hat");
    CHECK(h.ladders[0].levels.size() == 3);
    CHECK(h.ladders[1].levels.size() == 2);
    CHECK(h.ladders[1].levels[1] == "Average the pair.");
    for (const auto& l : h.ladders) CHECK(hints::lint(l, "hints.md").empty());
}

TEST_CASE("the reader rejects a malformed file with the line and the rule") {
    struct Case {
        const char* text;
        const char* message;
    };
    const Case cases[] = {
        {"### hat\n\n#### Hint 1\nA nudge.\n", "hints.md:4: the hints of 'hat' have 1 level(s); a ladder has 2 or 3"},
        {"### hat\nOld-style text.\n#### Hint 1\na\n#### Hint 2\nb\n",
         "hints.md:2: text before '#### Hint 1' in 'hat'"},
        {"### hat\n#### Hint 2\na\n", "hints.md:2: '#### Hint 2' in 'hat': expected #### Hint 1"},
        {"### hat\n#### Hint 1\na\n#### Hint 3\nb\n", "hints.md:4: '#### Hint 3' in 'hat': expected #### Hint 2"},
        {"### hat\n#### Hint 1\na\n#### Hint 2\nb\n#### Hint 3\nc\n#### Hint 4\nd\n",
         "hints.md:8: 'hat' has more than 3 levels"},
        {"### hat\n#### Hint 1\na\n#### Note\nb\n", "hints.md:4: '#### Note': the only level-4 headings are"},
        {"#### Hint 1\na\n", "hints.md:1: '#### Hint 1' outside an exercise's ### section"},
        {"### hat\n#### Hint 1\na\n#### Hint 2\n\n### vee\n", "hints.md:1: Hint 2 of 'hat' is empty"},
        {"### hat\n#### Hint 1\na\n#### Hint 2\nb\n### hat\n#### Hint 1\na\n#### Hint 2\nb\n",
         "hints.md:6: 'hat' has a second ### section"},
        {"### hat w\n", "hints.md:1: '### hat w' is not an exercise name"},
        {"### hat\n#### Hint 1\n```\ncode\n", "a code block (```) is not closed"},
    };
    for (const auto& c : cases) {
        const std::string text = c.text;
        CAPTURE(text);
        const hints::Hints h = hints::parse(c.text, "hints.md");
        CHECK(h.error.find(c.message) != std::string::npos);
        CAPTURE(h.error);
        CHECK(!h.error.empty());
    }
}

TEST_CASE("the terminal printer turns the TeX subset into plain text") {
    struct Case {
        const char* tex;
        const char* text;
    };
    const Case cases[] = {
        {"$\\Omega_k = -\\tfrac{1}{2}\\epsilon_{kij}W_{ij}$", "Ω_k = -½ε_kij W_ij"},
        {"$a \\cdot b$ and $a \\times b$", "a · b and a × b"},
        {"$R^\\top \\dot{R}$", "Rᵀ R\u0307"},
        {"$\\lVert\\alpha a + \\beta R^{a\\top} b\\rVert^2$", "‖α a + β Rᵃᵀ b‖²"},
        {"$\\sqrt{(C - B)(B - A)}/S$", "√((C - B)(B - A))/S"},
        {"$\\frac{a}{b}$, $\\tfrac{x^2}{720}$", "a/b, x²/720"},
        {"$\\sin\\varphi\\,\\mathbf{a}$", "sin φ a"},
        {"$\\cos\\tfrac{\\varphi}{2}$", "cos(φ/2)"},
        {"$\\theta \\le \\pi$, $x \\ge 0$, $a \\ne b$, $x \\approx y$, $\\pm 1$, $t \\to 0$",
         "θ ≤ π, x ≥ 0, a ≠ b, x ≈ y, ± 1, t → 0"},
        {"$\\langle a, b\\rangle$", "⟨a, b⟩"},
        {"$\\arccos x$, $J^{-1}$, $10^{-16}$", "arccos x, J⁻¹, 10⁻¹⁶"},
        {"$\\hat{J\\Omega}$", "hat(JΩ)"},
        {"**the left** and `a_b * c` stay", "the left and `a_b * c` stay"},
    };
    for (const auto& c : cases) {
        const std::string tex = c.tex;
        CAPTURE(tex);
        const std::string text = hints::plain_text(c.tex);
        CHECK(text == std::string(c.text) + "\n");
        CHECK(hints::tex_left(text).empty());
    }
    // What the printer does not know stays, and is reported.
    CHECK(hints::tex_left(hints::plain_text("$\\mathcal{L}$")).find("\\mathcal") != std::string::npos);
    CHECK(!hints::tex_left("a {brace}").empty());
    CHECK(hints::tex_left("code `{1, 2}` is code").empty());
}

TEST_CASE("the code rule finds code of the answer in a planted hint, at every rung") {
    const char* bad[] = {
        "Write the matrix with `W << 0, -w.z(), w.y(), ...;`.",
        "[P, (1.1.1)] is `vee` applied to `R.transpose() * R_dot`. That is all.",
        "It is simply vee(R.transpose() * R_dot).",
        "Just return the product.",
        "Use a `Mat3` and a `Vec3`.",
        "Compute `0.5 * Omega.dot(I.cwiseProduct(Omega))`.",
        "Solve with Eigen::LLT.",
        "```\nreturn vee(M);\n```",
        "    return vee(M);",
        "`(R.transpose() * R - Mat3::Identity()).norm()`",
        "`x.norm()`",
        "Check `defect <= tol`.",
    };
    for (const std::string text : bad) {
        CAPTURE(text);
        CHECK(!hints::code_in_nudge(text).empty());
    }
    const char* fine[] = {
        "[P, (1.1)]: a term along the identity, one along $a a^\\top$; use `rotation_about` and `rigid/require.hpp`.",
        "Throw `std::invalid_argument`; the grader looks for `hat:` tests.",
        "The angle between two rotations is the rotation angle of $R_1^\\top R_2$.",
        "Euler's equation $I\\dot{\\Omega} = (I\\Omega) \\times \\Omega$, solved for $\\dot{\\Omega}$ (see (6.7)).",
    };
    for (const std::string text : fine) {
        CAPTURE(text);
        CHECK(hints::code_in_nudge(text).empty());
    }
    // And lint() reports it against the ladder, naming the exercise and the level.
    const hints::Hints h = hints::parse(
        "### body_angular_velocity\n#### Hint 1\n`vee(R.transpose() * R_dot)`\n#### Hint 2\nb\n", "hints.md");
    REQUIRE(h.error.empty());
    const auto problems = hints::lint(h.ladders[0], "hints.md");
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].find("hints.md:1: body_angular_velocity, Hint 1 holds code of the answer") == 0);
    // Every rung: the last one too.
    const hints::Hints last = hints::parse(
        "### hat\n#### Hint 1\nThe cross product as a matrix.\n#### Hint 2\nIts diagonal is zero.\n"
        "#### Hint 3\n`m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;`\n",
        "hints.md");
    REQUIRE(last.error.empty());
    const auto top = hints::lint(last.ladders[0], "hints.md");
    REQUIRE(top.size() == 1);
    CHECK(top[0].find("hints.md:1: hat, Hint 3 holds code of the answer") == 0);
}

TEST_CASE("the terminal text of a level says how to get the next") {
    const hints::Hints h = hints::parse(good, "hints.md");
    REQUIRE(h.error.empty());
    const std::string one = hints::for_terminal(h.ladders[0], 1);
    CHECK(one.find("Hint 1 of 3 for hat") != std::string::npos);
    CHECK(one.find("cmake/workbook check hat --hint 2") != std::string::npos);
    CHECK(one.find("Place") == std::string::npos);  // not the next level
    CHECK(hints::for_terminal(h.ladders[0], 3).find("--hint") == std::string::npos);
    CHECK(hints::for_terminal(h.ladders[0], 4).empty());
    CHECK(hints::for_terminal(h.ladders[0], 0).empty());
}
