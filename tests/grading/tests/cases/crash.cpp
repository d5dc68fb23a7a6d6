// case: a segmentation fault
// replace: axis_angle
// expect: axis_angle | crash | SIGSEGV
namespace rigid {
AxisAngle axis_angle(const Mat3& R) {
    volatile int* volatile nowhere = nullptr;  // volatile twice: the compiler must do the write
    *nowhere = static_cast<int>(R(0, 0));
    return {Vec3::UnitZ(), 0.0};
}
}  // namespace rigid
