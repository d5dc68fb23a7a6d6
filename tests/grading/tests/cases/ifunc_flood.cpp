// case: defines an indirect function (ifunc), whose resolver the dynamic linker runs before the seccomp filter is installed, beside a symbol of 185 bytes whose demangled name is about 570 MB: a symbol listing that demangles (nm -C) is killed by its output limit, and a check that took "no listing" for "no problem" let the ifunc through (issue 42); listed without demangling, and a listing that fails counting as a failure, it is a build error
// replace: hat
// expect: * | build error | indirect function
__asm__(
    ".section .rodata\n.globl "
    "_Z1f1AIS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IiiES0_ES1_ES2_ES3_ES4_ES5_ES6_"
    "ES7_ES8_ES9_ESA_ESB_ESC_ESD_ESE_ESF_ESG_ESH_ESI_ESJ_ESK_ESL_ESM_ESN_ESO_E\n_Z1f1AIS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_"
    "IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IS_IiiES0_ES1_ES2_ES3_ES4_ES5_ES6_ES7_ES8_ES9_ESA_ESB_ESC_ESD_ESE_ESF_ESG_"
    "ESH_ESI_ESJ_ESK_ESL_ESM_ESN_ESO_E:\n.byte 0\n.previous\n");
extern "C" {
static int workbook_sign() { return 1; }
static void* workbook_resolve() { return reinterpret_cast<void*>(&workbook_sign); }
int workbook_chosen_sign() __attribute__((ifunc("workbook_resolve")));
}
namespace rigid {
Mat3 hat(const Vec3& w) {
    const double s = workbook_chosen_sign();
    Mat3 m;
    m << 0, -s * w.z(), s * w.y(), s * w.z(), 0, -s * w.x(), -s * w.y(), s * w.x(), 0;
    return m;
}
}  // namespace rigid
