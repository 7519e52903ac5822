// msaa_avx2.cpp — the multisample fill's AVX2 kernels for narrow triangles: msaa_lanes_fill.inc's
// kernels over eight lanes with vector masks (lanes8). 8× and 16×: a pixel's samples in one
// or two registers; 4×: two pixels of a row per step. Compiled inside avx2_region_open.inc's
// target region; no FMA contraction, so the samples are bit-identical to the portable ones.
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

// The lane trait of msaa_lanes_fill.inc: masks as vectors (blendv reads the sign bits),
// coverage the OR of the three edge values (sign set: out); narrow triangles, no prefetch.
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
    static mask both(mask a, mask b) { return _mm256_and_ps(a, b); }
    static void store_depths(float *p, vf writes, mask pass, mask, vf stored, vf z) { store(p, blend(both(pass, writes), stored, z)); }
    // 4× (fill_rows_quads): a pair of pixels from an even column, one aligned 64-byte line,
    // regrouped into depths and colours by two lane permutes, and back.
    static vf write_mask(bool depth_write) { return writes(depth_write); }
    static vi rows(bool, bool) { return _mm256_setzero_si256(); }
    static vi columns_within(vi out, vi column, vi last) {
        return _mm256_or_si256(out, _mm256_or_si256(_mm256_cmpgt_epi32(_mm256_setzero_si256(), column),
                                                    _mm256_cmpgt_epi32(column, last)));
    }
    static coverage covered_within(vi out, vi b0, vi b1, vi b2) {
        return _mm256_castsi256_ps(_mm256_or_si256(_mm256_or_si256(_mm256_or_si256(b0, b1), b2), out));
    }
    static void load_step(const float *p, vf &stored, vf &colours) {
        const vf pixel0 = _mm256_load_ps(p), pixel1 = _mm256_load_ps(p + 8);
        stored = _mm256_permute2f128_ps(pixel0, pixel1, 0x20);
        colours = _mm256_permute2f128_ps(pixel0, pixel1, 0x31);
    }
    static void store_step(float *p, vf depths, vf shades) {
        _mm256_store_ps(p, _mm256_permute2f128_ps(depths, shades, 0x20));
        _mm256_store_ps(p + 8, _mm256_permute2f128_ps(depths, shades, 0x31));
    }
    static void mark(std::uint8_t *touched) {
        constexpr std::uint16_t both_touched = 0x0101;
        std::memcpy(touched, &both_touched, sizeof both_touched);
    }
};

