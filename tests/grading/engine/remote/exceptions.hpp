// Exceptions across the channel, both ways: the one that left a student's function goes to the
// judge (tag_throw), the one that left a grader's callable goes to the student (tag_callback_throw).
// Each travels as its kind (the most derived standard type), what() and, for
// rigid::not_implemented, the function's name, and is thrown again on the other side as that type.
#pragma once

#include <new>
#include <stdexcept>
#include <string>

#include "rigid/todo.hpp"
#include "wire.hpp"

namespace workbook_remote {

// Inside a catch block: what is being handled.
inline Thrown current_exception() {
    Thrown t;
    try {
        throw;
    } catch (const rigid::not_implemented& e) {
        t = {k_not_implemented, e.what(), e.function_name};
    } catch (const std::invalid_argument& e) {
        t = {k_invalid_argument, e.what(), ""};
    } catch (const std::domain_error& e) {
        t = {k_domain_error, e.what(), ""};
    } catch (const std::length_error& e) {
        t = {k_length_error, e.what(), ""};
    } catch (const std::out_of_range& e) {
        t = {k_out_of_range, e.what(), ""};
    } catch (const std::logic_error& e) {
        t = {k_logic_error, e.what(), ""};
    } catch (const std::range_error& e) {
        t = {k_range_error, e.what(), ""};
    } catch (const std::overflow_error& e) {
        t = {k_overflow_error, e.what(), ""};
    } catch (const std::underflow_error& e) {
        t = {k_underflow_error, e.what(), ""};
    } catch (const std::runtime_error& e) {
        t = {k_runtime_error, e.what(), ""};
    } catch (const std::bad_alloc& e) {
        t = {k_bad_alloc, e.what(), ""};
    } catch (const std::exception& e) {
        t = {k_exception, e.what(), ""};
    } catch (...) {
        t = {k_unknown, "", ""};
    }
    return t;
}

template <class W>
void write_thrown(W& w, const Thrown& t) {
    const unsigned char k = t.kind;
    w.raw(&k, 1);
    w.string(t.what);
    w.string(t.extra);
}

template <class R>
Thrown read_thrown(R& r) {
    Thrown t;
    unsigned char k = 0;
    r.raw(&k, 1);
    if (k < k_not_implemented || k > k_unknown) throw bad_message("an exception of an unknown kind");
    t.kind = static_cast<Kind>(k);
    t.what = r.string();
    t.extra = r.string();
    return t;
}

// An exception of a kind the other side does not know: not a std::exception, as it was thrown.
struct unknown_exception {};
struct other_exception : std::exception {
    explicit other_exception(std::string w) : what_(std::move(w)) {}
    const char* what() const noexcept override { return what_.c_str(); }
    std::string what_;
};

[[noreturn]] inline void rethrow(const Thrown& t) {
    switch (t.kind) {
        case k_not_implemented:
            throw rigid::not_implemented(t.extra);
        case k_invalid_argument:
            throw std::invalid_argument(t.what);
        case k_domain_error:
            throw std::domain_error(t.what);
        case k_length_error:
            throw std::length_error(t.what);
        case k_out_of_range:
            throw std::out_of_range(t.what);
        case k_logic_error:
            throw std::logic_error(t.what);
        case k_range_error:
            throw std::range_error(t.what);
        case k_overflow_error:
            throw std::overflow_error(t.what);
        case k_underflow_error:
            throw std::underflow_error(t.what);
        case k_runtime_error:
            throw std::runtime_error(t.what);
        case k_bad_alloc:
            throw std::bad_alloc();
        case k_exception:
            throw other_exception(t.what);
        case k_unknown:
            break;
    }
    throw unknown_exception{};
}

}  // namespace workbook_remote
