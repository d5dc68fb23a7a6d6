// Checks of the provided exact free-body motion (rigid/free_body_exact.hpp). Not graders:
// nothing here is an exercise. Each check is against something independent of the elliptic
// formulas: GSL's own elliptic functions, the Euler-Poisson equations written out here and
// integrated by GSL's rk8pd at tight tolerance, finite differences, closed forms.
#include "rigid/free_body_exact.hpp"

#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "checks.hpp"
#include "rigid/ode.hpp"

using rigid::Mat3;
using rigid::Vec3;
using rigid::VecX;

namespace {

using checks::nan_;

// Euler-Poisson for the free body, written out component by component: independent of the
// student's free_body_equations and of the elliptic solution.
VecX euler_poisson(const Vec3& I, const VecX& y) {
    VecX d(12);
    const double w1 = y(0), w2 = y(1), w3 = y(2);
    d(0) = (I(1) - I(2)) * w2 * w3 / I(0);
    d(1) = (I(2) - I(0)) * w3 * w1 / I(1);
    d(2) = (I(0) - I(1)) * w1 * w2 / I(2);
    for (int i = 0; i < 3; ++i) {  // row i of dR/dt = R hat(Omega)
        const double r1 = y(3 + 3 * i), r2 = y(4 + 3 * i), r3 = y(5 + 3 * i);
        d(3 + 3 * i) = r2 * w3 - r3 * w2;
        d(4 + 3 * i) = r3 * w1 - r1 * w3;
        d(5 + 3 * i) = r1 * w2 - r2 * w1;
    }
    return d;
}

struct Integrated {
    std::vector<Vec3> Omega;
    std::vector<Mat3> R;
};

Integrated integrate(const Vec3& I, const Vec3& Omega0, const std::vector<double>& times, double tol = 1e-14) {
    Integrated out;
    rigid::integrate_gsl([&](double, const VecX& y) { return euler_poisson(I, y); },
                         rigid::pack({Omega0, Mat3::Identity()}), times,
                         [&](double, const VecX& y) {
                             const rigid::BodyState s = rigid::unpack(y);
                             out.Omega.push_back(s.Omega);
                             out.R.push_back(s.R);
                         },
                         {.method = "rk8pd", .rel_tol = tol, .abs_tol = tol});
    return out;
}

}  // namespace

