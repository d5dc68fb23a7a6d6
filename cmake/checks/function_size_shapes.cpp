// The shapes of function the function-size check must measure as clang-tidy does (its self-test,
// cmake/checks/function_size.cmake, compares the two on every function here): a signature over several
// lines, members defined in their class, a constructor whose initializers hold braces, braces in
// strings, characters, raw strings and comments, a lambda inside a function, templates and
// operators. Compiled by clang-tidy only, never built.
#include <string>
#include <vector>

namespace shapes {

int plain(int x) {
    x += 1;
    return x;
}

int wrapped_signature(int first_argument_with_a_long_name, int second_argument_with_a_long_name,
                      int third_argument_with_a_long_name) {
    return first_argument_with_a_long_name + second_argument_with_a_long_name + third_argument_with_a_long_name;
}

std::vector<int> defaulted_braces(const std::vector<int>& v = {}, int w = int{2}) {
    std::vector<int> out = v;
    out.push_back(w);
    return out;
}

std::string braces_in_text() {
    std::string s = "}}} not a brace {";
    s += '}';
    s += R"gp(set title "{x}" }
plot '-' using 1:2 }
)gp";
    /* } a comment
       with a brace { */
    return s;  // } and one here
}

int holds_a_lambda(int x) {
    const auto twice = [](int y) {
        int z = y;
        z += y;
        return z;
    };
    const int n = 1'000;
    return twice(x) + n;
}

template <class T>
T templated(T a, T b) {
    T c = a;
    c += b;
    return c;
}

struct Point {
    double x = 0, y = 0;
    Point(double a, double b) : x{a}, y{b} {
        x += 0;
        y += 0;
    }
    double norm2() const {
        const double s = x * x;
        return s + y * y;
    }
    bool operator==(const Point& o) const {
        const bool same_x = x == o.x;
        return same_x && y == o.y;
    }
    void one_line() { x = 1; }
};

double defined_outside(const Point& p);

double defined_outside(const Point& p) {
    double s = p.x;
    s += p.y;
    return s;
}

}  // namespace shapes
