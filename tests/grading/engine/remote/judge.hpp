// The judge's side: the topic's API as the trusted grading process sees it. The judge runs the
// grader's doctest case itself; it holds every expected value and never runs student code.
// Each API function the grader calls (defined in the generated judge_<topic>.cpp) sends the
// call's inputs over the channel to the sandboxed student process and waits for what the
// student's function returned or threw. Meanwhile the student may call the callables the
// grader passed in: each such call comes back as a message, and the grader's own callable runs
// here, in the judge, with the arguments the student gave; its result (or exception) goes back.
// A callable the student returns becomes a proxy here: calling it sends a message, and it runs
// in the student's process.
//
// Everything read from the channel is untrusted: a malformed message, an event out of place, a
// call of a callable the grader did not pass (or of one whose call has returned) or a process
// that ends during a call fails the test with the reason; the grader's CHECKs decide the rest.
#pragma once

#include <deque>
#include <functional>
#include <new>
#include <vector>

#include "channel.hpp"
#include "exceptions.hpp"
#include "wire.hpp"

namespace workbook_remote::judge {

// Thrown to end a test that cannot go on; not a std::exception, and the test fails whatever
// the grader does with it (the problem is kept and reported by workbook_remote_verdict()).
struct abort_test {};

// The generated judge_<topic>.cpp defines these: the API functions' names, by number.
extern const char* const api_names[];
extern const std::uint32_t api_count;

[[noreturn]] void fail(const std::string& why);
bool failed();
const std::string& problem();  // the first problem found in this test case, or empty
std::uint64_t round_trips();   // calls sent and callbacks answered in this test case
std::uint64_t sent_hash();     // of every byte sent to the student's process in this test case
std::uint32_t next_call_number();

// One open call: the grader's callables passed in it, each as an invoker that reads the
// student's arguments from a tag_callback message, calls the callable and answers.
using Invoker = std::function<void(Reader<NoCallables>&)>;
struct Frame {
    std::vector<Invoker> invokers;
};
std::deque<Frame>& frames();  // a deque: a nested call never moves an open frame

Channel& channel();
void send(const std::string& message, const std::string& what);
// The next message, whole; fails the test when the student's process ended or sent no frame.
std::string receive(const std::string& what);

// Calls the grader's callable f with the arguments in the message; answers with its result or
// with the exception that left it.
template <class R, class... A>
Invoker invoker(const std::function<R(A...)>* f) {
    return [f](Reader<NoCallables>& r) {
        typename signature<std::function<R(A...)>>::arguments args;
        try {
            std::apply([&r](auto&... a) { (r.get(a), ...); }, args);
        } catch (const bad_message& e) {
            fail(std::string("the arguments the submission passed to the grader's callable are malformed: ") +
                 e.what());
        } catch (const std::bad_alloc&) {
            fail("the arguments the submission passed to the grader's callable could not be allocated");
        }
        if (r.left() != 0) fail("a call of the grader's callable carries more than its arguments");
        std::string answer;
        NoCallables none;
        Writer<NoCallables> w{answer, none};
        try {
            if constexpr (std::is_void_v<R>) {
                std::apply([f](auto&... a) { (*f)(a...); }, args);
                answer = std::string(1, static_cast<char>(tag_callback_return));
            } else {
                R value = std::apply([f](auto&... a) { return (*f)(a...); }, args);
                answer = std::string(1, static_cast<char>(tag_callback_return));
                w.put(value);
            }
        } catch (const abort_test&) {
            throw;
        } catch (...) {
            const Thrown t = current_exception();
            answer = std::string(1, static_cast<char>(tag_callback_throw));
            write_thrown(w, t);
        }
        send(answer, "the answer of the grader's callable");
    };
}

// The arguments of a call: every callable becomes a slot of the call's frame.
struct ArgumentSink {
    Frame* frame;
    template <class W, class R, class... A>
    void callable(W& w, const std::function<R(A...)>& f) {
        if (!f) return w.u32(no_callable);
        w.u32(static_cast<std::uint32_t>(frame->invokers.size()));
        frame->invokers.push_back(invoker<R, A...>(&f));
    }
};

template <class R, class... A>
std::function<R(A...)> closure(std::uint32_t id);

// A result: every callable in it becomes a proxy of the one the student returned.
struct ResultSource {
    template <class Rd, class R, class... A>
    void callable(Rd& r, std::function<R(A...)>& f) {
        const std::uint32_t id = r.u32();
        if (id == no_callable)
            f = nullptr;
        else
            f = closure<R, A...>(id);
    }
};

template <class R>
R read_result(const std::string& message, const std::string& what) {
    std::size_t at = 1;
    ResultSource source;
    Reader<ResultSource> r{message, at, source};
    try {
        if constexpr (std::is_void_v<R>) {
            if (r.left() != 0) throw bad_message("a function returning nothing returned a value");
            return;
        } else {
            R value{};
            r.get(value);
            if (r.left() != 0) throw bad_message("more than the value");
            return value;
        }
    } catch (const bad_message& e) {
        fail(what + ": the value the submission returned is malformed: " + e.what());
    } catch (const std::bad_alloc&) {
        fail(what + ": the value the submission returned could not be allocated");
    }
}

[[noreturn]] void throw_sent(const std::string& message, const std::string& what);
// A callback: the student calls a callable of an open call's frame.
void answer_callback(const std::string& message, const std::string& what);

// After a call is sent: the student's callbacks until the call ends, then its result.
template <class R>
R finish(const std::string& what) {
    for (;;) {
        const std::string message = receive(what);
        const auto tag = static_cast<unsigned char>(message[0]);
        if (tag == tag_callback)
            answer_callback(message, what);
        else if (tag == tag_return)
            return read_result<R>(message, what);
        else if (tag == tag_throw)
            throw_sent(message, what);
        else if (tag == tag_refuse)
            fail(what + ": " + std::string(message, 1, 2000));
        else
            fail(what + ": the submission's process sent an unexpected message");
    }
}

// Opens a frame for one call and closes it however the call ends.
struct OpenFrame {
    std::uint32_t index;
    OpenFrame() : index(static_cast<std::uint32_t>(frames().size())) { frames().emplace_back(); }
    ~OpenFrame() { frames().pop_back(); }
    OpenFrame(const OpenFrame&) = delete;
    OpenFrame& operator=(const OpenFrame&) = delete;
};

template <class R, class... P>
R call(std::uint32_t function, P... args) {
    if (failed()) throw abort_test{};
    const std::string what = "call " + std::to_string(next_call_number()) + " (" + api_names[function] + ")";
    OpenFrame open;
    std::string message(1, static_cast<char>(tag_call));
    ArgumentSink sink{&frames()[open.index]};
    Writer<ArgumentSink> w{message, sink};
    w.u32(function);
    w.u32(open.index);
    (w.put(args), ...);
    send(message, what);
    return finish<R>(what);
}

template <class R, class... A>
std::function<R(A...)> closure(std::uint32_t id) {
    return [id](A... a) -> R {
        if (failed()) throw abort_test{};
        const std::string what =
            "call " + std::to_string(next_call_number()) + " (of a function the submission returned)";
        OpenFrame open;
        std::string message(1, static_cast<char>(tag_closure));
        NoCallables none;
        Writer<NoCallables> w{message, none};
        w.u32(id);
        w.u32(open.index);
        (w.put(a), ...);
        send(message, what);
        return finish<R>(what);
    };
}

}  // namespace workbook_remote::judge
