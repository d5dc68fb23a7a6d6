// The record of one test: what the student's API functions returned for the grader's inputs,
// written by the student's process (record.cpp) and read back by the trusted replay process
// (replay.cpp). The design: README.md, "Grading a class", and record.hpp and replay.hpp here.
//
// Values are written exactly, as their raw bytes (a double keeps every bit, NaN included), with
// no type tags: both sides know every type from the same generated signatures. The types are
// found by the compiler, not listed by hand: numbers, bool, enums, std::string, Eigen matrices
// (fixed and dynamic), std::vector, std::array, std::function, and any plain struct (an
// aggregate) of these, whose fields are found by the usual structured-binding technique.
//
// Everything read is untrusted: every size is checked against what is left of the record
// before anything is allocated, and a short or malformed record is an error, never a crash.
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

namespace workbook_replay {

// Event tags, one byte each.
enum Tag : unsigned char {
    tag_call = 'C',      // u32 function, u64 hash of the inputs: a call of an API function begins
    tag_return = 'R',    // the value returned by the innermost open call
    tag_throw = 'X',     // the exception that left the innermost open call
    tag_callback = 'B',  // u32 slot, arguments: the student called the grader's callable in that slot
    tag_closure = 'K',   // u32 closure, u64 hash of the arguments: a returned callable is called
    tag_end = 'E',       // the test case ended in the student's process
};

inline constexpr const char* magic = "WBREC1\n";

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

struct bad_record : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline std::uint64_t fnv1a(const std::string& bytes) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    return h;
}

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
            static_assert(sizeof(U) == 0, "a type in the API the record cannot write: extend serial.hpp");
        }
    }
};

// ---- reading ------------------------------------------------------------------------------
template <class Source>
struct Reader {
    const std::string& in;
    std::size_t& at;
    Source& source;

    std::size_t left() const { return in.size() - at; }
    void raw(void* p, std::size_t n) {
        if (n > left()) throw bad_record("the record ends in the middle of a value");
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
        if (n > max_string || n > left()) throw bad_record("a string in the record is too long");
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
            if (b > 1) throw bad_record("a bool in the record is neither 0 nor 1");
            v = b == 1;
        } else if constexpr (std::is_arithmetic_v<U> || std::is_enum_v<U>) {
            raw(&v, sizeof v);
        } else if constexpr (std::is_same_v<U, std::string>) {
            v = string();
        } else if constexpr (is_matrix<U>::value) {
            const std::uint32_t rows = u32(), cols = u32();
            if ((U::RowsAtCompileTime != Eigen::Dynamic && rows != static_cast<std::uint32_t>(U::RowsAtCompileTime)) ||
                (U::ColsAtCompileTime != Eigen::Dynamic && cols != static_cast<std::uint32_t>(U::ColsAtCompileTime)))
                throw bad_record("a fixed-size matrix in the record has the wrong shape");
            if (rows > max_dimension || cols > max_dimension ||
                std::uint64_t(rows) * cols * sizeof(typename U::Scalar) > left())
                throw bad_record("a matrix in the record is larger than the record");
            v.resize(rows, cols);
            for (Eigen::Index k = 0; k < v.size(); ++k) get(v.data()[k]);
        } else if constexpr (is_vector<U>::value) {
            const std::uint32_t n = u32();
            if (n > left()) throw bad_record("a list in the record is longer than the record");
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
            static_assert(sizeof(U) == 0, "a type in the API the record cannot read: extend serial.hpp");
        }
    }
};

// A sink for hashing inputs: a callable counts as its position only.
struct HashSink {
    template <class W, class F>
    void callable(W& w, const F&) {
        w.u32(0xCA11AB1Eu);
    }
};

template <class... A>
std::uint64_t hash_inputs(const A&... a) {
    std::string bytes;
    HashSink sink;
    Writer<HashSink> w{bytes, sink};
    (w.put(a), ...);
    return fnv1a(bytes);
}

// The decayed argument types of a callable's call, as a tuple to read them into.
template <class F>
struct signature;
template <class R, class... A>
struct signature<std::function<R(A...)>> {
    using result = R;
    using arguments = std::tuple<std::decay_t<A>...>;
};

}  // namespace workbook_replay
