// tests/harness.h — libtiny3d's own one-header test harness.
//
//   TEST(name) { CHECK(cond); CHECK_EQ(a, b); CHECK_NEAR(a, b, tol); }
//
// Each tests/*_test.cpp is one program; this header provides its main(). A test case
// passes when none of its checks fail; every failed check prints file:line, the
// expression and the values. The program ends with the line "N passed, N failed"
// (counting test cases) and exits non-zero if any failed. An argument runs only the
// test cases whose name contains it.
#pragma once
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace tiny_test {

struct test_case {
    const char *name;
    void (*body)();
};

inline std::vector<test_case> &registry() {
    static std::vector<test_case> cases;
    return cases;
}

inline int &current_failures() {
    static int n = 0;
    return n;
}

struct registrar {
    registrar(const char *name, void (*body)()) { registry().push_back({name, body}); }
};

// Values in messages as an ostream with precision 9 shows them. Numbers go through a few
// non-template functions (one copy per program rather than one per type: the tests
// compile faster); other types through operator<< where they have one.
[[gnu::noinline]] inline std::string show_number(long double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9Lg", v);
    return text;
}
[[gnu::noinline]] inline std::string show_number(long long v) { return std::to_string(v); }
[[gnu::noinline]] inline std::string show_number(unsigned long long v) { return std::to_string(v); }

template <class T>
std::string show(const T &v) {
    using char_like = std::bool_constant<std::is_same_v<T, char> || std::is_same_v<T, signed char> ||
                                         std::is_same_v<T, unsigned char> || std::is_same_v<T, char8_t>>;
    if constexpr (std::is_same_v<T, bool>) {
        return v ? "1" : "0";
    } else if constexpr (std::is_floating_point_v<T>) {
        return show_number(static_cast<long double>(v));
    } else if constexpr (std::is_integral_v<T> && !char_like::value) {
        if constexpr (std::is_signed_v<T>) return show_number(static_cast<long long>(v));
        else return show_number(static_cast<unsigned long long>(v));
    } else if constexpr (std::is_same_v<T, std::string>) {
        return v;
    } else {
        std::ostringstream s;
        s.precision(9);
        if constexpr (requires { s << v; }) {
            s << v;
        } else {
            s << "<value>";
        }
        return s.str();
    }
}

[[gnu::noinline]] inline void fail(const char *file, int line, const std::string &what) {
    ++current_failures();
    std::fprintf(stderr, "%s:%d: FAILED %s\n", file, line, what.c_str());
}

// The failure paths below are out of line, one copy per program: each CHECK site compiles
// to a test and a call (the tests build faster, above all under the sanitizers).
[[gnu::noinline]] inline bool fail_check(const char *file, int line, const char *what) {
    fail(file, line, what);
    return false;
}

[[gnu::noinline]] inline bool fail_check_msg(const char *file, int line, const char *what, const std::string &msg) {
    fail(file, line, std::string(what) + ": " + msg);
    return false;
}

[[gnu::noinline]] inline void fail_eq(const char *file, int line, const char *ea, const char *eb, const std::string &a,
                                      const std::string &b) {
    fail(file, line, std::string("CHECK_EQ(") + ea + ", " + eb + "): " + a + " != " + b);
}

template <class A, class B>
bool check_eq(const char *file, int line, const char *ea, const char *eb, const A &a, const B &b) {
    if (a == b) return true;
    fail_eq(file, line, ea, eb, show(a), show(b));
    return false;
}

[[gnu::noinline]] inline bool fail_near(const char *file, int line, const char *ea, const char *eb, double a, double b,
                                        double tol) {
    char text[160];
    std::snprintf(text, sizeof text, "): %.12g vs %.12g, |diff| = %.12g > tol %.12g", a, b, std::fabs(a - b), tol);
    fail(file, line, std::string("CHECK_NEAR(") + ea + ", " + eb + text);
    return false;
}

inline bool check_near(const char *file, int line, const char *ea, const char *eb, double a, double b,
                       double tol) {
    // NaN never passes: |a - b| <= tol is false when either is NaN.
    if (std::fabs(a - b) <= tol) return true;
    return fail_near(file, line, ea, eb, a, b, tol);
}

inline int run_all(int argc, char **argv) {
    int passed = 0, failed = 0;
    const char *filter = argc > 1 ? argv[1] : nullptr;
    for (const test_case &t : registry()) {
        if (filter && !std::strstr(t.name, filter)) continue;
        current_failures() = 0;
        t.body();
        if (current_failures() == 0) {
            ++passed;
        } else {
            ++failed;
            std::fprintf(stderr, "  test case '%s' failed (%d checks)\n", t.name, current_failures());
        }
    }
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}

}  // namespace tiny_test

#define TINY_TEST_CAT2(a, b) a##b
#define TINY_TEST_CAT(a, b) TINY_TEST_CAT2(a, b)
#define TEST(name)                                                                         \
    static void TINY_TEST_CAT(test_body_, name)();                                         \
    static const tiny_test::registrar TINY_TEST_CAT(test_reg_, name)(#name,                 \
                                                                     &TINY_TEST_CAT(test_body_, name)); \
    static void TINY_TEST_CAT(test_body_, name)()

#define CHECK(cond) ((cond) ? true : tiny_test::fail_check(__FILE__, __LINE__, "CHECK(" #cond ")"))
#define CHECK_MSG(cond, msg) ((cond) ? true : tiny_test::fail_check_msg(__FILE__, __LINE__, "CHECK(" #cond ")", (msg)))
#define CHECK_EQ(a, b) tiny_test::check_eq(__FILE__, __LINE__, #a, #b, (a), (b))
#define CHECK_NEAR(a, b, tol) tiny_test::check_near(__FILE__, __LINE__, #a, #b, (a), (b), (tol))

#ifndef TINY_TEST_NO_MAIN
int main(int argc, char **argv) { return tiny_test::run_all(argc, argv); }
#endif
