// The replay: the topic's API as the trusted verdict process sees it. It never runs student
// code. Each API function the grader calls checks that the call is the next one in the record,
// with the same inputs (their hash), then returns the value the student's function returned,
// or throws what it threw. The grader's callables the student called are called again here
// with the recorded arguments, in the recorded order, so the grader's counters and lists see
// them. Any mismatch, a record that stops early or a malformed record fails the test, with the
// reason; the grader's CHECKs decide the rest. Forging a record therefore means writing down
// values that pass the checks: solving the exercise.
#pragma once

#include <vector>

#include "serial.hpp"

namespace workbook_replay::replay {

// Thrown to end a test whose record does not fit; not a std::exception, and the test fails
// whatever the grader does with it (the problem is kept and reported).
struct abort_replay {};

// The generated replay_<topic>.cpp defines these: the names of the API functions, by number.
extern const char* const api_names[];
extern const std::uint32_t api_count;

[[noreturn]] void fail(const std::string& why);
bool failed();

// The record and where the replay is in it.
struct Cursor {
    const std::string* data;
    std::size_t* at;
};
Cursor cursor();
int next_tag();  // -1 at the end of the record
std::uint32_t call_number();
[[noreturn]] void throw_recorded();  // reads an exception after tag_throw and throws it

struct Source;
template <class R, class... A>
std::function<R(A...)> replaying_closure(std::uint32_t id);

struct Source {
    template <class Rd, class R, class... A>
    void callable(Rd& r, std::function<R(A...)>& f) {
        const std::uint32_t id = r.u32();
        if (id == 0xFFFFFFFFu)
            f = nullptr;
        else
            f = replaying_closure<R, A...>(id);
    }
};

inline Reader<Source> reader() {
    static Source source;
    const Cursor c = cursor();
    return Reader<Source>{*c.data, *c.at, source};
}

template <class T>
T read_value() {
    T value{};
    auto r = reader();
    try {
        r.get(value);
    } catch (const bad_record& e) {
        fail(std::string("the recorded value is malformed: ") + e.what());
    }
    return value;
}

// The head of the next event: its tag, function (or closure) number and inputs' hash.
void expect_head(Tag tag, std::uint32_t id, std::uint64_t hash, const std::string& what);

// Replays one grader callable: reads its recorded arguments and calls it.
using Invoker = std::function<void()>;

template <class R, class... A>
Invoker invoker(const std::function<R(A...)>& f) {
    return [&f]() {
        typename signature<std::function<R(A...)>>::arguments args;
        auto r = reader();
        try {
            std::apply([&r](auto&... a) { (r.get(a), ...); }, args);
        } catch (const bad_record& e) {
            fail(std::string("the recorded arguments of a callback are malformed: ") + e.what());
        }
        if (!f) fail("the submission called a callable the grader did not pass");
        try {
            std::apply([&f](auto&... a) { f(a...); }, args);
        } catch (const abort_replay&) {
            throw;
        } catch (...) {
            // The grader's callable threw into the student's function; what the function did
            // then is in the record.
        }
    };
}

template <class P>
void collect(std::vector<Invoker>& invokers, const P& arg) {
    if constexpr (is_function<std::decay_t<P>>::value) invokers.push_back(invoker(arg));
}

// Callbacks until the call ends; then its result.
template <class R>
R finish(const std::vector<Invoker>& invokers, const std::string& what) {
    for (;;) {
        const int tag = next_tag();
        if (tag == tag_callback) {
            const std::uint32_t slot = reader().u32();
            if (slot >= invokers.size()) fail(what + ": the record calls a callable the grader did not pass");
            invokers[slot]();
        } else if (tag == tag_return) {
            if constexpr (std::is_void_v<R>)
                return;
            else
                return read_value<R>();
        } else if (tag == tag_throw) {
            throw_recorded();
        } else if (tag < 0) {
            fail(what +
                 ": the record stops inside this call (the submission's process ended there: exit, "
                 "a crash or the time limit)");
        } else {
            fail(what + ": the record has an unexpected event inside this call");
        }
    }
}

template <class R, class... P>
R call(std::uint32_t function, P... args) {
    if (failed()) throw abort_replay{};
    const std::string what = "call " + std::to_string(call_number()) + " (" + api_names[function] + ")";
    expect_head(tag_call, function, hash_inputs(args...), what);
    std::vector<Invoker> invokers;
    (collect(invokers, args), ...);
    return finish<R>(invokers, what);
}

template <class R, class... A>
std::function<R(A...)> replaying_closure(std::uint32_t id) {
    return [id](A... a) -> R {
        if (failed()) throw abort_replay{};
        const std::string what = "call " + std::to_string(call_number()) + " (of a function the submission returned)";
        expect_head(tag_closure, id, hash_inputs(a...), what);
        return finish<R>({}, what);
    };
}

}  // namespace workbook_replay::replay
