// case: shrinks the mailboxes it shares with the judge (file descriptor 4) to nothing, so that the next side to touch them past their new end, the judge or its own, is killed by SIGBUS (issue 42: the trusted judge was; graded fail, but root code must not crash on a student's input); answers right, and passes only because the harness sealed the mailboxes at their size (before, its own reply crashed it)
// replace: hat
// expect: * | pass
#include <unistd.h>
namespace rigid {
Mat3 hat(const Vec3& w) {
    static const int shrunk = ftruncate(4, 0);  // refused: the harness sealed the mailboxes
    (void)shrunk;
    Mat3 m;
    m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return m;
}
}  // namespace rigid
