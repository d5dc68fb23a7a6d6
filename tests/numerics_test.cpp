// Graders for Chapter 7's geometric integrators (rigid/numerics.hpp). Each test cross-checks
// against something computed here without the student's functions: Eigen's AngleAxis for every
// rotation, central differences of the exponential, the closed form of dexp, the exact Grioli
// precession written out from [P, (4.5)-(4.11)], and the order of convergence.
#include "rigid/numerics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "checks.hpp"
#include "inputs.hpp"
#include "reference/quad_inertia.hpp"

using rigid::BodyState;
using rigid::HeavyTop;
using rigid::Increment;
using rigid::Mat3;
using rigid::Vec3;

// An increment in a failure message.
template <>
struct checks::Show<Increment> {
    static void to(std::ostream& s, const Increment& d) {
        show_fields(s, "dOmega", with_unit(d.dOmega, "rad/s"), "E", d.E);
    }
};

namespace {

using checks::Rot;
using checks::skew;

// exp(hat(w)), independent of the student's code.
Mat3 rot(const Vec3& w) { return w.norm() == 0 ? Mat3::Identity() : Rot(w, w.norm()); }

// The Grioli precession of the body diag(A, B, C), A < B < C, written out from [P, (4.5)-(4.11)]
// (the inertia frame at t = 0; z(0) = a): R(t) = R^b(alpha t) R^a(alpha t), b = e2.
struct Grioli {
    HeavyTop top;
    Vec3 a;
    double alpha;
    BodyState at(double t) const {
        const Mat3 Ra = Rot(a, alpha * t);
        return {alpha * (a + Ra.transpose() * Vec3::UnitY()), Rot(Vec3::UnitY(), alpha * t) * Ra};
    }
    double period() const { return 2 * std::acos(-1.0) / alpha; }
};

Grioli grioli(double A, double B, double C, double f) {
    const double S = std::sqrt((C - B) * (B - A) + (A + C - B) * (A + C - B));
    const Vec3 a(std::sqrt((B - A) / (C - A)), 0, -std::sqrt((C - B) / (C - A)));
    const Vec3 k = Vec3((C - B) * std::sqrt((B - A) / (C - A)), A + C - B, (B - A) * std::sqrt((C - B) / (C - A))) / S;
    return {{Vec3(A, B, C).asDiagonal().toDenseMatrix(), f, k, a}, a, std::sqrt(f / S)};
}

// Steps of size T / n from the start of the precession to T = one period; the largest of the
// angle between R and the exact R and of |Omega - Omega_exact| / alpha at the end.
template <class Step>
double error_after_one_period(const Grioli& g, int n, Step step) {
    const double T = g.period(), h = T / n;
    BodyState s = g.at(0);
    for (int i = 0; i < n; ++i) s = rigid::apply(s, step(s, h));
    const BodyState x = g.at(T);
    const Mat3 D = x.R.transpose() * s.R;
    const double angle = std::atan2(0.5 * (D - D.transpose()).norm() / std::sqrt(2.0), 0.5 * (D.trace() - 1));
    return std::max(angle, (s.Omega - x.Omega).norm() / g.alpha);
}

double vertical_momentum(const HeavyTop& top, const BodyState& s) { return top.k.dot(s.R * top.J * s.Omega); }

HeavyTop random_top() {
    // Principal moments obeying the triangle inequality, a random vertical and centre of mass.
    const double A = checks::uniform(1, 2), B = checks::uniform(1, 2),
                 C = checks::uniform(std::abs(A - B) + 0.2, A + B);
    return {Vec3(A, B, C).asDiagonal().toDenseMatrix(), checks::uniform(0.5, 2), checks::random_unit(),
            checks::random_unit()};
}

BodyState random_state() { return {checks::random_vector(1.5), checks::random_rotation(0.1, 3.0)}; }

}  // namespace

