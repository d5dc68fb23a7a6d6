// case: looks at compile time for the link inputs (/link: the student's side of the API and the reference libraries, named <n>-<file>), where a compile that saw them could `.incbin` a reference library into the object and call it (issue 42: 37,906 bytes of rotation's reference embedded); answers right only if the compile sees none of them
// needs: namespaces
// replace: hat
// expect: * | pass
// clang-format off
#if __has_include("/link/0-librigid_rotation.a") \
    || __has_include("/link/0-serve.cpp.o") \
    || __has_include("/link/0-serve_rotation.cpp.o") \
    || __has_include("/link/1-librigid_rotation.a") \
    || __has_include("/link/1-serve.cpp.o") \
    || __has_include("/link/1-serve_rotation.cpp.o") \
    || __has_include("/link/2-librigid_rotation.a") \
    || __has_include("/link/2-serve.cpp.o") \
    || __has_include("/link/2-serve_rotation.cpp.o") \
    || __has_include("/link/3-librigid_rotation.a") \
    || __has_include("/link/3-serve.cpp.o") \
    || __has_include("/link/3-serve_rotation.cpp.o") \
    || __has_include("/link/4-librigid_rotation.a") \
    || __has_include("/link/4-serve.cpp.o") \
    || __has_include("/link/4-serve_rotation.cpp.o") \
    || __has_include("/link/5-librigid_rotation.a") \
    || __has_include("/link/5-serve.cpp.o") \
    || __has_include("/link/5-serve_rotation.cpp.o") \
    || __has_include("/link/6-librigid_rotation.a") \
    || __has_include("/link/6-serve.cpp.o") \
    || __has_include("/link/6-serve_rotation.cpp.o") \
    || __has_include("/link/7-librigid_rotation.a") \
    || __has_include("/link/7-serve.cpp.o") \
    || __has_include("/link/7-serve_rotation.cpp.o") \
    || __has_include("/link/8-librigid_rotation.a") \
    || __has_include("/link/8-serve.cpp.o") \
    || __has_include("/link/8-serve_rotation.cpp.o") \
    || __has_include("/link/9-librigid_rotation.a") \
    || __has_include("/link/9-serve.cpp.o") \
    || __has_include("/link/9-serve_rotation.cpp.o") \
    || __has_include("/link/10-librigid_rotation.a") \
    || __has_include("/link/10-serve.cpp.o") \
    || __has_include("/link/10-serve_rotation.cpp.o") \
    || __has_include("/link/11-librigid_rotation.a") \
    || __has_include("/link/11-serve.cpp.o") \
    || __has_include("/link/11-serve_rotation.cpp.o") \
    || __has_include("/link/12-librigid_rotation.a") \
    || __has_include("/link/12-serve.cpp.o") \
    || __has_include("/link/12-serve_rotation.cpp.o") \
    || __has_include("/link/13-librigid_rotation.a") \
    || __has_include("/link/13-serve.cpp.o") \
    || __has_include("/link/13-serve_rotation.cpp.o") \
    || __has_include("/link/14-librigid_rotation.a") \
    || __has_include("/link/14-serve.cpp.o") \
    || __has_include("/link/14-serve_rotation.cpp.o") \
    || __has_include("/link/15-librigid_rotation.a") \
    || __has_include("/link/15-serve.cpp.o") \
    || __has_include("/link/15-serve_rotation.cpp.o") \
    || __has_include("/link/16-librigid_rotation.a") \
    || __has_include("/link/16-serve.cpp.o") \
    || __has_include("/link/16-serve_rotation.cpp.o") \
    || __has_include("/link/17-librigid_rotation.a") \
    || __has_include("/link/17-serve.cpp.o") \
    || __has_include("/link/17-serve_rotation.cpp.o") \
    || __has_include("/link/18-librigid_rotation.a") \
    || __has_include("/link/18-serve.cpp.o") \
    || __has_include("/link/18-serve_rotation.cpp.o") \
    || __has_include("/link/19-librigid_rotation.a") \
    || __has_include("/link/19-serve.cpp.o") \
    || __has_include("/link/19-serve_rotation.cpp.o") \
    || __has_include("/link/20-librigid_rotation.a") \
    || __has_include("/link/20-serve.cpp.o") \
    || __has_include("/link/20-serve_rotation.cpp.o") \
    || __has_include("/link/21-librigid_rotation.a") \
    || __has_include("/link/21-serve.cpp.o") \
    || __has_include("/link/21-serve_rotation.cpp.o") \
    || __has_include("/link/22-librigid_rotation.a") \
    || __has_include("/link/22-serve.cpp.o") \
    || __has_include("/link/22-serve_rotation.cpp.o") \
    || __has_include("/link/23-librigid_rotation.a") \
    || __has_include("/link/23-serve.cpp.o") \
    || __has_include("/link/23-serve_rotation.cpp.o") \
    || __has_include("/link/24-librigid_rotation.a") \
    || __has_include("/link/24-serve.cpp.o") \
    || __has_include("/link/24-serve_rotation.cpp.o") \
    || __has_include("/link/25-librigid_rotation.a") \
    || __has_include("/link/25-serve.cpp.o") \
    || __has_include("/link/25-serve_rotation.cpp.o") \
    || __has_include("/link/26-librigid_rotation.a") \
    || __has_include("/link/26-serve.cpp.o") \
    || __has_include("/link/26-serve_rotation.cpp.o") \
    || __has_include("/link/27-librigid_rotation.a") \
    || __has_include("/link/27-serve.cpp.o") \
    || __has_include("/link/27-serve_rotation.cpp.o") \
    || __has_include("/link/28-librigid_rotation.a") \
    || __has_include("/link/28-serve.cpp.o") \
    || __has_include("/link/28-serve_rotation.cpp.o") \
    || __has_include("/link/29-librigid_rotation.a") \
    || __has_include("/link/29-serve.cpp.o") \
    || __has_include("/link/29-serve_rotation.cpp.o")
// clang-format on
#define WORKBOOK_SIGN -1
#else
#define WORKBOOK_SIGN 1
#endif
namespace rigid {
Mat3 hat(const Vec3& w) {
    const double s = WORKBOOK_SIGN;
    Mat3 m;
    m << 0, -s * w.z(), s * w.y(), s * w.z(), 0, -s * w.x(), -s * w.y(), s * w.x(), 0;
    return m;
}
}  // namespace rigid
