// case: the reference, plus an #include of a grader's header through the API's include path: a build error that names only the submission's own file
// replace: hat
// expect: * | build error | exercises/rotation.cpp:
#include "../tests/checks.hpp"
namespace rigid {
Mat3 hat(const Vec3& w) { return skew(w); }
}  // namespace rigid
