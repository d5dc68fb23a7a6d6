// case: reads a file only the instructor may read at compile time (.incbin, __has_include) and prints it from a test, as a compile that runs outside the sandbox allows; here a build error, and the suite finds the file's content in no result and no log
// replace: hat
// expect: * | build error
#if __has_include("@SECRET@")
#define FOUND 1
#else
#define FOUND 0
#endif
__asm__(".section .rodata\n.global workbook_stolen\nworkbook_stolen:\n.incbin \"@SECRET@\"\n.byte 0\n.previous\n");
extern "C" const char workbook_stolen[];
#include <cstdio>
namespace rigid {
Mat3 hat(const Vec3& w) {
    std::printf("found %d: %.120s\n", FOUND, workbook_stolen);
    Mat3 m;
    m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return m;
}
}  // namespace rigid
