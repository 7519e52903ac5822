// msaa_avx2.cpp — the multisample fill's AVX2 kernels (msaa_kernel::avx2) for narrow
// triangles on CPUs without AVX-512 (8× and 16×: fill_rows_pixels, below). 4×: two pixels
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

// Narrow boxes at most this many columns wide are walked whole (no row spans), as in the
// AVX-512 kernels.
constexpr int SCAN_COLUMNS_AVX2 = 16;

// The depth test per lane, as depth_passes decides it (a NaN depth passes only not_equal
// and always): all ones where it passes.
template <depth_func Test>
inline __m256 passing(__m256 z, __m256 stored) {
    if constexpr (Test == depth_func::never) return _mm256_setzero_ps();
    else if constexpr (Test == depth_func::less) return _mm256_cmp_ps(z, stored, _CMP_LT_OQ);
    else if constexpr (Test == depth_func::less_equal) return _mm256_cmp_ps(z, stored, _CMP_LE_OQ);
    else if constexpr (Test == depth_func::equal) return _mm256_cmp_ps(z, stored, _CMP_EQ_OQ);
    else if constexpr (Test == depth_func::greater) return _mm256_cmp_ps(z, stored, _CMP_GT_OQ);
    else if constexpr (Test == depth_func::greater_equal) return _mm256_cmp_ps(z, stored, _CMP_GE_OQ);
    else if constexpr (Test == depth_func::not_equal) return _mm256_cmp_ps(z, stored, _CMP_NEQ_UQ);
    else return _mm256_castsi256_ps(_mm256_set1_epi32(-1));
}

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
    const bool scan = columns <= SCAN_COLUMNS_AVX2;
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
    const __m256i two_columns = _mm256_set1_epi32(2), minus_one = _mm256_set1_epi32(-1);
    const __m256i past_last = _mm256_set1_epi32(columns);
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
            // In (all ones): every edge value ≥ 0 (and, clipped, the pixel inside the bounds).
            __m256i inside = _mm256_set1_epi32(-1);
            if constexpr (Clipped) {
                inside = _mm256_and_si256(_mm256_cmpgt_epi32(column, minus_one), _mm256_cmpgt_epi32(past_last, column));
                column = _mm256_add_epi32(column, two_columns);
            }
            const __m256 in = _mm256_castsi256_ps(
                _mm256_andnot_si256(_mm256_srai_epi32(_mm256_or_si256(_mm256_or_si256(b0, b1), b2), 31), inside));
            b0 = _mm256_add_epi32(b0, step0), b1 = _mm256_add_epi32(b1, step1), b2 = _mm256_add_epi32(b2, step2);
            const __m256 z = _mm256_add_ps(_mm256_add_ps(z_row, _mm256_mul_ps(zdx, at)), dz);
            const __m256 shade = _mm256_min_ps(_mm256_max_ps(_mm256_add_ps(i_row, _mm256_mul_ps(idx, at)), zero), ones);
            // The 4-sample tile is at rest between bands (sample_store): an untouched pixel's
            // samples hold depth 1 and the clear colour in memory too, so the lines are used as
            // loaded, touched or not (as in the AVX-512 block kernel).
            const __m256 pixel0 = _mm256_load_ps(p), pixel1 = _mm256_load_ps(p + 2 * S);
            const __m256 stored = _mm256_permute2f128_ps(pixel0, pixel1, 0x20);
            const __m256 colours = _mm256_permute2f128_ps(pixel0, pixel1, 0x31);
            const __m256 pass = _mm256_and_ps(in, passing<Test>(z, stored));
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

