// case: does not compile (the first compiler error is shown, its path relative)
// replace: hat
// expect: * | build error | exercises/rotation.cpp:
namespace rigid {
Mat3 hat(const Vec3& w) { return w.cross(w) }
}  // namespace rigid
