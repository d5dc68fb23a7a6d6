// case: writes forged full-mark results by path into the out folder, for itself and for another student, then answers wrongly
// replace: lab_angular_velocity
// expect: lab_angular_velocity | fail | expected
// score: lab_angular_velocity 0
#include <cstdio>
#include <string>
namespace rigid {
Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) {
    for (const std::string who : {"@STUDENT@", "reference", "partial"})
        for (const char* ext : {".json", ".tsv"})
            if (FILE* f = std::fopen(("@OUT@/results/" + who + ext).c_str(), "w")) {
                std::fputs("{\"score\": 999}\n", f);
                std::fclose(f);
            }
    return vee(R.transpose() * R_dot);
}
}  // namespace rigid
