// The marker every exercise stub calls until the student writes the function.
//
// It throws rigid::not_implemented, which is deliberately not a std::invalid_argument:
// a test that expects a function to reject bad input cannot pass on an untouched stub.
#pragma once

#include <stdexcept>
#include <string>

namespace rigid {

struct not_implemented : std::logic_error {
    explicit not_implemented(const std::string& function)
        : std::logic_error("not implemented yet: " + function + " (see exercises/hints.md, section '" + function +
                           "')"),
          function_name(function) {}
    std::string function_name;
};

[[noreturn]] inline void todo(const char* function) { throw not_implemented(function); }

}  // namespace rigid