TEST_SUITE("ch07_numerics") {
    TEST_CASE("expm1_so3: is the rotation about w by |w| minus the identity") {
        for (int i = 0; i < 50; ++i) {
            const Vec3 u = checks::random_unit();
            INPUTS(u);
            const double phi = checks::uniform(1e-3, std::acos(-1.0));
            INPUTS(UNIT(phi, "rad"));
            INPUTS(UNIT(phi, "rad"));
            CHECK_MAT_NEAR(rigid::expm1_so3(phi * u), Rot(u, phi) - Mat3::Identity(), 2e-14);
        }
    }

    TEST_CASE("expm1_so3: keeps its digits for tiny angles") {
        // exp(hat w) - 1 = s hat(u) + c hat(u)^2 with s = sin phi and c = 1 - cos phi, here from
        // their Taylor series. Every entry must be right to a few ulp of the whole matrix, and the
        // diagonal, which holds c alone, to a few ulp of itself: 1 - cos(phi) formed as written has
        // no correct digit left at phi = 1e-8.
        for (double phi : {1e-2, 1e-4, 1e-6, 1e-8, 1e-12}) {
            INPUTS(UNIT(phi, "rad"));
            const Vec3 u = checks::random_unit();
            INPUTS(u);
            const double p2 = phi * phi;
            const double s = phi * (1 - p2 / 6 * (1 - p2 / 20 * (1 - p2 / 42)));
            const double c = p2 / 2 * (1 - p2 / 12 * (1 - p2 / 30 * (1 - p2 / 56)));
            const Mat3 U = skew(u), exact = s * U + c * U * U;
            const Mat3 E = rigid::expm1_so3(phi * u);
            CHECK_SMALL((E - exact).norm(), 4e-15 * exact.norm());
            CHECK_SMALL((E.diagonal() - exact.diagonal()).norm(), 4e-15 * exact.diagonal().norm());
        }
    }

    TEST_CASE("expm1_so3: is the zero matrix at w = 0 and finite near it") {
        {
            const Vec3 w = Vec3::Zero();
            INPUTS(w);
            CHECK_MAT_NEAR(rigid::expm1_so3(w), Mat3::Zero(), 0.0);
        }
        const Vec3 w(1e-300, -2e-300, 0);
        INPUTS(w);
        const Mat3 E = rigid::expm1_so3(w);
        CHECK(E.allFinite());
        CHECK_SMALL(E.cwiseAbs().maxCoeff(), 3e-300);
    }

    TEST_CASE("expm1_so3: one plus it is a rotation and w to -w transposes it") {
        for (int i = 0; i < 50; ++i) {
            const Vec3 w = checks::random_vector(3.0);
            INPUTS(UNIT(w, "rad"));
            const Mat3 E = rigid::expm1_so3(w);
            const Mat3 Q = Mat3::Identity() + E;
            CHECK_SMALL((Q.transpose() * Q - Mat3::Identity()).norm(), 4e-14);
            CHECK(Q.determinant() > 0);
            CHECK_MAT_NEAR(rigid::expm1_so3(-w), E.transpose(), 1e-14);
        }
    }

    TEST_CASE("dexpinv: inverts the derivative of exp measured by central differences") {
        // exp(u)^T d/de exp(u + e x) at e = 0 is hat(dexp_{-u}(x)), so dexpinv(-u, that) = x.
        for (int i = 0; i < 30; ++i) {
            const Vec3 u = checks::random_vector(2.0), x = checks::random_vector();
            INPUTS(u, x);
            const double e = 1e-5;
            const Mat3 D = rot(u).transpose() * (rot(u + e * x) - rot(u - e * x)) / (2 * e);
            const Vec3 y(D(2, 1) - D(1, 2), D(0, 2) - D(2, 0), D(1, 0) - D(0, 1));
            CHECK_MAT_NEAR(rigid::dexpinv(-u, 0.5 * y), x, 1e-9);
        }
    }

    TEST_CASE("dexpinv: inverts the closed form of dexp for small and large u") {
        // dexp_u(x) = x + (1 - cos t)/t^2 u x x + (t - sin t)/t^3 u x (u x x), t = |u| (series when small).
        for (double size : {1e-9, 1e-5, 1e-3, 0.01, 0.5, 2.0, 5.0}) {
            INPUTS(size);
            const Vec3 u = size * checks::random_unit(), x = checks::random_vector();
            INPUTS(u, x);
            const double t = u.norm(), t2 = t * t;
            const double a = 0.5 * std::pow(std::sin(t / 2) / (t / 2), 2);
            const double b = t < 0.01 ? 1.0 / 6 - t2 / 120 + t2 * t2 / 5040 : (t - std::sin(t)) / (t * t2);
            const Vec3 dexp = x + a * u.cross(x) + b * u.cross(u.cross(x));
            CHECK_MAT_NEAR(rigid::dexpinv(u, dexp), x, 5e-15 * (1 + t2));
        }
    }

    // Just below |u| = 1e-3 the header asks for the series c = 1/12 + x^2/720: its second term
    // moves the result by 2 x^4/720 |v| = 2.8e-15 |v| there, a dozen ulps of v, so a tolerance of a
    // few ulps against a long double reference (the series to x^4) sees it.
    TEST_CASE("dexpinv: keeps its last digits just below |u| = 1e-3") {
        using Vec3L = Eigen::Matrix<long double, 3, 1>;
        for (int n = 0; n < 10; ++n) {
            const Vec3 d = checks::random_unit();
            INPUTS(d);
            const Vec3 u = 0.999e-3 * d, v = d.unitOrthogonal();  // |v| = 1, v orthogonal to u
            const Vec3L uL = u.cast<long double>(), vL = v.cast<long double>();
            INPUTS(u, v);
            const long double x2 = uL.squaredNorm();
            const long double c = 1.0L / 12 + x2 / 720 + x2 * x2 / 30240;
            const Vec3L uv = uL.cross(vL);
            const Vec3L ref = vL - uv / 2 + c * uL.cross(uv);
            CHECK_MAT_NEAR(rigid::dexpinv(u, v), Vec3(ref.cast<double>()), 6e-16);
        }
    }

    TEST_CASE("dexpinv: is the identity at u = 0") {
        const Vec3 v(0.3, -1.2, 2.5);
        INPUTS(v);
        CHECK_MAT_NEAR(rigid::dexpinv(Vec3::Zero(), v), v, 0.0);
        CHECK(rigid::dexpinv(Vec3(1e-300, 0, 0), v).allFinite());
    }

    TEST_CASE("combine: is the step first then second") {
        for (int i = 0; i < 20; ++i) {
            const Vec3 w1 = checks::random_vector(), w2 = checks::random_vector();
            INPUTS(UNIT(w1, "rad"), UNIT(w2, "rad"));
            const Increment d1{checks::random_vector(), rot(w1) - Mat3::Identity()};
            INPUTS(d1);
            const Increment d2{checks::random_vector(), rot(w2) - Mat3::Identity()};
            INPUTS(d2);
            const Increment d = rigid::combine(d1, d2);
            CHECK_MAT_NEAR(d.dOmega, d1.dOmega + d2.dOmega, 1e-15);
            CHECK_MAT_NEAR(Mat3::Identity() + d.E, rot(w1) * rot(w2), 2e-14);
            const Increment same = rigid::combine(d1, Increment{});
            CHECK_MAT_NEAR(same.E, d1.E, 0.0);
        }
    }

    TEST_CASE("combine: keeps the digits of small increments") {
        // Two turns about one axis by 1e-9 and 2e-9 rad make one turn by 3e-9. Multiplying
        // (1 + E1)(1 + E2) and subtracting 1 would leave about 7 correct digits here.
        const Vec3 u = Vec3(1, 2, 2) / 3;
        INPUTS(u);
        const auto turn = [&](double phi) {  // sin(phi) hat(u) + (1 - cos phi) hat(u)^2, exactly enough
            const Mat3 U = skew(u);
            return Mat3(std::sin(phi) * U + 2 * std::pow(std::sin(phi / 2), 2) * U * U);
        };
        const Increment d = rigid::combine({Vec3::Zero(), turn(1e-9)}, {Vec3::Zero(), turn(2e-9)});
        CHECK_SMALL((d.E - turn(3e-9)).norm(), 1e-14 * turn(3e-9).norm());
    }

    TEST_CASE("rkmk4_step: one plus E is a rotation whatever the step") {
        for (int i = 0; i < 20; ++i) {
            const HeavyTop top = random_top();
            INPUTS(top);
            const BodyState s = random_state();
            INPUTS(s);
            const Increment d = rigid::rkmk4_step(top, s, checks::uniform(0.05, 0.5));
            const Mat3 Q = Mat3::Identity() + d.E;
            CHECK_SMALL((Q.transpose() * Q - Mat3::Identity()).norm(), 3e-14);
            CHECK(d.dOmega.allFinite());
        }
    }

    TEST_CASE("rkmk4_step: is exact for a spherical body without torque") {
        // Omega stays constant and R(h) = R(0) exp(h hat(Omega)).
        const HeavyTop top{2.5 * Mat3::Identity(), 0.0, Vec3::UnitZ(), Vec3::UnitX()};
        INPUTS(top);
        const BodyState s{Vec3(0.4, -1.1, 0.7), checks::random_rotation(0.1, 3.0)};
        INPUTS(s);
        const double h = 0.7;
        INPUTS(UNIT(h, "s"));
        const Increment d = rigid::rkmk4_step(top, s, h);
        CHECK_MAT_NEAR(d.dOmega, Vec3::Zero(), 1e-14);
        CHECK_MAT_NEAR(s.R + s.R * d.E, s.R * rot(h * s.Omega), 2e-15);
    }

    TEST_CASE("rkmk4_step: converges with order 4 to the Grioli precession") {
        const Grioli g = grioli(1.0, 1.5, 2.0, 1.0);
        const auto step = [&](const BodyState& s, double h) { return rigid::rkmk4_step(g.top, s, h); };
        INPUTS(g.top, UNIT(g.alpha, "rad/s"), g.a);
        INFO("the Grioli precession of diag(1, 1.5, 2) with f = 1 from its start for one period "
             << g.period()
             << " s in 80 and in 160 steps; e1 and e2 the errors at its end (angle in rad, "
                "|Omega - Omega(T)| / alpha), e1 / e2 the order's ratio");
        const double e1 = error_after_one_period(g, 80, step), e2 = error_after_one_period(g, 160, step);
        CHECK_SMALL(e1, 3e-5);
        CHECK_NEAR(e1 / e2, 16.0, 2.0);
    }

    TEST_CASE("torque_kick: changes Omega by h f J^-1 (R^T k) x z(0) and nothing else") {
        for (int i = 0; i < 20; ++i) {
            HeavyTop top = random_top();
            INPUTS(top);
            const Mat3 Q = checks::random_rotation(0.1, 3.0);
            top.J = Q * top.J * Q.transpose();  // the kick works for any inertia tensor
            const BodyState s = random_state();
            INPUTS(s);
            const double h = checks::uniform(-0.5, 0.5);
            INPUTS(UNIT(h, "s"));
            const Vec3 g = s.R.transpose() * top.k;
            const Vec3 torque(g.y() * top.z0.z() - g.z() * top.z0.y(), g.z() * top.z0.x() - g.x() * top.z0.z(),
                              g.x() * top.z0.y() - g.y() * top.z0.x());
            const Increment d = rigid::torque_kick(top, s, h);
            CHECK_MAT_NEAR(d.dOmega, h * top.f * top.J.inverse() * torque, 1e-14);
            CHECK_MAT_NEAR(d.E, Mat3::Zero(), 0.0);
        }
    }

    TEST_CASE("free_rotation: is the exact flow of the kinetic energy about one axis") {
        for (int axis = 0; axis < 3; ++axis) {
            INPUTS(axis);
            const HeavyTop top = random_top();
            INPUTS(top);
            const BodyState s = random_state();
            INPUTS(s);
            const double h = checks::uniform(-0.8, 0.8);
            INPUTS(UNIT(h, "s"));
            const Vec3 e = Vec3::Unit(axis);
            const double phi = h * s.Omega(axis);
            INPUTS(UNIT(phi, "rad"));
            const Increment d = rigid::free_rotation(top, s, axis, h);
            CHECK_MAT_NEAR(s.R + s.R * d.E, s.R * Rot(e, phi), 2e-15);
            CHECK_MAT_NEAR(s.Omega + d.dOmega, top.J.inverse() * Rot(e, -phi) * top.J * s.Omega, 1e-14);
        }
    }

    TEST_CASE("free_rotation: keeps the angular momentum in space and Omega along its axis") {
        const HeavyTop top = random_top();
        INPUTS(top);
        const BodyState s = random_state();
        INPUTS(s);
        for (int axis = 0; axis < 3; ++axis) {
            INPUTS(axis);
            const BodyState n = rigid::apply(s, rigid::free_rotation(top, s, axis, 0.37));
            CHECK_MAT_NEAR(n.R * top.J * n.Omega, s.R * top.J * s.Omega, 1e-14);
            CHECK_NEAR(n.Omega(axis), s.Omega(axis), 1e-15);
        }
    }

    TEST_CASE("free_rotation: rejects an axis outside 0..2") {
        const HeavyTop top = random_top();
        INPUTS(top);
        const BodyState s = random_state();
        INPUTS(s);
        // A valid input first: a file that refuses every input earns nothing here.
        CHECK_NOTHROW((void)rigid::free_rotation(top, s, 0, 0.1));
        CHECK_THROWS_AS(rigid::free_rotation(top, s, -1, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_rotation(top, s, 3, 0.1), std::invalid_argument);
    }

    TEST_CASE("strang_step: is the flows of V T1 T2 T3 T2 T1 V in that order") {
        const HeavyTop top = random_top();
        INPUTS(top);
        const BodyState s = random_state();
        INPUTS(s);
        const double h = 0.3;
        INPUTS(UNIT(h, "s"));
        const Vec3 I = top.J.diagonal();
        // Each flow written out here: the kick, and the rotation about one principal axis.
        BodyState x = s;
        const auto kick = [&](double t) {
            x.Omega += t * top.f * ((x.R.transpose() * top.k).cross(top.z0)).cwiseQuotient(I);
        };
        const auto turn = [&](int i, double t) {
            const double phi = t * x.Omega(i);
            INPUTS(UNIT(phi, "rad"));
            x.R = x.R * Rot(Vec3::Unit(i), phi);
            x.Omega = (Rot(Vec3::Unit(i), -phi) * I.cwiseProduct(x.Omega)).cwiseQuotient(I);
        };
        kick(h / 2), turn(0, h / 2), turn(1, h / 2), turn(2, h), turn(1, h / 2), turn(0, h / 2), kick(h / 2);
        const BodyState n = rigid::apply(s, rigid::strang_step(top, s, h));
        CHECK_MAT_NEAR(n.R, x.R, 1e-14);
        CHECK_MAT_NEAR(n.Omega, x.Omega, 1e-14);
    }

    TEST_CASE("strang_step: is symmetric so that a step of -h undoes a step of h") {
        const HeavyTop top = random_top();
        INPUTS(top);
        const BodyState s = random_state();
        INPUTS(s);
        const BodyState there = rigid::apply(s, rigid::strang_step(top, s, 0.2));
        const BodyState back = rigid::apply(there, rigid::strang_step(top, there, -0.2));
        CHECK_MAT_NEAR(back.R, s.R, 1e-14);
        CHECK_MAT_NEAR(back.Omega, s.Omega, 1e-14);
    }

    TEST_CASE("strang_step: converges with order 2 to the Grioli precession") {
        const Grioli g = grioli(1.0, 1.5, 2.0, 1.0);
        const auto step = [&](const BodyState& s, double h) { return rigid::strang_step(g.top, s, h); };
        INPUTS(g.top, UNIT(g.alpha, "rad/s"), g.a);
        INFO("the Grioli precession of diag(1, 1.5, 2) with f = 1 from its start for one period "
             << g.period()
             << " s in 100 and in 200 steps; e1 and e2 the errors at its end (angle in rad, "
                "|Omega - Omega(T)| / alpha), e1 / e2 the order's ratio");
        const double e1 = error_after_one_period(g, 100, step), e2 = error_after_one_period(g, 200, step);
        CHECK_SMALL(e1, 2e-2);
        CHECK_NEAR(e1 / e2, 4.0, 0.3);
    }

    TEST_CASE("strang_step: keeps the vertical angular momentum and R on SO(3) over 2000 steps") {
        const HeavyTop top = random_top();
        INPUTS(top);
        BodyState s = random_state();
        INPUTS(s);
        const double L0 = vertical_momentum(top, s);
        for (int i = 0; i < 2000; ++i) s = rigid::apply(s, rigid::strang_step(top, s, 0.05));
        CHECK_NEAR(vertical_momentum(top, s), L0, 2e-13);
        CHECK_SMALL((s.R.transpose() * s.R - Mat3::Identity()).norm(), 2e-13);
    }

    TEST_CASE("triple_jump: takes the substeps g1 h then g2 h then g1 h each from the state reached") {
        const double g1 = 1 / (2 - std::cbrt(2.0)), g2 = 1 - 2 * g1;
        std::vector<double> hs;
        std::vector<BodyState> from;
        // A made-up step: Omega grows by h (1, 2, 3), R turns by h about e3.
        const rigid::IncrementStepper step = [&](const BodyState& s, double h) {
            hs.push_back(h);
            from.push_back(s);
            return Increment{h * Vec3(1, 2, 3), Rot(Vec3::UnitZ(), h) - Mat3::Identity()};
        };
        const BodyState s{Vec3(0.1, 0.2, 0.3), checks::random_rotation(0.1, 3.0)};
        INPUTS(s);
        const double h = 0.4;
        INPUTS(UNIT(h, "s"));
        const Increment d = rigid::triple_jump(step, s, h);
        REQUIRE(hs.size() == 3);
        CHECK_NEAR(hs[0], g1 * h, 1e-15);
        CHECK_NEAR(hs[1], g2 * h, 1e-15);
        CHECK_NEAR(hs[2], g1 * h, 1e-15);
        CHECK_MAT_NEAR(from[1].R, s.R * Rot(Vec3::UnitZ(), g1 * h), 1e-14);
        CHECK_MAT_NEAR(from[2].Omega, s.Omega + (g1 + g2) * h * Vec3(1, 2, 3), 1e-14);
        CHECK_MAT_NEAR(d.dOmega, h * Vec3(1, 2, 3), 1e-14);
        CHECK_MAT_NEAR(Mat3::Identity() + d.E, Rot(Vec3::UnitZ(), h), 1e-14);
    }

    TEST_CASE("triple_jump: makes the Strang splitting fourth order") {
        ALSO_USES("strang_step");
        const Grioli g = grioli(1.0, 1.5, 2.0, 1.0);
        const rigid::IncrementStepper strang = [&](const BodyState& s, double h) {
            return rigid::strang_step(g.top, s, h);
        };
        const auto step = [&](const BodyState& s, double h) { return rigid::triple_jump(strang, s, h); };
        INPUTS(g.top, UNIT(g.alpha, "rad/s"), g.a);
        INFO("the Grioli precession of diag(1, 1.5, 2) with f = 1 from its start for one period "
             << g.period()
             << " s in 80 and in 160 steps; e1 and e2 the errors at its end (angle in rad, "
                "|Omega - Omega(T)| / alpha), e1 / e2 the order's ratio");
        const double e1 = error_after_one_period(g, 80, step), e2 = error_after_one_period(g, 160, step);
        CHECK_SMALL(e1, 5e-4);
        CHECK_NEAR(e1 / e2, 16.0, 2.0);
    }

    // rk4_energy_loss is a derivation exercise: its closed form is in no contract. The graders take
    // one classical RK4 step of q' = p, p' = -q (omega = 1, h = x) here in binary128 and measure
    // the energy before and after.
    TEST_CASE("rk4_energy_loss: equals 1 - E(h)/E(0) of one RK4 step taken in binary128 down to x = 0.01") {
        using quadref::quad;
        for (double x : {0.01, 0.03, 0.1, 0.3, 0.5, 1.0, 1.5, 2.0, 2.5, 2.7, 3.0}) {
            for (const auto& [q0, p0] : {std::pair{1.0, 0.0}, {0.3, -0.7}}) {
                auto f = [](quad q, quad p) { return std::pair<quad, quad>{p, -q}; };
                const quad h = x, q = q0, p = p0;
                const auto [a1, b1] = f(q, p);
                const auto [a2, b2] = f(q + h / 2 * a1, p + h / 2 * b1);
                const auto [a3, b3] = f(q + h / 2 * a2, p + h / 2 * b2);
                const auto [a4, b4] = f(q + h * a3, p + h * b3);
                const quad q1 = q + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4), p1 = p + h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
                const quad E0 = (q * q + p * p) / 2, E1 = (q1 * q1 + p1 * p1) / 2;
                const double loss = (double)(1 - E1 / E0);
                // The size of the two terms of the loss (x^6/72 and x^8/576): the scale of its rounding.
                const double scale = std::pow(x, 6) / 72 + std::pow(x, 8) / 576;
                const double got = rigid::rk4_energy_loss(x);
                INPUTS(x);
                INFO("the binary128 RK4 step from q = "
                     << q0 << ", p = " << p0 << ": expected " << checks::digits17(loss) << ", actual "
                     << checks::digits17(got) << ", tolerance 32 eps (" << scale << ")");
                CHECK(std::abs(got - loss) <= 32 * std::numeric_limits<double>::epsilon() * scale);
            }
        }
    }

    TEST_CASE("rk4_energy_loss: equals the binary128 step at random x from 0.01 to 3 (the graders' seed)") {
        using quadref::quad;
        for (int n = 0; n < 20; ++n) {
            const double x = std::exp(checks::uniform(std::log(0.01), std::log(3.0)));
            INPUTS(x);
            const quad h = x;
            quad q = 1, p = 0;
            const quad a1 = p, b1 = -q;
            const quad a2 = p + h / 2 * b1, b2 = -(q + h / 2 * a1);
            const quad a3 = p + h / 2 * b2, b3 = -(q + h / 2 * a2);
            const quad a4 = p + h * b3, b4 = -(q + h * a3);
            const quad q1 = q + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4), p1 = p + h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
            const double loss = (double)(1 - (q1 * q1 + p1 * p1) / (q * q + p * p));
            const double scale = std::pow(x, 6) / 72 + std::pow(x, 8) / 576;
            const double got = rigid::rk4_energy_loss(x);
            INFO("expected " << checks::digits17(loss) << ", actual " << checks::digits17(got) << ", tolerance 32 eps ("
                             << scale << ")");
            CHECK(std::abs(got - loss) <= 32 * std::numeric_limits<double>::epsilon() * scale);
        }
    }

    TEST_CASE("rk4_energy_loss: keeps its digits at x = 1e-3 and changes sign at x = 2 sqrt(2)") {
        // At x = 1e-3 the loss is x^6/72 (1 - x^2/8) to 1e-12 relative (the next term is x^8/576):
        // a value computed as 1 - (energy after a step in double) is 0 or 1e-16, off by 10^4.
        const double x = 1e-3, lead = std::pow(x, 6) / 72;
        INPUTS(x);
        CHECK(std::abs(rigid::rk4_energy_loss(x) / lead - 1) <= 2e-6);
        CHECK(std::abs(rigid::rk4_energy_loss(1e-5) / (std::pow(1e-5, 6) / 72) - 1) <= 1e-9);
        CHECK(rigid::rk4_energy_loss(2.8) > 0);
        CHECK(rigid::rk4_energy_loss(2.9) < 0);
        CHECK(std::abs(rigid::rk4_energy_loss(0.0)) == 0.0);
    }

    TEST_CASE("rk4_energy_loss: rejects a negative or non-finite x") {
        // A valid input first: a file that refuses every input earns nothing here.
        CHECK_NOTHROW((void)rigid::rk4_energy_loss(1.0));
        for (double x : {-0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
            INPUTS(x);
            CHECK_THROWS_AS((void)rigid::rk4_energy_loss(x), std::invalid_argument);
        }
    }

}  // TEST_SUITE

