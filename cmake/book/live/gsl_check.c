/* The GSL of the live scenes against Debian's native GSL (cmake/book/live/gsl_check.cmake): the same
 * program, built natively and with emscripten, prints what the scenes ask of GSL, a Jacobi
 * elliptic function (the exact free body, rigid/free_body_exact.hpp) and a rk8pd integration of
 * odeiv2 (rigid/ode.hpp), with 17 digits. PLANT (its self-test) moves one result by 1e-9. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_elljac.h>
#include <math.h>
#include <stdio.h>

static int pendulum(double t, const double y[], double dydt[], void* params) {
    (void)t, (void)params;
    dydt[0] = y[1];
    dydt[1] = -sin(y[0]);
    return GSL_SUCCESS;
}

int main(void) {
    const double u[] = {0.3, 1.7, 4.2}, m[] = {0.1, 0.5, 0.999};
    for (int i = 0; i < 3; ++i) {
        double sn, cn, dn;
        if (gsl_sf_elljac_e(u[i], m[i], &sn, &cn, &dn) != GSL_SUCCESS) return 1;
#ifdef PLANT
        sn *= 1 + 1e-9;
#endif
        printf("elljac %.17g %.17g %.17g\n", sn, cn, dn);
    }
    gsl_odeiv2_system sys = {pendulum, NULL, 2, NULL};
    gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, 1e-12, 1e-12);
    double t = 0, y[2] = {2.0, 0.0};
    if (gsl_odeiv2_driver_apply(d, &t, 20.0, y) != GSL_SUCCESS) return 1;
    gsl_odeiv2_driver_free(d);
    printf("rk8pd %.17g %.17g\n", y[0], y[1]);
    return 0;
}
