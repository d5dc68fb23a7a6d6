// The wire between the two processes of a graded test (README: "Grading a class"): the
// trusted judge, which runs the grader's doctest case, and the sandboxed student process,
// which runs only the student's functions. Both sides are generated from the same API
// signatures (tests/grading/engine/api.cpp), so values travel as their raw bytes with no type tags:
// a double keeps every bit, NaN included. The types are found by the compiler, not listed by
// hand: numbers, bool, enums, std::string, Eigen matrices (fixed and dynamic), std::vector,
// std::array, std::function, and any plain struct (an aggregate) of these, whose fields are
// found by the usual structured-binding technique.
//
// Everything read is untrusted: every size is checked in bytes against what is left of the
// message before anything is allocated, and a short or malformed message is an error
// (bad_message), never a crash.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace workbook_remote {

// A message is a frame: u32 length, then that many bytes, the first of them its tag.
enum Tag : unsigned char {
    // judge -> student
    tag_call = 'C',             // u32 function, u32 frame, arguments: call an API function
    tag_closure = 'K',          // u32 closure, u32 frame, arguments: call a callable the student returned
    tag_callback_return = 'r',  // the value the grader's callable returned
    tag_callback_throw = 'x',   // the exception that left the grader's callable
    tag_quit = 'Q',             // the test case is over: end normally
    // student -> judge
    tag_return = 'R',    // the value returned by the innermost open call
    tag_throw = 'X',     // the exception that left the innermost open call
    tag_callback = 'B',  // u32 frame, u32 slot, arguments: the student calls a callable the grader passed
    tag_refuse = 'F',    // string: the student's runtime refuses what the submission did (why)
};

inline constexpr std::uint32_t max_message = 256u << 20;   // one frame
inline constexpr std::uint32_t no_callable = 0xFFFFFFFFu;  // an empty std::function

// Exceptions, by the most derived standard type they are (rigid::not_implemented first).
enum Kind : unsigned char {
    k_not_implemented = 1,
    k_invalid_argument,
    k_domain_error,
    k_length_error,
    k_out_of_range,
    k_logic_error,
    k_range_error,
    k_overflow_error,
    k_underflow_error,
    k_runtime_error,
    k_bad_alloc,
    k_exception,
    k_unknown,
};

inline constexpr std::uint32_t max_string = 1u << 16;     // an exception's message, a string field
inline constexpr std::uint32_t max_dimension = 1u << 24;  // rows or columns of a matrix

struct bad_message : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---- type traits -------------------------------------------------------------------------
template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};
template <class T>
struct is_array : std::false_type {};
template <class T, std::size_t N>
struct is_array<std::array<T, N>> : std::true_type {};
template <class T>
struct is_function : std::false_type {};
template <class R, class... A>
struct is_function<std::function<R(A...)>> : std::true_type {};
template <class T>
struct is_matrix : std::false_type {};
template <class S, int R, int C, int O, int MR, int MC>
struct is_matrix<Eigen::Matrix<S, R, C, O, MR, MC>> : std::true_type {};

// The fields of a plain struct, without naming them: count how many initialisers T{...} takes,
// then bind that many with a structured binding.
struct any_field {
    template <class U>
    operator U() const;
};
template <class T, class... A>
constexpr auto initialisable(int) -> decltype(T{std::declval<A>()...}, true) {
    return true;
}
template <class T, class... A>
constexpr bool initialisable(...) {
    return false;
}
template <class T, class... A>
constexpr std::size_t field_count() {
    if constexpr (sizeof...(A) > 24)
        return 0;  // more than this: not supported (see fields())
    else if constexpr (!initialisable<T, A..., any_field>(0))
        return sizeof...(A);
    else
        return field_count<T, A..., any_field>();
}

#define WB_FIELDS(N, ...)                          \
    if constexpr (n == N) {                        \
        auto& [__VA_ARGS__] = t;                   \
        return std::forward_as_tuple(__VA_ARGS__); \
    } else