// 8× and 16×: one pixel per step, its samples in G = S/8 registers of 8 (depths) and G of
// colours, as the AVX-512 kernel does with one register and mask registers: coverage as the
// sign bits of the stepped edge values' OR, the depth test a compare, the writes blends, no
// branch for a pixel without a covered sample, the untouched samples selected away.
template <int S, depth_func Test>
void fill_rows_pixels(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, bool depth_write,
                      float clear_colour, int y0, int y1) {
    constexpr int G = S / 8;
    // The edge offsets a/16·dx + b/16·dy per sample, in float: exact integers for a narrow
    // triangle (|·| < 2^22); the depth offsets are the portable kernel's float operations.
    __m256i d[3][G];
    __m256 dz[G];
    for (int g = 0; g < G; ++g) {
        const __m256 ox = _mm256_loadu_ps(pat.fdx + 8 * g), oy = _mm256_loadu_ps(pat.fdy + 8 * g);
        for (int k = 0; k < 3; ++k)
            d[k][g] = _mm256_cvtps_epi32(_mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(static_cast<float>(f.a[k])), ox),
                                                       _mm256_mul_ps(_mm256_set1_ps(static_cast<float>(f.b[k])), oy)));
        dz[g] = _mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(f.zdx), ox), _mm256_mul_ps(_mm256_set1_ps(f.zdy), oy));
    }
    const int columns = f.max_x - f.min_x + 1;
    const bool scan = columns <= SCAN_COLUMNS_AVX2;
    edge_extremes off;  // (row spans only)
    if (!scan)
        for (int k = 0; k < 3; ++k) {
            alignas(32) std::int32_t v[S];
            for (int g = 0; g < G; ++g) _mm256_store_si256(reinterpret_cast<__m256i *>(v + 8 * g), d[k][g]);
            off.lo[k] = *std::min_element(v, v + S);
            off.hi[k] = *std::max_element(v, v + S);
        }
    const __m256i step0 = _mm256_set1_epi32(static_cast<std::int32_t>(f.a[0]));
    const __m256i step1 = _mm256_set1_epi32(static_cast<std::int32_t>(f.a[1]));
    const __m256i step2 = _mm256_set1_epi32(static_cast<std::int32_t>(f.a[2]));
    const __m256 ones = _mm256_set1_ps(1.0f), clear = _mm256_set1_ps(clear_colour);
    const __m256 write = depth_write ? _mm256_castsi256_ps(_mm256_set1_epi32(-1)) : _mm256_setzero_ps();
    // Depth in lane 0, intensity in lane 1: both planes' row value plus step · column in one
    // multiply and add (the portable kernel's float operations, lane by lane).
    const __m128 plane0 = _mm_setr_ps(f.z, f.i, 0.0f, 0.0f), plane_dy = _mm_setr_ps(f.zdy, f.idy, 0.0f, 0.0f);
    const __m128 plane_dx = _mm_setr_ps(f.zdx, f.idx, 0.0f, 0.0f);
    const __m128 one = _mm_set1_ps(1.0f), zero = _mm_setzero_ps();
    for (int y = y0; y < y1; ++y) {
        std::int32_t e[3];
        int lo = 0, hi = columns - 1;
        if (scan) {
            for (int k = 0; k < 3; ++k) e[k] = static_cast<std::int32_t>(f.e[k] + f.b[k] * (y - f.min_y));
        } else if (!off.row(f, y, e, lo, hi)) {
            continue;
        }
        const __m128 plane_row = _mm_add_ps(plane0, _mm_mul_ps(plane_dy, _mm_set1_ps(static_cast<float>(y - f.min_y))));
        __m256i b[3][G];
        for (int k = 0; k < 3; ++k)
            for (int g = 0; g < G; ++g)
                b[k][g] = _mm256_add_epi32(_mm256_set1_epi32(e[k] + static_cast<std::int32_t>(f.a[k]) * lo), d[k][g]);
        std::uint8_t *touched = store.touched_row(y) + f.min_x + lo;
        float *p = store.pixel(f.min_x + lo, y);
        __m128 column = _mm_set1_ps(static_cast<float>(lo));  // exactly (< 2^24)
        for (int x = lo; x <= hi; ++x, p += 2 * S, ++touched, column = _mm_add_ps(column, one)) {
            __m256 in[G];
            int any = 0;
            for (int g = 0; g < G; ++g) {
                in[g] = _mm256_castsi256_ps(_mm256_or_si256(_mm256_or_si256(b[0][g], b[1][g]), b[2][g]));  // sign: out
                any |= _mm256_movemask_ps(in[g]) ^ 0xFF;
                b[0][g] = _mm256_add_epi32(b[0][g], step0), b[1][g] = _mm256_add_epi32(b[1][g], step1);
                b[2][g] = _mm256_add_epi32(b[2][g], step2);
            }
            const __m128 at = _mm_add_ps(plane_row, _mm_mul_ps(plane_dx, column));
            const __m256 shade = _mm256_broadcastss_ps(_mm_min_ps(_mm_max_ps(_mm_shuffle_ps(at, at, 0x55), zero), one));
            const __m256 zc = _mm256_broadcastss_ps(at);
            const __m256 held = _mm256_castsi256_ps(_mm256_set1_epi32(-static_cast<std::int32_t>(*touched)));
            *touched = static_cast<std::uint8_t>(*touched | (any != 0));
            for (int g = 0; g < G; ++g) {
                const __m256 z = _mm256_add_ps(zc, dz[g]);
                const __m256 stored = _mm256_blendv_ps(ones, _mm256_loadu_ps(p + 8 * g), held);
                const __m256 colours = _mm256_blendv_ps(clear, _mm256_loadu_ps(p + S + 8 * g), held);
                const __m256 pass = _mm256_andnot_ps(in[g], passing<Test>(z, stored));  // blendv reads the sign bits
                _mm256_storeu_ps(p + 8 * g, _mm256_blendv_ps(stored, z, _mm256_and_ps(pass, write)));
                _mm256_storeu_ps(p + S + 8 * g, _mm256_blendv_ps(colours, shade, pass));
            }
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
    else fill_rows_pixels<S, Test>(store, f, pat, depth_write, clear_colour, y0, y1);
}

}  // namespace

msaa_row_fill fill_function_avx2(int samples, depth_func test) {
    return fill_function(samples, test, [](auto s, auto t) -> msaa_row_fill { return &fill_avx2<s.value, t.value>; });
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"

#endif  // TINY3D_AVX2
