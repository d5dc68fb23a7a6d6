// case: quick_exit(0), which skips even the flushing of open files
// replace: compose
// expect: compose | fail | did not finish
#include <cstdlib>
namespace rigid {
AxisAngle compose(const AxisAngle&, const AxisAngle&) { std::quick_exit(0); }
}  // namespace rigid
