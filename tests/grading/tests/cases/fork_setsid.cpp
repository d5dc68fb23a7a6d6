// case: as root, forks a child that calls setsid() to leave the test's process group and, a second later, writes full marks into the results
// needs: root
// replace: lab_angular_velocity
// expect: lab_angular_velocity | fail | expected
// score: lab_angular_velocity 0
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <thread>
namespace {
void forge() {
    const std::string results = "@OUT@/results/@STUDENT@";
    for (const char* ext : {".json", ".tsv"}) {
        if (FILE* f = std::fopen((results + ext).c_str(), "w")) {
            std::fputs("{\"score\": 999, \"tests\": []}\n", f);
            std::fclose(f);
        }
    }
}
}  // namespace
namespace rigid {
Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) {
    if (fork() == 0) {
        setsid();
        if (fork() == 0) {
            sleep(1);
            forge();
        }
        _exit(0);
    }
    try {
        std::thread([] {
            sleep(1);
            forge();
        }).detach();  // if processes are refused, a thread
    } catch (...) {
    }
    forge();  // and at once, in case the folder is there to write
    return vee(R.transpose() * R_dot);
}
}  // namespace rigid