TEST_SUITE("provided_free_body_exact") {
    TEST_CASE("jacobi_elliptic: agrees with gsl_sf_elljac_e away from m = 1") {
        double worst = 0;
        for (double m : {1e-6, 0.1, 0.5, 0.9, 0.999}) {
            for (double u : {-7.3, -1.0, 0.0, 0.4, 1.7, 3.2, 25.0}) {
                double sn, cn, dn;
                gsl_sf_elljac_e(u, m, &sn, &cn, &dn);
                const rigid::JacobiElliptic e = rigid::jacobi_elliptic(u, m, 1 - m);
                worst = std::max({worst, std::abs(e.sn - sn), std::abs(e.cn - cn), std::abs(e.dn - dn)});
            }
        }
        CHECK_SMALL(worst, 2e-14);
    }

    TEST_CASE("jacobi_elliptic: obeys the identities and the derivative sn' = cn dn") {
        for (double m_c : {0.7, 1e-3, 1e-9}) {
            const double m = 1 - m_c;
            for (double u : {0.3, 2.0, 9.5}) {
                CAPTURE(m_c);
                CAPTURE(u);
                const auto e = rigid::jacobi_elliptic(u, m, m_c);
                CHECK_NEAR(e.sn * e.sn + e.cn * e.cn, 1.0, 4e-16);
                CHECK_NEAR(e.dn * e.dn + m * e.sn * e.sn, 1.0, 4e-16);
                const double h = 1e-5;
                const double dsn =
                    (rigid::jacobi_elliptic(u + h, m, m_c).sn - rigid::jacobi_elliptic(u - h, m, m_c).sn) / (2 * h);
                CHECK_NEAR(dsn, e.cn * e.dn, 1e-9);
            }
        }
    }

    TEST_CASE("jacobi_elliptic: keeps dn(K) = sqrt(m_c) near the separatrix where 1 - m is lost") {
        for (double m_c : {1e-6, 1e-10, 1e-12, 1e-14}) {
            CAPTURE(m_c);
            const double K = gsl_sf_ellint_RF(0.0, m_c, 1.0, GSL_PREC_DOUBLE);
            const auto e = rigid::jacobi_elliptic(K, 1 - m_c, m_c);
            CHECK_NEAR(e.sn, 1.0, 1e-15);
            CHECK_NEAR(e.dn / std::sqrt(m_c), 1.0, 1e-9);
        }
        CHECK_NEAR(rigid::jacobi_elliptic(0.8, 1.0, 0.0).sn, std::tanh(0.8), 2e-16);
        CHECK_THROWS_AS(rigid::jacobi_elliptic(0.8, 0.5, 0.6), std::invalid_argument);
    }

    TEST_CASE("free_body_motion: Omega(0) is Omega0 for every order of the moments and both cases") {
        for (int n = 0; n < 40; ++n) {
            Vec3 I(checks::uniform(1, 2), checks::uniform(1, 2), checks::uniform(1, 2));
            const Vec3 Omega0 = checks::random_vector(3);
            CAPTURE(I.transpose());
            CAPTURE(Omega0.transpose());
            const auto mo = rigid::free_body_motion(I, Omega0);
            CHECK_MAT_NEAR(rigid::free_body_exact_omega(mo, 0.0), Omega0, 4e-15 * Omega0.norm());
            CHECK_NEAR(mo.m + mo.m_c, 1.0, 4e-16);
        }
    }

    TEST_CASE("free_body_motion: Omega(t) and R(t) agree with rk8pd at tolerance 1e-14") {
        for (int n = 0; n < 12; ++n) {
            const Vec3 I(checks::uniform(1, 2), checks::uniform(1, 2), checks::uniform(1, 2));
            const Vec3 Omega0 = checks::random_vector(2);
            CAPTURE(I.transpose());
            CAPTURE(Omega0.transpose());
            const auto times = rigid::linspace(0, 10, 20);
            const Integrated ref = integrate(I, Omega0, times);
            const auto mo = rigid::free_body_motion(I, Omega0);
            const auto R = rigid::free_body_exact_rotations(mo, times);
            double eO = 0, eR = 0;
            for (std::size_t k = 0; k < times.size(); ++k) {
                eO = std::max(eO, (rigid::free_body_exact_omega(mo, times[k]) - ref.Omega[k]).norm() / Omega0.norm());
                eR = std::max(eR, (R[k] - ref.R[k]).norm());
            }
            CHECK_SMALL(eO, 1e-12);
            CHECK_SMALL(eR, 1e-11);
        }
    }

    TEST_CASE("free_body_exact_rotations: R is orthogonal, carries the angular momentum fixed, and gives back Omega") {
        const Vec3 I(1, 2, 3), Omega0(0.3, -2.0, 0.5);
        const auto mo = rigid::free_body_motion(I, Omega0);
        const double h = 1e-4;
        for (double t : {0.7, 4.1, 13.0}) {
            CAPTURE(t);
            const auto R = rigid::free_body_exact_rotations(mo, {t - h, t, t + h});
            CHECK_SMALL((R[1].transpose() * R[1] - Mat3::Identity()).norm(), 1e-14);
            CHECK(R[1].determinant() > 0);
            const Vec3 Omega = rigid::free_body_exact_omega(mo, t);
            CHECK_MAT_NEAR(R[1] * I.cwiseProduct(Omega), I.cwiseProduct(Omega0), 1e-13);
            const Mat3 W = R[1].transpose() * (R[2] - R[0]) / (2 * h);
            CHECK_MAT_NEAR(0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1)), Omega, 1e-7);
        }
    }

    TEST_CASE("free_body_motion: the invariants of (6.9) stay at their initial values") {
        const Vec3 I(2, 1, 2.5), Omega0(1.0, 0.2, -0.7);
        const auto mo = rigid::free_body_motion(I, Omega0);
        for (double t : {0.1, 5.0, 50.0, 500.0}) {
            const Vec3 w = rigid::free_body_exact_omega(mo, t);
            CHECK_NEAR(0.5 * w.dot(I.cwiseProduct(w)) / mo.energy, 1.0, 1e-15);
            CHECK_NEAR(I.cwiseProduct(w).squaredNorm() / mo.momentum_squared, 1.0, 1e-15);
        }
    }

    TEST_CASE("free_body_motion: a symmetric body precesses regularly at (I3 - I1) Omega3 / I1") {
        for (const Vec3& I : {Vec3(1, 1, 1.8), Vec3(2, 2, 1)}) {
            const Vec3 Omega0(0.4, -0.1, 1.3);
            const auto mo = rigid::free_body_motion(I, Omega0);
            CHECK_SMALL(mo.m, 0.0);
            const double rate = (I(2) - I(0)) * Omega0(2) / I(0);
            for (double t : {0.5, 3.0, 20.0}) {
                // (Omega1 + i Omega2)(t) = (Omega1 + i Omega2)(0) exp(i rate t), Omega3 constant.
                const double c = std::cos(rate * t), s = std::sin(rate * t);
                const Vec3 expected(c * Omega0(0) - s * Omega0(1), s * Omega0(0) + c * Omega0(1), Omega0(2));
                CHECK_MAT_NEAR(rigid::free_body_exact_omega(mo, t), expected, 1e-14);
            }
        }
    }

    TEST_CASE("free_body_motion: rotations about principal axes are steady") {
        const Vec3 I(1, 2, 3);
        for (const Vec3& w : {Vec3(0, 0, 2), Vec3(0, -1.5, 0), Vec3(3, 0, 0), Vec3(0, 0, 0)}) {
            const auto mo = rigid::free_body_motion(I, w);
            CHECK_MAT_NEAR(rigid::free_body_exact_omega(mo, 7.0), w, 1e-15);
            const Mat3 R = rigid::free_body_exact_rotations(mo, {7.0})[0];
            CHECK_MAT_NEAR(R * w, w, 1e-14);
            if (w.norm() > 0) CHECK_NEAR(R.trace(), 1 + 2 * std::cos(7.0 * w.norm()), 1e-13);
        }
        // A spherical body and Omega in the plane of two equal moments: steady too.
        CHECK(rigid::free_body_motion(Vec3(2, 2, 2), Vec3(1, 2, 3)).steady);
        CHECK(rigid::free_body_motion(Vec3(1, 2, 2), Vec3(0, 2, 3)).steady);
    }

    TEST_CASE("free_body_motion: near the separatrix, restarting from Omega(t1) reproduces the motion") {
        // J = (1, 2, 3), Omega0 = (d, 10, d): m_c ~ d^2, from 1e-4 down to 1e-12.
        for (double d : {1e-2, 1e-4, 1e-6}) {
            CAPTURE(d);
            const Vec3 I(1, 2, 3), Omega0(d, 10, d);
            const auto mo = rigid::free_body_motion(I, Omega0);
            CHECK(mo.m_c > 0.0);
            CHECK_SMALL(mo.m_c, 10 * d * d);
            const double t1 = 1.3, t2 = 2.9;
            const auto restarted = rigid::free_body_motion(I, rigid::free_body_exact_omega(mo, t1));
            const double err =
                (rigid::free_body_exact_omega(restarted, t2) - rigid::free_body_exact_omega(mo, t1 + t2)).norm();
            // The flow itself magnifies a relative perturbation eps by about 1 / m_c over one flip.
            CHECK_SMALL(err, 1e-12 * 10 / std::sqrt(mo.m_c));
        }
    }

    TEST_CASE("free_body_motion: rejects bad moments and a non-finite Omega0; accepts a flat body") {
        CHECK_THROWS_AS(rigid::free_body_motion(Vec3(-1, 2, 2), Vec3(1, 1, 1)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_motion(Vec3(0, 2, 2), Vec3(1, 1, 1)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_motion(Vec3(1, 2, 3.5), Vec3(1, 1, 1)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_motion(Vec3(5, 1, 2), Vec3(1, 1, 1)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_motion(Vec3(nan_, 1, 2), Vec3(1, 1, 1)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_motion(Vec3(1, 2, 3), Vec3(1, nan_, 1)), std::invalid_argument);
        const auto flat = rigid::free_body_motion(Vec3(1, 2, 3), Vec3(0.5, 0.5, 0.5));
        CHECK_MAT_NEAR(rigid::free_body_exact_omega(flat, 0.0), Vec3(0.5, 0.5, 0.5), 1e-15);
    }

}  // TEST_SUITE
