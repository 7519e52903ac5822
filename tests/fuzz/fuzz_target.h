// tests/fuzz/fuzz_target.h — the common body of the libFuzzer targets: run a check from
// fuzz_checks.h on the input and stop (with the reason on stderr) when it is violated, so
// libFuzzer records the input as a crash.
#ifndef TINY3D_FUZZ_TARGET_H
#define TINY3D_FUZZ_TARGET_H

#include <cstdio>
#include <cstdlib>
#include <string>

inline void fuzz_require(const std::string &violation) {
    if (violation.empty()) return;
    std::fprintf(stderr, "fuzz check failed: %s\n", violation.c_str());
    std::abort();
}

#endif
