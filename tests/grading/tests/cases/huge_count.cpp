// case: answers a call with a forged message in the judge's mailbox whose list claims a million points in a thousand bytes (a small message that asks for a large allocation): refused before anything is allocated, with the reason
// topic: inertia
// replace: six_point_body
// expect: six_point_body | fail | longer than the message
#include <linux/futex.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstring>
namespace {
// The mailboxes as tests/grading/engine/remote/channel.hpp lays them out (the workbook is public).
struct Mailbox {
    alignas(64) std::atomic<std::uint32_t> sequence;
    std::atomic<std::uint32_t> length;
    std::atomic<std::uint32_t> sleeping;
    char data[1u << 20];
};
struct Mailboxes {
    Mailbox to_student, to_judge;
};
}  // namespace
namespace rigid {
std::vector<PointMass> six_point_body(const BodyAtG&) {
    void* p = mmap(nullptr, sizeof(Mailboxes), PROT_READ | PROT_WRITE, MAP_SHARED, 4, 0);
    if (p == MAP_FAILED) return {};
    Mailbox& out = static_cast<Mailboxes*>(p)->to_judge;
    const std::uint32_t n = 1000000;  // points, of 32 bytes each on the wire
    out.data[0] = 'R';
    std::memcpy(out.data + 1, &n, sizeof n);
    std::memset(out.data + 5, 0, 1000);
    out.length.store(1005);
    out.sequence.fetch_add(1);
    syscall(SYS_futex, &out.sequence, FUTEX_WAKE, 1, nullptr, nullptr, 0);
    // The judge ends the test: its next message is the one that says so.
    const Mailbox& in = static_cast<Mailboxes*>(p)->to_student;
    const std::uint32_t seen = in.sequence.load();
    while (in.sequence.load() == seen) usleep(1000);
    _exit(0);
}
}  // namespace rigid
