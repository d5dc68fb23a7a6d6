// The student's side: the process that runs the student's functions for the judge, in the
// sandbox. It holds the student's object, the provided code, the reference libraries of the
// topic's dependencies, the generated serve_<topic>.cpp (the table of API functions) and this
// runtime; no grader, no doctest, no expected value. It reads calls from the channel, runs the
// student's function with the arguments sent, and sends back its result or exception. A
// callable the grader passed becomes a proxy here that asks the judge to run it; a callable
// the student returns is kept here, by number, for the judge to call. The student's state
// (a static cache) lives on between the calls of one test.
//
// Nothing here is trusted by the judge: the student's code can write anything to the channel.
#pragma once

#include <functional>
#include <mutex>
#include <tuple>
#include <type_traits>
#include <vector>

#include "channel.hpp"
#include "exceptions.hpp"
#include "wire.hpp"

namespace workbook_remote::serve {

// The generated serve_<topic>.cpp: one entry per API function, by the judge's numbering.
using Entry = void (*)(const std::string& message, std::size_t at, std::uint32_t frame);
extern const Entry api_table[];
extern const std::uint32_t api_count;

Channel& channel();
// One lock for the channel: a callback from another thread of the student's waits its turn.
std::recursive_mutex& channel_lock();

[[noreturn]] void refuse(const std::string& why);  // tells the judge why, then ends the process
void send(const std::string& message);             // ends the process when the judge is gone
std::string receive();                             // the same
bool frame_open(std::uint32_t frame, std::uint64_t generation);
std::uint64_t frame_generation(std::uint32_t frame);
// A message that is not the answer being waited for: a call (nested in a callback) is served.
void serve_nested(const std::string& message);

// The grader's callable in slot `slot` of call `frame`: calling it asks the judge to run it and
// waits for its result, serving the calls the judge makes meanwhile. Refused once its call has
// returned: the callable no longer exists on the judge's side.
template <class R, class... A>
std::function<R(A...)> callback(std::uint32_t frame, std::uint32_t slot) {
    const std::uint64_t generation = frame_generation(frame);
    return [frame, slot, generation](A... a) -> R {
        std::lock_guard<std::recursive_mutex> lock(channel_lock());
        if (!frame_open(frame, generation))
            refuse(
                "the submission called a callable the grader passed in an earlier call, after that call had returned");
        std::string message(1, static_cast<char>(tag_callback));
        NoCallables none;
        Writer<NoCallables> w{message, none};
        w.u32(frame);
        w.u32(slot);
        (w.put(a), ...);
        send(message);
        for (;;) {
            const std::string answer = receive();
            const auto tag = static_cast<unsigned char>(answer[0]);
            std::size_t at = 1;
            Reader<NoCallables> r{answer, at, none};
            if (tag == tag_callback_return) {
                if constexpr (std::is_void_v<R>) {
                    return;
                } else {
                    R value{};
                    r.get(value);
                    return value;
                }
            }
            if (tag == tag_callback_throw) rethrow(read_thrown(r));
            serve_nested(answer);
        }
    };
}

// The arguments of a call: a callable slot becomes a callback proxy.
struct ArgumentSource {
    std::uint32_t frame;
    template <class Rd, class R, class... A>
    void callable(Rd& r, std::function<R(A...)>& f) {
        const std::uint32_t slot = r.u32();
        if (slot == no_callable)
            f = nullptr;
        else
            f = callback<R, A...>(frame, slot);
    }
};

// A callable the student returns: kept here, by number.
using Closure = std::function<void(const std::string& message, std::size_t at, std::uint32_t frame)>;
std::uint32_t keep(Closure c);

template <class T>
void answer(const T& value);

template <class R, class... A>
Closure closure_entry(std::function<R(A...)> g) {
    return [g](const std::string& message, std::size_t at, std::uint32_t) {
        NoCallables none;
        Reader<NoCallables> r{message, at, none};
        std::tuple<std::decay_t<A>...> args;
        std::apply([&r](auto&... a) { (r.get(a), ...); }, args);
        try {
            if constexpr (std::is_void_v<R>) {
                std::apply(g, args);
                send(std::string(1, static_cast<char>(tag_return)));
            } else {
                answer(std::apply(g, args));
            }
        } catch (...) {
            std::string m(1, static_cast<char>(tag_throw));
            Writer<NoCallables> w{m, none};
            write_thrown(w, current_exception());
            send(m);
        }
    };
}

struct ResultSink {
    template <class W, class R, class... A>
    void callable(W& w, const std::function<R(A...)>& g) {
        w.u32(g ? keep(closure_entry<R, A...>(g)) : no_callable);
    }
};

template <class T>
void answer(const T& value) {
    std::string message(1, static_cast<char>(tag_return));
    ResultSink sink;
    Writer<ResultSink> w{message, sink};
    w.put(value);
    send(message);
}

// The entry of one API function: reads its arguments, runs the student's function, answers.
template <class R, class... P>
void serve_call(R (*f)(P...), const std::string& message, std::size_t at, std::uint32_t frame) {
    static_assert(((!std::is_lvalue_reference_v<P> || std::is_const_v<std::remove_reference_t<P>>)&&...),
                  "an API function with a non-const reference parameter: the wire cannot send it back");
    ArgumentSource source{frame};
    Reader<ArgumentSource> r{message, at, source};
    std::tuple<std::decay_t<P>...> args;
    std::apply([&r](auto&... a) { (r.get(a), ...); }, args);
    try {
        if constexpr (std::is_void_v<R>) {
            std::apply(f, args);
            send(std::string(1, static_cast<char>(tag_return)));
        } else {
            answer(std::apply(f, args));
        }
    } catch (...) {
        std::string m(1, static_cast<char>(tag_throw));
        NoCallables none;
        Writer<NoCallables> w{m, none};
        write_thrown(w, current_exception());
        send(m);
    }
}

}  // namespace workbook_remote::serve
