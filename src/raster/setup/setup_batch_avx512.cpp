// setup_batch_avx512.cpp — the set-up stage's AVX-512 batches (kernel_table::setup_fast_batch,
// setup_msaa_batch for raster_simd::avx512): setup_batch.inc over the AVX-512 lane trait,
// inside the AVX-512 target region (headers before it stay baseline); run only where kernels_run.
#include <cstdint>

#include "setup.h"
#include "../msaa/msaa.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX512
#include <immintrin.h>

#include "../../avx512_region_open.inc"

namespace tiny3d::detail {

namespace {

// The doubles and 64-bit values in one part of eight lanes, chosen by mask registers.
struct avx512_lanes {
    static constexpr int parts = 1;
    using pd = __m512d;
    using q = __m512i;
    using pmask = __mmask8;
    static pd to_double(__m256i v, int) { return _mm512_cvtepi32_pd(v); }
    static q widen(__m256i v, int) { return _mm512_cvtepi32_epi64(v); }
    static pmask mask(__m256i m, int) { return _mm256_movepi32_mask(m); }
    static pd set1(double x) { return _mm512_set1_pd(x); }
    static pd select(pmask m, pd no, pd yes) { return _mm512_mask_blend_pd(m, no, yes); }
    static q mul(q a, q b) { return _mm512_mul_epi32(a, b); }
    static pd exact(q e) { return _mm512_cvtepi64_pd(e); }
    static pd load(const float *f, int) { return _mm512_cvtps_pd(_mm256_load_ps(f)); }
    static void store(float *to, int, pd v) { _mm256_storeu_ps(to, _mm512_cvtpd_ps(v)); }
    static void store(double *to, int, pd v) { _mm512_store_pd(to, v); }
    static void store(std::int64_t *to, int, q v) { _mm512_store_si512(to, v); }
    static __m256i orientation(const std::int64_t area2[SETUP_BATCH]) {
        const __mmask8 positive = _mm512_cmpgt_epi64_mask(_mm512_load_si512(area2), _mm512_setzero_si512());
        return _mm256_mask_blend_epi32(positive, _mm256_set1_epi32(-1), _mm256_set1_epi32(1));
    }
};

#include "setup_batch.inc"

}  // namespace

void setup_fast_batch_avx512(const setup_batch &in, pixel_rect clip, fast_setup verdict[SETUP_BATCH],
                             fast_triangle out[SETUP_BATCH]) {
    setup_fast_lanes<avx512_lanes>(in, clip, verdict, out);
}

void setup_msaa_batch_avx512(const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                             fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]) {
    setup_msaa_lanes<avx512_lanes>(in, pat, clip, verdict, out);
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"
#endif
