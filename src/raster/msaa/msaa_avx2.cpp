// msaa_avx2.cpp — the multisample fill's AVX2 kernels (msaa_kernel::avx2) for narrow
// triangles on CPUs without AVX-512. 8× and 16×: msaa_lanes_fill.inc's kernel over eight
// lanes with vector masks (lanes8, below; the AVX-512 kernel's scheme). 4×: two pixels
// of a row per step, their 8 samples in one 256-bit register (lane 4j + s: sample s of
// pixel j). Steps start at even columns, so the two pixels' samples are one whole, aligned
// 64-byte line of the tile (sample_store::STRIDE_PIXELS): two 256-bit halves, each one
// pixel's 4 depths and 4 colours, regrouped into the two pixels' depths and their colours
// by two lane permutes, and back. Coverage (the sign bits of the three stepped edge values'
// OR, within the box's columns), the depth test (a compare) and the writes (blends) take no
// branch, and neither does a step without a covered sample (stored back as it was): the
// AVX-512 block kernel's scheme (msaa_avx512.cpp), with 8 lanes and without mask registers.
//
// Compiled for AVX2 inside the target region of avx2_region_open.inc; run only on CPUs that
// have it (kernels_run, src/kernels.cpp). No FMA contraction: the portable kernel's float operations,
// rounded step by step, lane by lane, so the samples are bit-identical.
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "msaa_kernels.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX2
#include <immintrin.h>

#include "../../avx2_region_open.inc"

