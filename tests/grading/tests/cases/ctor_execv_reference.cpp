// case: the untouched stubs, plus a constructor that execv()s the reference grader and the judge (fd 3 survives an exec; the filter forbids it)
// base: stubs
// expect: * | not started | todo(
#include <unistd.h>

#include <fstream>
#include <string>
#include <vector>
__attribute__((constructor)) static void take_over() {
    // The arguments this process got (the test's name among them), passed on unchanged.
    std::ifstream in("/proc/self/cmdline");
    std::vector<std::string> words;
    for (std::string w; std::getline(in, w, '\0');) words.push_back(w);
    for (const char* other : {"@BUILD@/graders/grade_rotation", "@BUILD@/grading/judge/judge_rotation"}) {
        std::vector<char*> argv{const_cast<char*>(other)};
        for (std::size_t k = 1; k < words.size(); ++k) argv.push_back(words[k].data());
        argv.push_back(nullptr);
        execv(other, argv.data());
    }
}