template <class T>
auto fields(T& t) {
    constexpr std::size_t n = field_count<std::remove_const_t<T>>();
    static_assert(n >= 1 && n <= 24, "a struct in the API with no field or more than 24: extend fields()");
    WB_FIELDS(1, a1)
    WB_FIELDS(2, a1, a2)
    WB_FIELDS(3, a1, a2, a3)
    WB_FIELDS(4, a1, a2, a3, a4)
    WB_FIELDS(5, a1, a2, a3, a4, a5)
    WB_FIELDS(6, a1, a2, a3, a4, a5, a6)
    WB_FIELDS(7, a1, a2, a3, a4, a5, a6, a7)
    WB_FIELDS(8, a1, a2, a3, a4, a5, a6, a7, a8)
    WB_FIELDS(9, a1, a2, a3, a4, a5, a6, a7, a8, a9)
    WB_FIELDS(10, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10)
    WB_FIELDS(11, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11)
    WB_FIELDS(12, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12)
    WB_FIELDS(13, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13)
    WB_FIELDS(14, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14)
    WB_FIELDS(15, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15)
    WB_FIELDS(16, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16)
    WB_FIELDS(17, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17)
    WB_FIELDS(18, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18)
    WB_FIELDS(19, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19)
    WB_FIELDS(20, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20)
    WB_FIELDS(21, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21)
    WB_FIELDS(22, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22)
    WB_FIELDS(23, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22,
              a23)
    WB_FIELDS(24, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22,
              a23, a24)
    return std::tuple<>{};
}
#undef WB_FIELDS

// ---- writing ------------------------------------------------------------------------------
// A Sink decides what a callable becomes: `callable(f)` is called for every std::function met
// on the way (the grader's callable passed in, or one the student returns).
template <class Sink>
struct Writer {
    std::string& out;
    Sink& sink;

    void raw(const void* p, std::size_t n) { out.append(static_cast<const char*>(p), n); }
    void u32(std::uint32_t x) { raw(&x, sizeof x); }
    void u64(std::uint64_t x) { raw(&x, sizeof x); }
    void string(const std::string& s) {
        const std::size_t n = s.size() < max_string ? s.size() : max_string;
        u32(static_cast<std::uint32_t>(n));
        raw(s.data(), n);
    }

    template <class T>
    void put(const T& v) {
        using U = std::remove_cv_t<T>;
        if constexpr (std::is_same_v<U, bool>) {
            const unsigned char b = v ? 1 : 0;
            raw(&b, 1);
        } else if constexpr (std::is_arithmetic_v<U> || std::is_enum_v<U>) {
            raw(&v, sizeof v);
        } else if constexpr (std::is_same_v<U, std::string>) {
            string(v);
        } else if constexpr (is_matrix<U>::value) {
            u32(static_cast<std::uint32_t>(v.rows()));
            u32(static_cast<std::uint32_t>(v.cols()));
            for (Eigen::Index k = 0; k < v.size(); ++k) put(v.data()[k]);
        } else if constexpr (is_vector<U>::value) {
            u32(static_cast<std::uint32_t>(v.size()));
            for (const auto& x : v) put(x);
        } else if constexpr (is_array<U>::value) {
            for (const auto& x : v) put(x);
        } else if constexpr (is_function<U>::value) {
            sink.callable(*this, v);
        } else if constexpr (std::is_aggregate_v<U>) {
            std::apply([this](const auto&... f) { (put(f), ...); }, fields(const_cast<U&>(v)));
        } else {
            static_assert(sizeof(U) == 0, "a type in the API the wire cannot write: extend wire.hpp");
        }
    }
};

// ---- sizes -------------------------------------------------------------------------------
// The fewest bytes a value of type T takes on the wire: a list of n elements needs at least
// n * wire_min<T>() bytes, which is checked before anything is allocated for it.
template <class T>
constexpr std::size_t wire_min();
template <class Tuple, std::size_t... I>
constexpr std::size_t fields_min(std::index_sequence<I...>) {
    return (std::size_t(0) + ... + wire_min<std::remove_reference_t<std::tuple_element_t<I, Tuple>>>());
}
template <class T>
constexpr std::size_t wire_min() {
    using U = std::remove_cv_t<T>;
    if constexpr (std::is_same_v<U, bool>)
        return 1;
    else if constexpr (std::is_arithmetic_v<U> || std::is_enum_v<U>)
        return sizeof(U);
    else if constexpr (std::is_same_v<U, std::string>)
        return 4;
    else if constexpr (is_matrix<U>::value)
        return 8 + (U::SizeAtCompileTime == Eigen::Dynamic ? 0 : U::SizeAtCompileTime * sizeof(typename U::Scalar));
    else if constexpr (is_vector<U>::value)
        return 4;
    else if constexpr (is_array<U>::value)
        return std::tuple_size_v<U> * wire_min<typename U::value_type>();
    else if constexpr (is_function<U>::value)
        return 4;
    else if constexpr (std::is_aggregate_v<U>)
        return fields_min<decltype(fields(std::declval<U&>()))>(
            std::make_index_sequence<std::tuple_size_v<decltype(fields(std::declval<U&>()))>>{});
    else
        return 1;
}

