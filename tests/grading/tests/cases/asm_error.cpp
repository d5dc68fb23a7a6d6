// case: an asm statement the assembler refuses: the build error must show the assembler's own message, not only that the compiler failed with exit status 1 (issue 42)
// replace: hat
// expect: * | build error | Error: no such instruction
namespace rigid {
Mat3 hat(const Vec3& w) {
    __asm__("workbook_not_an_instruction");
    Mat3 m;
    m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return m;
}
}  // namespace rigid
