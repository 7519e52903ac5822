// setup_batch_avx2.cpp — the set-up stage's AVX2 batches (kernel_table::setup_fast_batch,
// setup_msaa_batch for raster_simd::avx2): setup_batch.inc over the AVX2 lane trait, inside
// the AVX2 target region (headers before it stay baseline); run only where kernels_run.
#include <cstdint>

#include "setup.h"
#include "../msaa/msaa.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX2
#include <immintrin.h>

#include "../../avx2_region_open.inc"

namespace tiny3d::detail {

namespace {

// The doubles and 64-bit values in two halves of four lanes, chosen by vector masks.
struct avx2_lanes {
    static constexpr int parts = 2;
    using pd = __m256d;
    using q = __m256i;
    using pmask = __m256d;
    static __m128i half(__m256i v, int h) { return h ? _mm256_extracti128_si256(v, 1) : _mm256_castsi256_si128(v); }
    static pd to_double(__m256i v, int h) { return _mm256_cvtepi32_pd(half(v, h)); }
    static q widen(__m256i v, int h) { return _mm256_cvtepi32_epi64(half(v, h)); }
    static pmask mask(__m256i m, int h) { return _mm256_castsi256_pd(widen(m, h)); }
    static pd set1(double x) { return _mm256_set1_pd(x); }
    static pd select(pmask m, pd no, pd yes) { return _mm256_blendv_pd(no, yes, m); }
    static q mul(q a, q b) { return _mm256_mul_epi32(a, b); }
    static pd exact(q e) {  // its low 32 bits
        return _mm256_cvtepi32_pd(_mm256_castsi256_si128(_mm256_permutevar8x32_epi32(e, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6))));
    }
    static pd load(const float *f, int h) { return _mm256_cvtps_pd(_mm_load_ps(f + 4 * h)); }
    static void store(float *to, int h, pd v) { _mm_storeu_ps(to + 4 * h, _mm256_cvtpd_ps(v)); }
    static void store(double *to, int h, pd v) { _mm256_store_pd(to + 4 * h, v); }
    static void store(std::int64_t *to, int h, q v) { _mm256_store_si256(reinterpret_cast<__m256i *>(to + 4 * h), v); }
    static __m256i orientation(const std::int64_t area2[SETUP_BATCH]) {
        alignas(32) std::int32_t sign[SETUP_BATCH];
        for (int l = 0; l < SETUP_BATCH; ++l) sign[l] = area2[l] > 0 ? 1 : -1;
        return _mm256_load_si256(reinterpret_cast<const __m256i *>(sign));
    }
};

#include "setup_batch.inc"

}  // namespace

void setup_fast_batch_avx2(const setup_batch &in, pixel_rect clip, fast_setup verdict[SETUP_BATCH],
                           fast_triangle out[SETUP_BATCH]) {
    setup_fast_lanes<avx2_lanes>(in, clip, verdict, out);
}

void setup_msaa_batch_avx2(const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                           fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]) {
    setup_msaa_lanes<avx2_lanes>(in, pat, clip, verdict, out);
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"
#endif