// ---- Bad input at its boundary: every "throws ... for ..." rule of exercises/rigid/numerics.hpp ----
// The last bad value is refused with std::invalid_argument and the first good value beyond it
// is accepted, with the right answer. Graders check the exception's type, never its wording.
TEST_SUITE("ch07_numerics") {
    TEST_CASE("rk4_energy_loss: rejects x just below 0 or infinite and accepts x = 0 and the smallest x") {
        const double tiny = std::numeric_limits<double>::denorm_min(), inf = std::numeric_limits<double>::infinity();
        for (double x : {-tiny, -1e-300, -inf}) {
            INPUTS(x);
            CHECK_THROWS_AS((void)rigid::rk4_energy_loss(x), std::invalid_argument);
        }
        // x = 0 and the next doubles up lose nothing a double can hold; x = 1e-50 keeps its
        // leading term x^6 / 72 = 1.3888...e-302 (no underflow yet).
        CHECK(std::abs(rigid::rk4_energy_loss(0.0)) == 0.0);
        INPUTS(tiny);
        CHECK(std::abs(rigid::rk4_energy_loss(tiny)) == 0.0);
        CHECK_NEAR(rigid::rk4_energy_loss(1e-50) / (1e-300 / 72), 1.0, 1e-14);
    }
}  // TEST_SUITE
