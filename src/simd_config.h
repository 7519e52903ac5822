// simd_config.h — internal: the one switch for which instruction-set paths are compiled.
// Every SIMD kernel and every intrinsic in the library (and the tests that compare a SIMD
// kernel with its portable reference) is guarded by these macros, never by the compiler's
// own (__SSE2__, __AVX512F__ …):
//   TINY3D_SSE2    SSE2 kernels: the compiler targets SSE2 (every x86-64 build does).
//   TINY3D_AVX2    AVX2 kernels (the multisample fill, the 1-sample narrow fill), compiled
//                  and checked at run time as TINY3D_AVX512's are, for CPUs without AVX-512.
//   TINY3D_AVX512  AVX-512 kernels: x86-64 with GCC or clang, compiled in their own files
//                  inside a target region (the rest of the build stays baseline) and run
//                  only where the CPU check at run time finds AVX-512 F/VL/DQ/BW.
// Defining TINY3D_PORTABLE (-DTINY3D_PORTABLE; `make test-portable` builds everything so
// into build/portable/) turns every path off: each kernel family then runs its portable
// reference, which is what the SIMD kernels are tested against.
#ifndef TINY3D_SIMD_CONFIG_H
#define TINY3D_SIMD_CONFIG_H

#ifndef TINY3D_PORTABLE
#ifdef __SSE2__
#define TINY3D_SSE2 1
#endif
#if defined(__x86_64__) && defined(__GNUC__)  // clang defines __GNUC__ too
#define TINY3D_AVX512 1
#define TINY3D_AVX2 1
#endif
#endif

#ifdef TINY3D_AVX2
namespace tiny3d::detail {
// Whether this CPU runs the AVX2 kernels.
inline bool cpu_has_avx2() { return __builtin_cpu_supports("avx2"); }
}  // namespace tiny3d::detail
#endif

#ifdef TINY3D_AVX512
namespace tiny3d::detail {
// Whether this CPU runs the AVX-512 kernels (F, VL, DQ and BW).
inline bool cpu_has_avx512() {
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
}
}  // namespace tiny3d::detail
#endif

#endif
