// case: keeps the grader's callable from one call of rk4_step and calls it during a later call, after its own call has returned (nothing in the API needs that): refused, with the reason
// topic: integrators
// replace: rk4_step
// expect: rk4_step | pass
// expect: rk4_step: one step | fail | after that call had returned
// expect: rk4_step: the error of one step | fail | after that call had returned
namespace rigid {
VecX rk4_step(const OdeRhs& f, double t, const VecX& y, double h) {
    static OdeRhs kept;
    if (kept) kept(t, y);  // the callable of an earlier call
    kept = f;
    const VecX k1 = f(t, y);
    const VecX k2 = f(t + h / 2, y + h / 2 * k1);
    const VecX k3 = f(t + h / 2, y + h / 2 * k2);
    const VecX k4 = f(t + h, y + h * k3);
    return y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
}
}  // namespace rigid
