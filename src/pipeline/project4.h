// project4.h — the vertex stage's 4-wide projection kernel, shared by both pipelines
// (the render context's vertex transform and the wireframe): for four clip-space points,
// clip_outcode(p, guard) and clip_to_screen's pixel position and depth, with the same
// float operations in the same order, hence the same bits (tests/vertex_stage_test.cpp).
// The portable reference is those two functions themselves (include/pipeline.h); the SSE2
// kernel is below. Not installed.
#ifndef TINY3D_PROJECT4_H
#define TINY3D_PROJECT4_H

#include "pipeline.h"
#include "../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>

namespace tiny3d::detail {

// Four clip-space points, one per lane, and what project4 makes of them.
struct projected4 {
    __m128 x, y, depth;  // clip_to_screen's x, y, depth on every lane (meaningless where !in_front)
    __m128i outcode;     // clip_outcode(p, guard) (0 on every lane when outcodes are not wanted)
    __m128 in_front;     // all ones where clip_to_screen's `behind` is false
};

// with_outcodes = false skips the plane tests (a caller that knows every point is inside).
// The plane tests use float sums: the sign of a rounded sum of two finite floats is the sign
// of the exact sum (zero only when that is), so they agree with clip_outcode.
inline projected4 project4(__m128 x, __m128 y, __m128 z, __m128 w, float guard, float width, float height,
                           bool with_outcodes) {
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f), half = _mm_set1_ps(0.5f);
    auto finite = [&](__m128 v) { return _mm_cmpeq_ps(_mm_mul_ps(v, zero), zero); };  // ±∞·0, NaN·0 are NaN
    const __m128i all_planes = _mm_set1_epi32(int(clip_all));
    projected4 r;
    r.outcode = _mm_setzero_si128();
    if (with_outcodes) {
        auto outside = [&](__m128 distance, unsigned plane) {  // plane's bit unless distance ≥ 0
            return _mm_andnot_si128(_mm_castps_si128(_mm_cmpge_ps(distance, zero)), _mm_set1_epi32(int(plane)));
        };
        const __m128 gw = guard == 1.0f ? w : _mm_mul_ps(_mm_set1_ps(guard), w);  // 1·w = w exactly
        __m128i code = _mm_or_si128(_mm_or_si128(outside(_mm_add_ps(z, w), clip_near), outside(_mm_sub_ps(w, z), clip_far)),
                                    _mm_or_si128(outside(_mm_add_ps(x, gw), clip_left), outside(_mm_sub_ps(gw, x), clip_right)));
        code = _mm_or_si128(code, _mm_or_si128(outside(_mm_add_ps(y, gw), clip_bottom), outside(_mm_sub_ps(gw, y), clip_top)));
        const __m128 clip_finite = _mm_and_ps(_mm_and_ps(finite(x), finite(y)), _mm_and_ps(finite(z), finite(w)));
        r.outcode = _mm_or_si128(code, _mm_andnot_si128(_mm_castps_si128(clip_finite), all_planes));
    }
    // clip_to_screen, on every lane.
    const __m128 inv_w = _mm_div_ps(one, w);
    const __m128 ndc_x = _mm_mul_ps(x, inv_w), ndc_y = _mm_mul_ps(y, inv_w), ndc_z = _mm_mul_ps(z, inv_w);
    r.x = _mm_mul_ps(_mm_mul_ps(_mm_add_ps(ndc_x, one), half), _mm_set1_ps(width));
    r.y = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(one, ndc_y), half), _mm_set1_ps(height));
    r.depth = _mm_mul_ps(_mm_add_ps(ndc_z, one), half);
    r.in_front = _mm_and_ps(_mm_and_ps(_mm_cmpgt_ps(w, zero), finite(w)),
                            _mm_and_ps(finite(ndc_x), _mm_and_ps(finite(ndc_y), finite(ndc_z))));
    return r;
}

}  // namespace tiny3d::detail

#endif  // TINY3D_SSE2
#endif
