// The channel between the judge and the student's process. The two take turns strictly: one
// sends a message, then waits for the other's. A message goes through a mailbox in memory the
// two share (file descriptor 4 in both, made by the harness for this test), and the one waiting
// spins briefly before it sleeps on a futex, and spins less the less spinning pays (see wait()):
// a call of a student's function costs a few microseconds, where a socket costs 21 us across the
// heaviest grader's 197,511 calls (measured here; a grader makes up to 200,000 in a test).
// A message larger than the mailbox goes on the socket (file descriptor 3), which is also how
// each side learns that the other has ended: the socket is closed.
//
// Nothing the other side writes is trusted: the judge reads a mailbox's length once, checks it
// and copies the message before it parses it (wire.hpp), and stops waiting when the socket closes.
#pragma once

#include <linux/futex.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <string>

#include "wire.hpp"

namespace workbook_remote {

inline constexpr int channel_fd = 3;  // the socket
inline constexpr int shared_fd = 4;   // the mailboxes
inline constexpr std::uint32_t mailbox_bytes = 1u << 20;
inline constexpr std::uint32_t on_socket = 0xFFFFFFFFu;  // a mailbox's length: the message is on the socket

struct Mailbox {
    alignas(64) std::atomic<std::uint32_t> sequence;  // one more for each message
    std::atomic<std::uint32_t> length;
    std::atomic<std::uint32_t> sleeping;  // 1 while the reader sleeps on `sequence`: wake it
    char data[mailbox_bytes];
};
struct Mailboxes {
    Mailbox to_student, to_judge;
};
inline constexpr std::size_t shared_bytes = sizeof(Mailboxes);
static_assert(shared_bytes <= (4u << 20), "the harness makes 4 MiB of mailboxes (tests/grading/engine/grade.cpp)");

enum class Received { message, closed, too_long, empty };

namespace detail {

inline bool read_exactly(char* p, std::size_t n) {
    std::size_t done = 0;
    while (done < n) {
        const ssize_t k = ::read(channel_fd, p + done, n - done);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        done += static_cast<std::size_t>(k);
    }
    return true;
}

inline bool send_on_socket(const std::string& message) {
    const auto n = static_cast<std::uint32_t>(message.size());
    std::string frame(reinterpret_cast<const char*>(&n), sizeof n);
    frame += message;
    std::size_t done = 0;
    while (done < frame.size()) {
        const ssize_t k = ::send(channel_fd, frame.data() + done, frame.size() - done, MSG_NOSIGNAL);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        done += static_cast<std::size_t>(k);
    }
    return true;
}

inline Received receive_on_socket(std::string& message) {
    std::uint32_t n = 0;
    if (!read_exactly(reinterpret_cast<char*>(&n), sizeof n)) return Received::closed;
    if (n > max_message) return Received::too_long;
    if (n == 0) return Received::empty;
    message.resize(n);
    if (!read_exactly(message.data(), n)) return Received::closed;
    return Received::message;
}

// The other side has closed the socket: it is gone. (Data waiting on the socket is a large
// message, read when its mailbox says so.)
inline bool socket_closed() {
    pollfd p{channel_fd, POLLIN | POLLRDHUP, 0};
    if (::poll(&p, 1, 0) <= 0) return false;
    if (p.revents & (POLLHUP | POLLRDHUP | POLLERR | POLLNVAL)) return true;
    char c;
    return ::recv(channel_fd, &c, 1, MSG_PEEK | MSG_DONTWAIT) == 0;
}

}  // namespace detail

class Channel {
public:
    // side: true for the judge. Without the mailboxes (fd 4 not the harness's), the socket alone.
    explicit Channel(bool judge) : judge_(judge) {
        void* p = ::mmap(nullptr, shared_bytes, PROT_READ | PROT_WRITE, MAP_SHARED, shared_fd, 0);
        if (p != MAP_FAILED) boxes_ = static_cast<Mailboxes*>(p);
    }

