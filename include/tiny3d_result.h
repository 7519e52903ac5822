// tiny3d_result.h — how libtiny3d reports failure.
//
// The library never prints, exits, aborts or throws across its API for bad input.
// A function that can fail returns tiny3d::status (success or an error) or
// tiny3d::result<T> (a value or an error). An error names the file (if any), the
// place in it (1-based line for text, byte offset for binary data) and the problem;
// message() formats it as "file:line: reason" / "file: byte N: reason" / "reason".
#ifndef TINY3D_RESULT_H
#define TINY3D_RESULT_H

// ---- C and C++ from one header ----------------------------------------------------------
// The report's API (canvas.h, math3d.h, renderer.h, lighting.h, animation.h) compiles as C11
// and C++20. Its functions have C linkage: TINY3D_C_BEGIN / TINY3D_C_END wrap them in
// extern "C" { } under C++ and are empty in C. TINY3D_DEFAULT(v) gives a struct member the
// default initialiser `= v` in C++ (so `vec3_t v = {0};` stays warning-free under -Wextra)
// and nothing in C; the layout is the same in both languages. Everything else in this file
// (status, result) is C++ only.
#if defined(__cplusplus) && __cplusplus < 202002L
#error "libtiny3d's C++ API needs C++20: compile with -std=c++20 (C programs: any C11 compiler)"
#endif
#ifdef __cplusplus
#define TINY3D_C_BEGIN extern "C" {
#define TINY3D_C_END }
#define TINY3D_DEFAULT(...) = __VA_ARGS__
#else
#include <stdbool.h>
#include <stddef.h>
#define TINY3D_C_BEGIN
#define TINY3D_C_END
#define TINY3D_DEFAULT(...)
#endif

#ifdef __cplusplus
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace tiny3d {

struct error {
    std::string file;        // path of the file concerned, empty if none
    long line = 0;           // 1-based line in a text file, 0 = not applicable
    long byte_offset = -1;   // byte offset in a binary file, -1 = not applicable
    std::string reason;      // what was wrong, in words

    std::string message() const {
        std::string m;
        if (!file.empty()) {
            m = file;
            if (line > 0) m += ":" + std::to_string(line);
            else if (byte_offset >= 0) m += ": byte " + std::to_string(byte_offset);
            m += ": ";
        } else if (line > 0) {
            m = "line " + std::to_string(line) + ": ";
        }
        return m + reason;
    }
};

// Success, or an error.
class status {
public:
    status() = default;  // success
    status(error e) : err_(std::move(e)) {}
    bool ok() const { return !err_.has_value(); }
    explicit operator bool() const { return ok(); }
    const error &err() const { return *err_; }             // precondition: !ok()
    std::string message() const { return ok() ? std::string("ok") : err_->message(); }

private:
    std::optional<error> err_;
};

// A value of type T, or an error.
template <class T>
class result {
public:
    result(T value) : v_(std::in_place_index<0>, std::move(value)) {}
    result(error e) : v_(std::in_place_index<1>, std::move(e)) {}
    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }
    T &value() & { return std::get<0>(v_); }                // precondition: ok()
    const T &value() const & { return std::get<0>(v_); }
    T &&value() && { return std::get<0>(std::move(v_)); }
    T *operator->() { return &value(); }
    const T *operator->() const { return &value(); }
    T &operator*() & { return value(); }
    const T &operator*() const & { return value(); }
    const error &err() const { return std::get<1>(v_); }    // precondition: !ok()
    std::string message() const { return ok() ? std::string("ok") : err().message(); }
    status to_status() const { return ok() ? status() : status(err()); }

private:
    std::variant<T, error> v_;
};

}  // namespace tiny3d

#endif  // __cplusplus

#endif