// ---- reading ------------------------------------------------------------------------------
template <class Source>
struct Reader {
    const std::string& in;
    std::size_t& at;
    Source& source;

    std::size_t left() const { return in.size() - at; }
    void raw(void* p, std::size_t n) {
        if (n > left()) throw bad_message("the message ends in the middle of a value");
        std::memcpy(p, in.data() + at, n);
        at += n;
    }
    std::uint32_t u32() {
        std::uint32_t x;
        raw(&x, sizeof x);
        return x;
    }
    std::uint64_t u64() {
        std::uint64_t x;
        raw(&x, sizeof x);
        return x;
    }
    std::string string() {
        const std::uint32_t n = u32();
        if (n > max_string || n > left()) throw bad_message("a string in the message is longer than the message");
        std::string s(in.data() + at, n);
        at += n;
        return s;
    }

    template <class T>
    void get(T& v) {
        using U = std::remove_cv_t<T>;
        if constexpr (std::is_same_v<U, bool>) {
            unsigned char b;
            raw(&b, 1);
            if (b > 1) throw bad_message("a bool in the message is neither 0 nor 1");
            v = b == 1;
        } else if constexpr (std::is_arithmetic_v<U> || std::is_enum_v<U>) {
            raw(&v, sizeof v);
        } else if constexpr (std::is_same_v<U, std::string>) {
            v = string();
        } else if constexpr (is_matrix<U>::value) {
            const std::uint32_t rows = u32(), cols = u32();
            if ((U::RowsAtCompileTime != Eigen::Dynamic && rows != static_cast<std::uint32_t>(U::RowsAtCompileTime)) ||
                (U::ColsAtCompileTime != Eigen::Dynamic && cols != static_cast<std::uint32_t>(U::ColsAtCompileTime)))
                throw bad_message("a fixed-size matrix in the message has the wrong shape");
            if (rows > max_dimension || cols > max_dimension ||
                std::uint64_t(rows) * cols * sizeof(typename U::Scalar) > left())
                throw bad_message("a matrix in the message is larger than the message");
            v.resize(rows, cols);
            for (Eigen::Index k = 0; k < v.size(); ++k) get(v.data()[k]);
        } else if constexpr (is_vector<U>::value) {
            // In bytes, before the allocation: n elements take at least n * wire_min bytes.
            const std::uint32_t n = u32();
            if (std::uint64_t(n) * wire_min<typename U::value_type>() > left())
                throw bad_message("a list in the message is longer than the message");
            v.clear();
            v.resize(n);
            for (auto& x : v) get(x);
        } else if constexpr (is_array<U>::value) {
            for (auto& x : v) get(x);
        } else if constexpr (is_function<U>::value) {
            source.callable(*this, v);
        } else if constexpr (std::is_aggregate_v<U>) {
            std::apply([this](auto&... f) { (get(f), ...); }, fields(v));
        } else {
            static_assert(sizeof(U) == 0, "a type in the API the wire cannot read: extend wire.hpp");
        }
    }
};

// Where no callable may travel (the arguments of a callback, a callback's result, the arguments
// of a returned callable): a type with a std::function there stops the build, naming it.
struct NoCallables {
    template <class W, class F>
    void callable(W&, F&) {
        static_assert(sizeof(F) == 0, "a callable inside a callback's arguments or result: extend wire.hpp");
    }
};

// The decayed argument types of a callable's call, as a tuple to read them into.
template <class F>
struct signature;
template <class R, class... A>
struct signature<std::function<R(A...)>> {
    using result = R;
    using arguments = std::tuple<std::decay_t<A>...>;
};

// Exceptions travel as their kind (the most derived standard type, rigid::not_implemented
// first), what() and, for not_implemented, the function's name.
struct Thrown {
    Kind kind = k_unknown;
    std::string what, extra;
};

}  // namespace workbook_remote