    // false when the other side is gone (never SIGPIPE).
    bool send(const std::string& message) {
        if (!boxes_) return detail::send_on_socket(message);
        Mailbox& out = judge_ ? boxes_->to_student : boxes_->to_judge;
        if (message.size() <= mailbox_bytes) {
            std::memcpy(out.data, message.data(), message.size());
            out.length.store(static_cast<std::uint32_t>(message.size()), std::memory_order_relaxed);
        } else {
            if (!detail::send_on_socket(message)) return false;
            out.length.store(on_socket, std::memory_order_relaxed);
        }
        // Sequentially consistent, with the reader's store of `sleeping` then load of `sequence`:
        // either the reader sees the new message or this sees that it sleeps (and wakes it).
        out.sequence.fetch_add(1, std::memory_order_seq_cst);
        if (out.sleeping.load(std::memory_order_seq_cst) != 0)
            ::syscall(SYS_futex, &out.sequence, FUTEX_WAKE, 1, nullptr, nullptr, 0);
        return true;
    }

    // The next message, whole, in `message` (a copy: the other side cannot change it any more).
    Received receive(std::string& message) {
        if (!boxes_) return detail::receive_on_socket(message);
        Mailbox& in = judge_ ? boxes_->to_judge : boxes_->to_student;
        if (!wait(in)) return Received::closed;
        const std::uint32_t n = in.length.load(std::memory_order_relaxed);  // read once
        if (n == on_socket) return detail::receive_on_socket(message);
        if (n > mailbox_bytes) return Received::too_long;
        if (n == 0) return Received::empty;
        message.assign(in.data, n);
        return Received::message;
    }

private:
    // Until the other side has sent a message (true) or has closed the socket (false): a spin of
    // up to spin_ pauses (an answer that comes that soon is read at once), then sleeps of 10 ms on
    // the futex, looking at the socket between them. The spin adapts, as an adaptive mutex does:
    // it doubles (to 3,000 pauses, tens of microseconds) after a wait that the spin ended, and
    // halves (to 16) after one that had to sleep. On an idle machine the other side answers while
    // this one spins; on a loaded one it is often not running at all, and a fixed spin of 3,000
    // burned processor time on every call: the heaviest grader's test (197,511 round trips) used
    // 0.44 s of CPU in a check alone and 3.7 s in a class graded with -j 2, which is charged to
    // the test's budget (--timeout). Measured with this wait: tests/grading/README.md, "The channel".
    // (sched_yield instead took 10 to 15 s beside two hogs: each yield hands a hog its whole time
    // slice; a socket alone 4.2 s idle.)
    bool wait(Mailbox& in) {
        unsigned k = 0;
        for (; k < spin_; ++k) {
            if (in.sequence.load(std::memory_order_acquire) != seen_) {
                spin_ = spin_ >= max_spin / 2 ? max_spin : 2 * spin_;
                seen_ = in.sequence.load(std::memory_order_acquire);
                return true;
            }
            pause();
        }
        spin_ = spin_ <= 2 * min_spin ? min_spin : spin_ / 2;
        for (;;) {
            in.sleeping.store(1, std::memory_order_seq_cst);
            if (in.sequence.load(std::memory_order_seq_cst) != seen_) break;
            const timespec sleep{0, 10'000'000};
            ::syscall(SYS_futex, &in.sequence, FUTEX_WAIT, seen_, &sleep, nullptr, 0);
            if (in.sequence.load(std::memory_order_acquire) != seen_) break;
            if (detail::socket_closed()) {
                in.sleeping.store(0, std::memory_order_relaxed);
                return false;
            }
        }
        in.sleeping.store(0, std::memory_order_relaxed);
        seen_ = in.sequence.load(std::memory_order_acquire);
        return true;
    }

    static constexpr unsigned max_spin = 3000, min_spin = 16;

    static void pause() {
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#elif defined(__aarch64__)
        __asm__ volatile("yield");
#endif
    }

    bool judge_;
    Mailboxes* boxes_ = nullptr;
    std::uint32_t seen_ = 0;
    unsigned spin_ = max_spin;
};

}  // namespace workbook_remote
