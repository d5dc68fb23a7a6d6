// The judge's state (judge.hpp): the first problem found in this test case, the number of calls
// made, the open frames; and the verdict that the reporter (tests/grading/engine/reporter.cpp) asks for at the end.
#include "judge.hpp"

#include <doctest/doctest.h>

#include "listener.hpp"

namespace workbook_remote::judge {

namespace {

struct State {
    std::uint32_t calls = 0;  // API calls and calls of returned callables
    std::uint64_t callbacks = 0;
    std::uint64_t sent = 0xcbf29ce484222325ULL;  // FNV-1a of every byte sent to the student
    std::string problem;
    std::deque<Frame> frames;
};

State& state() {
    static State s;
    return s;
}

// Exactly one test case runs per judge process; each starts clean, and at its end the student's
// process is told to end (normally: a process that does not is stopped by the harness).
struct Reset : checks::Listener {
    explicit Reset(const doctest::ContextOptions&) {}
    void test_case_start(const doctest::TestCaseData&) override { state() = State{}; }
    void test_case_end(const doctest::CurrentTestCaseStats&) override {
        channel().send(std::string(1, static_cast<char>(tag_quit)));
    }
};

REGISTER_LISTENER("workbook_judge", 0, Reset);

}  // namespace

void fail(const std::string& why) {
    State& s = state();
    if (s.problem.empty()) s.problem = why;
    throw abort_test{};
}

bool failed() { return !state().problem.empty(); }

const std::string& problem() { return state().problem; }

std::uint64_t round_trips() { return state().calls + state().callbacks; }

std::uint64_t sent_hash() { return state().sent; }

std::uint32_t next_call_number() { return ++state().calls; }

std::deque<Frame>& frames() { return state().frames; }

Channel& channel() {
    static Channel c(true);
    return c;
}

void send(const std::string& message, const std::string& what) {
    for (const char c : message) state().sent = (state().sent ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    if (!channel().send(message))
        fail(what + ": the submission's process is gone (it ended before this call: exit, a crash or the time limit)");
}

std::string receive(const std::string& what) {
    std::string message;
    switch (channel().receive(message)) {
        case Received::message:
            return message;
        case Received::closed:
            fail(what +
                 ": the submission's process ended inside this call (exit(), quick_exit() or _exit() in the "
                 "exercise code, a crash or the time limit)");
        case Received::too_long:
            fail(what + ": the submission's process sent a message over the limit of " +
                 std::to_string(max_message >> 20) + " MiB");
        case Received::empty:
            break;
    }
    fail(what + ": the submission's process sent an empty message");
}

void throw_sent(const std::string& message, const std::string& what) {
    std::size_t at = 1;
    NoCallables none;
    Reader<NoCallables> r{message, at, none};
    Thrown t;
    try {
        t = read_thrown(r);
        if (r.left() != 0) throw bad_message("more than the exception");
    } catch (const bad_message& e) {
        fail(what + ": the exception the submission threw is malformed: " + e.what());
    }
    rethrow(t);
}

void answer_callback(const std::string& message, const std::string& what) {
    std::size_t at = 1;
    NoCallables none;
    Reader<NoCallables> r{message, at, none};
    std::uint32_t frame = 0, slot = 0;
    try {
        frame = r.u32();
        slot = r.u32();
    } catch (const bad_message& e) {
        fail(what + ": a call of the grader's callable is malformed: " + e.what());
    }
    auto& open = frames();
    if (frame >= open.size() || slot >= open[frame].invokers.size())
        fail(what + ": the submission called a callable the grader did not pass in an open call");
    const Invoker invoke = open[frame].invokers[slot];
    ++state().callbacks;
    invoke(r);
}

}  // namespace workbook_remote::judge

// Asked by the verdict reporter (tests/grading/engine/reporter.cpp) when the test case ends: the messages that went
// both ways (each a round trip), for the run's timing log.
extern "C" unsigned long long workbook_remote_round_trips() { return workbook_remote::judge::round_trips(); }

// The same: a hash of every input the judge sent the student's process. Two runs whose inputs
// differ (the graders' seed) give two hashes: how the suite proves every exercise has a test
// on seeded inputs.
extern "C" unsigned long long workbook_remote_sent_hash() { return workbook_remote::judge::sent_hash(); }

// Asked by the verdict reporter (tests/grading/engine/reporter.cpp) when the test case ends: empty, or why the
// test cannot pass although its checks may have.
extern "C" const char* workbook_remote_verdict() {
    static std::string answer;
    answer = workbook_remote::judge::problem();
    return answer.c_str();
}
