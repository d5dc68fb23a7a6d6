// case: sets LD_PRELOAD and LD_LIBRARY_PATH and runs itself again (exec keeps fd 3), so that a second record follows the first
// replace: compose
// expect: compose | fail
// score: compose 0
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>
namespace rigid {
AxisAngle compose(const AxisAngle& first, const AxisAngle&) {
    if (!std::getenv("AGAIN")) {
        setenv("AGAIN", "1", 1);
        setenv("LD_PRELOAD", "/work/evil.so", 1);
        setenv("LD_LIBRARY_PATH", "/work", 1);
        std::ifstream in("/proc/self/cmdline");
        std::vector<std::string> words;
        for (std::string w; std::getline(in, w, '\0');) words.push_back(w);
        std::vector<char*> argv;
        for (auto& w : words) argv.push_back(w.data());
        argv.push_back(nullptr);
        execv("/proc/self/exe", argv.data());
    }
    return first;
}
}  // namespace rigid
