// case: allocates without bound until the memory limit stops it
// replace: compose
// expect: compose | fail | bad_alloc
#include <memory>
#include <vector>
namespace rigid {
AxisAngle compose(const AxisAngle& first, const AxisAngle&) {
    std::vector<std::unique_ptr<char[]>> hoard;
    volatile char sink = 0;
    for (;;) {
        hoard.emplace_back(new char[16 << 20]);
        hoard.back()[0] = 1;  // used, so the compiler may not leave the allocation out
        sink = sink + hoard.back()[0];
    }
    return first;
}
}  // namespace rigid