// 4× on narrow triangles, two columns of a row per step (fill_rows_quads' step with R = 1,
// the same operations): each row from its span (sample_row_spans, no divisions) widened to
// even canvas columns; the pointers at the box's first step stepped down per row, the edge
// values at the row's first step from the spans' own row values.
template <depth_func Test, bool Clipped>
void fill_rows_pairs(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, bool depth_write, int y0,
                     int y1) {
    using V = lanes8;
    using vf = V::vf;
    using vi = V::vi;
    constexpr int S = 4;
    alignas(32) static constexpr std::int32_t lane_columns[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    const vi lane_column = V::load_int(lane_columns);
    const vf ox = V::broadcast4(pat.fdx), oy = V::broadcast4(pat.fdy);
    const vf bx = V::add(ox, V::to_float(lane_column));
    vi d[3];
    std::int64_t best[3];  // over pixel 0's lanes: the pattern's own offsets
    for (int k = 0; k < 3; ++k) {  // exact integers (< 2^22): f is narrow
        d[k] = V::to_int(V::add(V::mul(V::set(static_cast<float>(f.a[k])), bx), V::mul(V::set(static_cast<float>(f.b[k])), oy)));
        __m128i h = _mm256_castsi256_si128(d[k]);
        h = _mm_max_epi32(h, _mm_shuffle_epi32(h, 0x4E));
        best[k] = _mm_cvtsi128_si32(_mm_max_epi32(h, _mm_shuffle_epi32(h, 0xB1)));
    }
    const vf dz = V::add(V::mul(V::set(f.zdx), ox), V::mul(V::set(f.zdy), oy));
    const vi step0 = V::set_int(2 * f.a[0]), step1 = V::set_int(2 * f.a[1]), step2 = V::set_int(2 * f.a[2]);
    const vf ones = V::set(1.0f), zero = V::set(0.0f);
    const vf zdx = V::set(f.zdx), idx = V::set(f.idx), zdy = V::set(f.zdy), idy = V::set(f.idy);
    const vf z0 = V::set(f.z), i0 = V::set(f.i), two_columns_f = V::set(2.0f);
    const vi two_columns = V::set_int(2), last_column = V::set_int(f.max_x - f.min_x);
    const int odd = f.min_x & 1;  // the steps start at even canvas columns
    const auto writes = V::write_mask(depth_write);
    const int dy0 = y0 - f.min_y;
    // Row y's pointers at the box's first step (column −odd), stepped per row; its edge
    // values there from the spans' (32 bits, wrapping as the 64-bit values' truncation does).
    float *row_p = store.pixel(f.min_x - odd, y0);
    std::uint8_t *row_touched = store.touched_row(y0) + f.min_x - odd;
    const std::ptrdiff_t p_down = store.rows_step(1), touched_down = store.stride();
    const vf at0 = V::to_float(V::add(V::set_int(-odd), lane_column));
    const __m128i a_lanes = _mm_setr_epi32(static_cast<std::int32_t>(f.a[0]), static_cast<std::int32_t>(f.a[1]),
                                           static_cast<std::int32_t>(f.a[2]), 0);
    // (the spans' t less the best sample's offset, at column −odd)
    const __m128i from_best = _mm_sub_epi32(_mm_mullo_epi32(a_lanes, _mm_set1_epi32(-odd)),
                                            _mm_setr_epi32(static_cast<std::int32_t>(best[0]),
                                                           static_cast<std::int32_t>(best[1]),
                                                           static_cast<std::int32_t>(best[2]), 0));
    sample_row_spans spans;
    spans.start(f, best, dy0);
    for (int y = y0; y < y1; ++y, row_p += p_down, row_touched += touched_down) {
        int lo, hi;
        const __m128i t = spans.next(lo, hi);
        if (lo > hi) continue;
        const int skip = (lo + odd) & ~1;  // columns from the box's first step
        const __m128i e = _mm_add_epi32(_mm_add_epi32(t, from_best), _mm_mullo_epi32(a_lanes, _mm_set1_epi32(skip)));
        vi b0 = V::add(_mm256_broadcastd_epi32(e), d[0]);
        vi b1 = V::add(_mm256_broadcastd_epi32(_mm_shuffle_epi32(e, 0x55)), d[1]);
        vi b2 = V::add(_mm256_broadcastd_epi32(_mm_shuffle_epi32(e, 0xAA)), d[2]);
        float *p = row_p + skip * 2 * S;
        std::uint8_t *touched = row_touched + skip;
        const int first = skip - odd;
        vf at = V::add(at0, V::set(static_cast<float>(skip)));  // (exactly)
        vi column = V::add(V::set_int(first), lane_column);     // (Clipped only)
        const vf row = V::set(static_cast<float>(y - f.min_y));  // (exactly)
        const vf z_row = V::add(z0, V::mul(zdy, row)), i_row = V::add(i0, V::mul(idy, row));
        for (int x = first; x <= hi; x += 2, p += 4 * S, touched += 2, at = V::add(at, two_columns_f)) {
            auto inside = V::rows(true, false);
            if constexpr (Clipped) {
                inside = V::columns_within(inside, column, last_column);
                column = V::add(column, two_columns);
            }
            const V::coverage in = V::covered_within(inside, b0, b1, b2);
            b0 = V::add(b0, step0), b1 = V::add(b1, step1), b2 = V::add(b2, step2);
            const vf z = V::add(V::add(z_row, V::mul(zdx, at)), dz);
            const vf shade = V::min(V::max(V::add(i_row, V::mul(idx, at)), zero), ones);  // clamp01
            vf stored, colours;
            V::load_step(p, stored, colours);
            const V::mask pass = passing<V, Test>(in, z, stored);
            V::store_step(p, V::blend(V::both(pass, writes), stored, z), V::blend(pass, colours, shade));
            V::mark(touched);
        }
    }
}

template <int S, depth_func Test>
void fill_avx2(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test, bool depth_write,
               float clear_colour, int y0, int y1) {
    if (!f.narrow || store.blocks())  // (lanes8's 4× steps walk the rows layout)
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

// Eight pixels at a time: pixels j and j + 4 in one register's two halves, then the SSE2
// resolve's transpose on both halves at once (per pixel (s0 + s2) + (s1 + s3), the nearest
// sample, the same operations in the same order); untouched pixels get the clear values.
void resolve_rows4_avx2(float *p, const std::uint8_t *touched, int pixels, float clear_colour, float *colour, float *z) {
    const __m256 quarter = _mm256_set1_ps(0.25f), clear = _mm256_set1_ps(clear_colour), far = _mm256_set1_ps(1.0f);
    const __m256 rest = _mm256_blend_ps(far, clear, 0xF0);  // a pixel at rest: four depths, four colours
    for (int x = 0; x < pixels; x += 8, p += 8 * 8) {
        std::uint64_t t8;
        std::memcpy(&t8, touched + x, sizeof t8);
        if (t8 == 0) {
            _mm256_storeu_ps(colour + x, clear), _mm256_storeu_ps(z + x, far);
            continue;
        }
        // (pixel j's depths or colours, pixel j + 4's)
        auto pair = [p](int j, int offset) { return _mm256_loadu2_m128(p + 8 * (j + 4) + offset, p + 8 * j + offset); };
        auto reduce = [&](int offset, auto op) {
            const __m256 q0 = pair(0, offset), q1 = pair(1, offset), q2 = pair(2, offset), q3 = pair(3, offset);
            const __m256 v01 = op(_mm256_unpacklo_ps(q0, q1), _mm256_unpackhi_ps(q0, q1));
            const __m256 v23 = op(_mm256_unpacklo_ps(q2, q3), _mm256_unpackhi_ps(q2, q3));
            return op(_mm256_castpd_ps(_mm256_unpacklo_pd(_mm256_castps_pd(v01), _mm256_castps_pd(v23))),
                      _mm256_castpd_ps(_mm256_unpackhi_pd(_mm256_castps_pd(v01), _mm256_castps_pd(v23))));
        };
        __m256 c = _mm256_mul_ps(reduce(4, [](__m256 u, __m256 v) { return _mm256_add_ps(u, v); }), quarter);
        __m256 d = reduce(0, [](__m256 u, __m256 v) { return _mm256_min_ps(u, v); });
        if (t8 != 0x0101010101010101u) {
            const __m256 out = _mm256_castsi256_ps(_mm256_cmpeq_epi32(
                _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(t8))), _mm256_setzero_si256()));
            c = _mm256_blendv_ps(c, clear, out);
            d = _mm256_blendv_ps(d, far, out);
        }
        _mm256_storeu_ps(colour + x, c), _mm256_storeu_ps(z + x, d);
        _mm256_store_ps(p, rest), _mm256_store_ps(p + 8, rest), _mm256_store_ps(p + 16, rest);
        _mm256_store_ps(p + 24, rest), _mm256_store_ps(p + 32, rest), _mm256_store_ps(p + 40, rest);
        _mm256_store_ps(p + 48, rest), _mm256_store_ps(p + 56, rest);
    }
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"

#endif  // TINY3D_AVX2
