// case: honest code with a static cache (rotation_about remembers what it computed, across the calls of a test) and debug output on stderr: full marks
// replace: rotation_about
// expect: * | pass
#include <array>
#include <cstdio>
#include <map>
#include <utility>
namespace rigid {
Mat3 rotation_about(const Vec3& axis, double angle) {
    static std::map<std::pair<std::array<double, 3>, double>, Mat3> cache;
    const auto key = std::make_pair(std::array<double, 3>{axis.x(), axis.y(), axis.z()}, angle);
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
    std::fprintf(stderr, "rotation_about: computing (%zu cached)\n", cache.size());
    const Mat3 R = rotation_about_reference_unused(axis, angle);
    if (cache.size() < 100000) cache.emplace(key, R);
    return R;
}
}  // namespace rigid
