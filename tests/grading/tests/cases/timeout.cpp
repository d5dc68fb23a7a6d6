// case: an endless loop
// replace: compose
// expect: compose | timeout | used all of its budget of 3 s of processor time (--timeout)
namespace rigid {
AxisAngle compose(const AxisAngle& first, const AxisAngle& second) {
    volatile double spin = first.angle + second.angle;
    for (;;) spin = spin + 1;
}
}  // namespace rigid
