// The recorder, linked into the student's test process only. The linker sends the graders'
// calls of the topic's API functions to generated wrappers (-Wl,--wrap=<symbol>), which call
// record::call: it writes the inputs' hash, runs the student's function (__real_<symbol>),
// writes what it returned or threw, and returns it. Calls the student makes of a callable the
// grader passed in are written too (their arguments), and so are the calls of a callable the
// student returns. The record goes to file descriptor 3, a pipe only the harness reads.
//
// Nothing here is trusted: the student's code can write anything to that pipe. The trusted
// replay process takes from the record only values, and the grader's own checks judge them.
#pragma once

#include "serial.hpp"

namespace workbook_replay::record {

void append(const std::string& bytes);  // buffered, flushed at the end of the test case
void write_exception();                 // inside a catch block: what left the call

struct OutputSink;
struct InputSink {
    template <class W, class F>
    void callable(W& w, const F&) {
        w.u32(0xCA11AB1Eu);
    }
};

std::uint32_t next_closure();

template <class R, class... A>
std::function<R(A...)> recording_closure(std::uint32_t id, std::function<R(A...)> f);

// A returned value: every callable in it becomes a recording closure with the next number.
struct OutputSink {
    template <class W, class R, class... A>
    void callable(W& w, const std::function<R(A...)>& f) {
        const std::uint32_t id = next_closure();
        if (f) const_cast<std::function<R(A...)>&>(f) = recording_closure<R, A...>(id, f);
        w.u32(f ? id : 0xFFFFFFFFu);
    }
};

template <class T>
void write_return(const T& value) {
    std::string bytes(1, static_cast<char>(tag_return));
    OutputSink sink;
    Writer<OutputSink> w{bytes, sink};
    w.put(value);
    append(bytes);
}

inline void write_void_return() { append(std::string(1, static_cast<char>(tag_return))); }

template <class... A>
void write_head(Tag tag, std::uint32_t id, const A&... a) {
    std::string bytes(1, static_cast<char>(tag));
    InputSink sink;
    Writer<InputSink> w{bytes, sink};
    w.u32(id);
    w.u64(hash_inputs(a...));
    append(bytes);
}

template <class R, class... A>
std::function<R(A...)> recording_closure(std::uint32_t id, std::function<R(A...)> f) {
    return [id, f](A... a) -> R {
        write_head(tag_closure, id, a...);
        try {
            if constexpr (std::is_void_v<R>) {
                f(std::forward<A>(a)...);
                write_void_return();
            } else {
                R r = f(std::forward<A>(a)...);
                write_return(r);
                return r;
            }
        } catch (...) {
            write_exception();
            throw;
        }
    };
}

// The grader's callable in slot `slot` of a call: the student's calls of it are written down.
template <class R, class... A>
std::function<R(A...)> recording_callback(std::uint32_t slot, const std::function<R(A...)>& f) {
    if (!f) return f;
    return [slot, f](A... a) -> R {
        std::string bytes(1, static_cast<char>(tag_callback));
        InputSink sink;
        Writer<InputSink> w{bytes, sink};
        w.u32(slot);
        (w.put(a), ...);
        append(bytes);
        return f(std::forward<A>(a)...);
    };
}

template <class P>
using stored_t = std::conditional_t<is_function<std::decay_t<P>>::value, std::decay_t<P>, P>;

template <class P>
stored_t<P> pass(P arg, std::uint32_t& slot) {
    if constexpr (is_function<std::decay_t<P>>::value)
        return recording_callback(slot++, arg);
    else
        return static_cast<P>(arg);
}

template <class R, class... P>
R call(std::uint32_t function, R (*real)(P...), P... args) {
    write_head(tag_call, function, args...);
    std::uint32_t slot = 0;
    std::tuple<stored_t<P>...> passed{pass<P>(static_cast<P>(args), slot)...};
    try {
        if constexpr (std::is_void_v<R>) {
            std::apply(real, passed);
            write_void_return();
        } else {
            R r = std::apply(real, passed);
            write_return(r);
            return r;
        }
    } catch (...) {
        write_exception();
        throw;
    }
}

}  // namespace workbook_replay::record