namespace tiny3d::detail {
namespace {

#include "msaa_lanes_fill.inc"  // ymm_lanes, passing, fill_rows_pixels

// Eight samples per register, masks as vectors: a mask all ones in its lanes (blendv reads
// the sign bits), coverage the OR of the three edge values (sign bit set: the lane is out).
// The lane trait of msaa_lanes_fill.inc: narrow triangles only, no prefetch.
struct lanes8 : ymm_lanes {
    static constexpr bool wide = false, prefetch_below = false;
    using mask = __m256;
    using coverage = __m256;
    static vf blend(mask m, vf a, vf b) { return _mm256_blendv_ps(a, b, m); }
    static coverage covered(vi b0, vi b1, vi b2) { return _mm256_castsi256_ps(_mm256_or_si256(_mm256_or_si256(b0, b1), b2)); }
    static int any(coverage in) { return _mm256_movemask_ps(in) ^ 0xFF; }
    static mask held(std::uint8_t touched) { return _mm256_castsi256_ps(_mm256_set1_epi32(-static_cast<std::int32_t>(touched))); }
    template <int Predicate>
    static mask compare(coverage in, vf z, vf stored) { return _mm256_andnot_ps(in, _mm256_cmp_ps(z, stored, Predicate)); }
    static mask all(coverage in) { return _mm256_andnot_ps(in, _mm256_castsi256_ps(_mm256_set1_epi32(-1))); }
    static vf writes(bool depth_write) { return depth_write ? _mm256_castsi256_ps(_mm256_set1_epi32(-1)) : _mm256_setzero_ps(); }
    static void store_depths(float *p, vf writes, mask pass, mask, vf stored, vf z) {
        store(p, blend(_mm256_and_ps(pass, writes), stored, z));
    }
};


// Clipped (f.clipped_x): a pair reaching a column past the bounds masks it off; otherwise no
// sample there is inside f and the mask is left out, the pair's column stepped in float
// (as the AVX-512 block kernel: the unclipped loop carries no mask).
template <depth_func Test, bool Clipped>
void fill_rows_pairs(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, bool depth_write, int y0,
                     int y1) {
    constexpr int S = 4;
    // Lane 4j + s: sample s's offset from its pixel's centre (ox, oy: the pattern's four,
    // once per pixel) and from pixel 0's (bx = j + dx/16, exact). The edge offsets
    // a·bx + b·oy are integers below 2^21 for a narrow triangle, so the float products and
    // sum are exact; the depth offsets are the portable kernel's.
    const __m256i lane_column = _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1);
    const __m256 ox = _mm256_broadcast_ps(reinterpret_cast<const __m128 *>(pat.fdx));
    const __m256 oy = _mm256_broadcast_ps(reinterpret_cast<const __m128 *>(pat.fdy));
    const __m256 bx = _mm256_add_ps(ox, _mm256_cvtepi32_ps(lane_column));
    const int columns = f.max_x - f.min_x + 1;
    const bool scan = columns <= SCAN_COLUMNS_WIDE;
    edge_extremes off;  // (row spans only) over pixel 0's lanes: the pattern's own offsets
    __m256i d[3];
    for (int k = 0; k < 3; ++k) {
        d[k] = _mm256_cvtps_epi32(_mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(static_cast<float>(f.a[k])), bx),
                                                _mm256_mul_ps(_mm256_set1_ps(static_cast<float>(f.b[k])), oy)));
        if (scan) continue;
        alignas(32) std::int32_t v[8];
        _mm256_store_si256(reinterpret_cast<__m256i *>(v), d[k]);
        off.lo[k] = *std::min_element(v, v + S);
        off.hi[k] = *std::max_element(v, v + S);
    }
    const __m256 dz = _mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(f.zdx), ox), _mm256_mul_ps(_mm256_set1_ps(f.zdy), oy));
    const __m256i step0 = _mm256_set1_epi32(static_cast<std::int32_t>(2 * f.a[0]));
    const __m256i step1 = _mm256_set1_epi32(static_cast<std::int32_t>(2 * f.a[1]));
    const __m256i step2 = _mm256_set1_epi32(static_cast<std::int32_t>(2 * f.a[2]));
    const __m256 ones = _mm256_set1_ps(1.0f), zero = _mm256_setzero_ps();
    const __m256 zdx = _mm256_set1_ps(f.zdx), idx = _mm256_set1_ps(f.idx);
    const __m256 write = depth_write ? _mm256_castsi256_ps(_mm256_set1_epi32(-1)) : zero;
    const __m256i two_columns = _mm256_set1_epi32(2), zero_i = _mm256_setzero_si256();
    const __m256i last_column = _mm256_set1_epi32(columns - 1);
    const __m256 two_columns_f = _mm256_set1_ps(2.0f);
    const int odd = f.min_x & 1;  // the steps start one column left of min_x
    for (int y = y0; y < y1; ++y) {
        const int dy = y - f.min_y;
        std::int32_t e[3];
        int lo = 0, hi = columns - 1;
        if (scan) {
            for (int k = 0; k < 3; ++k) e[k] = static_cast<std::int32_t>(f.e[k] + f.b[k] * dy);
        } else if (!off.row(f, y, e, lo, hi)) {
            continue;
        }
        const int first = lo - ((lo + odd) & 1);  // relative to min_x, at an even canvas column
        __m256i b0 = _mm256_add_epi32(_mm256_set1_epi32(e[0] + static_cast<std::int32_t>(f.a[0]) * first), d[0]);
        __m256i b1 = _mm256_add_epi32(_mm256_set1_epi32(e[1] + static_cast<std::int32_t>(f.a[1]) * first), d[1]);
        __m256i b2 = _mm256_add_epi32(_mm256_set1_epi32(e[2] + static_cast<std::int32_t>(f.a[2]) * first), d[2]);
        __m256i column = _mm256_add_epi32(_mm256_set1_epi32(first), lane_column);
        __m256 at = _mm256_cvtepi32_ps(column);  // (exactly: < 2^24; stepped exactly)
        const __m256 z_row = _mm256_set1_ps(f.z + f.zdy * static_cast<float>(dy));
        const __m256 i_row = _mm256_set1_ps(f.i + f.idy * static_cast<float>(dy));
        std::uint8_t *touched = store.touched_row(y) + f.min_x + first;
        float *p = store.pixel(f.min_x + first, y);
        for (int x = first; x <= hi; x += 2, p += 2 * 2 * S, touched += 2, at = _mm256_add_ps(at, two_columns_f)) {
            // Out (sign bit set): an edge value < 0 (or, clipped, the pixel outside the bounds).
            __m256i out = _mm256_or_si256(_mm256_or_si256(b0, b1), b2);
            if constexpr (Clipped) {
                out = _mm256_or_si256(out, _mm256_or_si256(_mm256_cmpgt_epi32(zero_i, column),
                                                           _mm256_cmpgt_epi32(column, last_column)));
                column = _mm256_add_epi32(column, two_columns);
            }
            b0 = _mm256_add_epi32(b0, step0), b1 = _mm256_add_epi32(b1, step1), b2 = _mm256_add_epi32(b2, step2);
            const __m256 z = _mm256_add_ps(_mm256_add_ps(z_row, _mm256_mul_ps(zdx, at)), dz);
            const __m256 shade = _mm256_min_ps(_mm256_max_ps(_mm256_add_ps(i_row, _mm256_mul_ps(idx, at)), zero), ones);
            // The 4-sample tile is at rest between bands (sample_store): an untouched pixel's
            // samples hold depth 1 and the clear colour in memory too, so the lines are used as
            // loaded, touched or not (as in the AVX-512 block kernel).
            const __m256 pixel0 = _mm256_load_ps(p), pixel1 = _mm256_load_ps(p + 2 * S);
            const __m256 stored = _mm256_permute2f128_ps(pixel0, pixel1, 0x20);
            const __m256 colours = _mm256_permute2f128_ps(pixel0, pixel1, 0x31);
            const __m256 pass = passing<lanes8, Test>(_mm256_castsi256_ps(out), z, stored);
            const __m256 depths = _mm256_blendv_ps(stored, z, _mm256_and_ps(pass, write));
            const __m256 shades = _mm256_blendv_ps(colours, shade, pass);
            _mm256_store_ps(p, _mm256_permute2f128_ps(depths, shades, 0x20));
            _mm256_store_ps(p + 2 * S, _mm256_permute2f128_ps(depths, shades, 0x31));
            // Both pixels now hold their samples in memory, covered or not (as in the AVX-512
            // block kernel: sample_store::touched_row).
            constexpr std::uint16_t both_touched = 0x0101;
            std::memcpy(touched, &both_touched, sizeof both_touched);
        }
    }
}

template <int S, depth_func Test>
void fill_avx2(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test, bool depth_write,
               float clear_colour, int y0, int y1) {
    if (!f.narrow || store.blocks())  // (the pair kernel walks the rows layout)
        return msaa_fill_for(msaa_kernel::sse2, S, test)(store, f, pat, test, depth_write, clear_colour, y0, y1);
    if (!clamp_to_rows(f, y0, y1)) return;
    if constexpr (S == 4) {
        if (f.clipped_x) fill_rows_pairs<Test, true>(store, f, pat, depth_write, y0, y1);
        else fill_rows_pairs<Test, false>(store, f, pat, depth_write, y0, y1);
    }
    else fill_rows_pixels<lanes8, S, Test>(store, f, pat, depth_write, clear_colour, y0, y1);
}

}  // namespace

msaa_row_fill fill_function_avx2(int samples, depth_func test) {
    return fill_function(samples, test, [](auto s, auto t) -> msaa_row_fill { return &fill_avx2<s.value, t.value>; });
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"

#endif  // TINY3D_AVX2
