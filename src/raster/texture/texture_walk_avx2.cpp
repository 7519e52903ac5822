// texture_walk_avx2.cpp — the anisotropic tap walk (texture_walk.h) eight taps per 256-bit
// register: positions, floors, weights and wrapped texel indices as vectors, each tap's four
// bilinear corners fetched by gathers (inactive lanes gather texel 0 and add nothing). The
// same operations in the same order as walk_taps_portable, lane by lane, and the same final
// sum: its bits (tests/kernel_table_test.cpp). Inside avx2_region_open.inc's target region
// (no FMA contraction); run only where kernels_run.
#include "texture_walk.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX2
#include <immintrin.h>

#include "../../avx2_region_open.inc"

namespace tiny3d::detail {
namespace {

// ⌊t⌋ of each lane as the reference's floor_index: truncation, then one down where t is
// below it (the compare's all-ones lanes are −1).
inline __m256i floor_lanes(__m256 t) {
    const __m256i i = _mm256_cvttps_epi32(t);
    return _mm256_add_epi32(i, _mm256_castps_si256(_mm256_cmp_ps(t, _mm256_cvtepi32_ps(i), _CMP_LT_OQ)));
}

// One wrap by n of indices in [−n, 2n): the reference's address() with repeat.
inline __m256i wrap_lanes(__m256i i, __m256i n) {
    const __m256i below = _mm256_cmpgt_epi32(_mm256_setzero_si256(), i);
    const __m256i beyond = _mm256_cmpgt_epi32(i, _mm256_sub_epi32(n, _mm256_set1_epi32(1)));
    return _mm256_sub_epi32(_mm256_add_epi32(i, _mm256_and_si256(below, n)), _mm256_and_si256(beyond, n));
}

// The next index after a wrapped one, wrapped: address(i + 1) for i in [−n, 2n − 1).
inline __m256i next_lanes(__m256i wrapped, __m256i n) {
    const __m256i next = _mm256_add_epi32(wrapped, _mm256_set1_epi32(1));
    return _mm256_andnot_si256(_mm256_cmpeq_epi32(next, n), next);
}

}  // namespace

float walk_taps_avx2(const tap_walk &w) {
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i width = _mm256_set1_epi32(w.width), height = _mm256_set1_epi32(w.height);
    const __m256 fx0 = _mm256_set1_ps(w.fx0), fy0 = _mm256_set1_ps(w.fy0);
    const __m256 sx = _mm256_set1_ps(w.sx), sy = _mm256_set1_ps(w.sy);
    __m256 sum = _mm256_setzero_ps();
    for (int base = 0; base < w.taps; base += 8) {
        const __m256i tap = _mm256_add_epi32(_mm256_set1_epi32(base), lane);
        const __m256i active = _mm256_cmpgt_epi32(_mm256_set1_epi32(w.taps), tap);
        const __m256 k = _mm256_cvtepi32_ps(tap);  // exact: tap < 2^24
        const __m256 fx = _mm256_add_ps(fx0, _mm256_mul_ps(k, sx)), fy = _mm256_add_ps(fy0, _mm256_mul_ps(k, sy));
        const __m256i i0 = floor_lanes(fx), j0 = floor_lanes(fy);
        const __m256 tx = _mm256_sub_ps(fx, _mm256_cvtepi32_ps(i0)), ty = _mm256_sub_ps(fy, _mm256_cvtepi32_ps(j0));
        const __m256i left = wrap_lanes(i0, width), right = next_lanes(left, width);
        const __m256i top_row = wrap_lanes(j0, height);
        const __m256i row0 = _mm256_and_si256(_mm256_mullo_epi32(top_row, width), active);
        const __m256i row1 = _mm256_and_si256(_mm256_mullo_epi32(next_lanes(top_row, height), width), active);
        const __m256i l = _mm256_and_si256(left, active), r = _mm256_and_si256(right, active);
        const __m256 t00 = _mm256_i32gather_ps(w.texels, _mm256_add_epi32(row0, l), 4);
        const __m256 t01 = _mm256_i32gather_ps(w.texels, _mm256_add_epi32(row0, r), 4);
        const __m256 t10 = _mm256_i32gather_ps(w.texels, _mm256_add_epi32(row1, l), 4);
        const __m256 t11 = _mm256_i32gather_ps(w.texels, _mm256_add_epi32(row1, r), 4);
        const __m256 top = _mm256_add_ps(t00, _mm256_mul_ps(_mm256_sub_ps(t01, t00), tx));
        const __m256 bottom = _mm256_add_ps(t10, _mm256_mul_ps(_mm256_sub_ps(t11, t10), tx));
        const __m256 value = _mm256_add_ps(top, _mm256_mul_ps(_mm256_sub_ps(bottom, top), ty));
        sum = _mm256_add_ps(sum, _mm256_and_ps(value, _mm256_castsi256_ps(active)));
    }
    // ((0 + 4) + (2 + 6)) + ((1 + 5) + (3 + 7)), as the reference.
    const __m128 half = _mm_add_ps(_mm256_castps256_ps128(sum), _mm256_extractf128_ps(sum, 1));
    const __m128 quarter = _mm_add_ps(half, _mm_movehl_ps(half, half));
    return _mm_cvtss_f32(_mm_add_ss(quarter, _mm_shuffle_ps(quarter, quarter, 1)));
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"
#endif
