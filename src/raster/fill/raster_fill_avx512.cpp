// raster_fill_avx512.cpp — the 1-sample fill's AVX-512 kernels (raster_simd::avx512): a
// narrow triangle's row (narrow_fits) as ONE register of 16 lanes (8 for a triangle at most 8
// columns wide), the span a lane mask, the depth test a masked compare, the writes masked
// stores (no colour read, no blend), where SSE2 needs up to four groups of four, each loaded,
// compared, blended and stored; four rows' spans and plane values at once. Every other
// triangle goes to the SSE2 kernels (fill_fast_rows). The same bits as the SSE2 kernel: the
// lanes' depth and intensity in its operation order (the row's value plus the lane's offset
// within its group of four, then the group's step once per group before it), the spans'
// doubles as row_spans', no FMA contraction; the narrow kernel takes exactly the triangles
// SSE2's takes (tests/raster_threads_test.cpp). Inside avx512_region_open.inc's target region
// (headers included before it stay baseline); run only where kernels_run.
#include <algorithm>
#include <cstdint>

#include "fill.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX512
#include <immintrin.h>

#include "../../avx512_region_open.inc"

namespace tiny3d::detail {
namespace {

// The narrow kernel's registers: a row of up to 16 columns as 16 lanes, or of up to 8 as 8
// lanes (half the work where a 512-bit operation costs two 256-bit ones, as on AMD Zen 4;
// fewer group steps everywhere). The same operations on either width, lane by lane.
struct lanes16 {
    using vec = __m512;
    using mask = __mmask16;
    static constexpr int count = 16;
    static vec set1(float v) { return _mm512_set1_ps(v); }
    static vec column() { return _mm512_setr_ps(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3); }
    static vec add(vec a, vec b) { return _mm512_add_ps(a, b); }
    static vec mul(vec a, vec b) { return _mm512_mul_ps(a, b); }
    static vec mask_add(vec src, mask m, vec a, vec b) { return _mm512_mask_add_ps(src, m, a, b); }
    static vec clamp01(vec v) { return _mm512_min_ps(_mm512_max_ps(v, _mm512_setzero_ps()), _mm512_set1_ps(1.0f)); }
    static vec load(mask m, const float *p) { return _mm512_maskz_loadu_ps(m, p); }
    static void store(float *p, mask m, vec v) { _mm512_mask_storeu_ps(p, m, v); }
    template <int Predicate>
    static mask compare(mask m, vec a, vec b) { return _mm512_mask_cmp_ps_mask(m, a, b, Predicate); }
};
struct lanes8 {
    using vec = __m256;
    using mask = __mmask8;
    static constexpr int count = 8;
    static vec set1(float v) { return _mm256_set1_ps(v); }
    static vec column() { return _mm256_setr_ps(0, 1, 2, 3, 0, 1, 2, 3); }
    static vec add(vec a, vec b) { return _mm256_add_ps(a, b); }
    static vec mul(vec a, vec b) { return _mm256_mul_ps(a, b); }
    static vec mask_add(vec src, mask m, vec a, vec b) { return _mm256_mask_add_ps(src, m, a, b); }
    static vec clamp01(vec v) { return _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(1.0f)); }
    static vec load(mask m, const float *p) { return _mm256_maskz_loadu_ps(m, p); }
    static void store(float *p, mask m, vec v) { _mm256_mask_storeu_ps(p, m, v); }
    template <int Predicate>
    static mask compare(mask m, vec a, vec b) { return _mm256_mask_cmp_ps_mask(m, a, b, Predicate); }
};

// The depth test (depth_predicate) on the lanes of `cover`.
template <depth_func Test, class L>
inline typename L::mask depth_pass(typename L::mask cover, typename L::vec z, typename L::vec stored) {
    if constexpr (Test == depth_func::always) return cover;
    else return L::template compare<depth_predicate<Test>()>(cover, z, stored);
}

// The lanes' offsets from the row's value, as the SSE2 kernel forms them: lane l of group
// g = l / 4 is (row + step·(l mod 4)) + 4·step, the group step added g times.
template <class L>
inline typename L::vec lanes_from(float row, typename L::vec within_group, typename L::vec group_step) {
    typename L::vec v = L::add(L::set1(row), within_group);
    for (int g = 1; g < L::count / 4; ++g)  // (unrolled: the lanes of group g and after)
        v = L::mask_add(v, static_cast<typename L::mask>((0xFFFFu << (4 * g)) & 0xFFFFu), v, group_step);
    return v;
}

// The covered columns of four rows dy .. dy + 3 as four 16-bit lane masks (bit x: column
// min_x + x), in the low 16 bits of out[0..3]: row_spans::at's operations for the four rows
// at once, lane pair (2r, 2r + 1) = row r's (lo, hi) pair — the same doubles, rounded the
// same way — then mask = bits lo..hi.
struct span_batch {
    __m512d a, a_step, b, b_step, low, high;
    explicit span_batch(const fast_triangle &f) {
        const double w = f.max_x - f.min_x;
        a = _mm512_broadcast_f64x2(_mm_loadu_pd(f.cross));
        a_step = _mm512_broadcast_f64x2(_mm_loadu_pd(f.cross_step));
        b = _mm512_broadcast_f64x2(_mm_loadu_pd(f.cross + 2));
        b_step = _mm512_broadcast_f64x2(_mm_loadu_pd(f.cross_step + 2));
        low = _mm512_broadcast_f64x2(_mm_setr_pd(-0.5, -w - 0.5));
        high = _mm512_broadcast_f64x2(_mm_setr_pd(w + 0.5, 0.5));
    }
    void masks(int dy, std::uint64_t out[4]) const {
        constexpr double K = 1 << 20;  // row_spans' offset: ceil(v) = K − trunc(K − v)
        const __m512d d = _mm512_cvtepi32_pd(_mm256_add_epi32(_mm256_set1_epi32(dy), _mm256_setr_epi32(0, 0, 1, 1, 2, 2, 3, 3)));
        const __m512d va = _mm512_add_pd(a, _mm512_mul_pd(a_step, d)), vb = _mm512_add_pd(b, _mm512_mul_pd(b_step, d));
        const __m512d u = _mm512_min_pd(_mm512_max_pd(_mm512_sub_pd(_mm512_max_pd(va, vb), _mm512_set1_pd(CROSS_EPS)), low), high);
        const __m256i t = _mm512_cvttpd_epi32(_mm512_sub_pd(_mm512_set1_pd(K), u));
        // Even lanes: lo = K − t, odd lanes: hi + 1 = t − K + 1; then (1 << n) − 1 in each.
        const __m256i ik = _mm256_set1_epi32(static_cast<int>(K));
        const __m256i n = _mm256_mask_sub_epi32(_mm256_sub_epi32(ik, t), 0xAA, t, _mm256_sub_epi32(ik, _mm256_set1_epi32(1)));
        const __m256i below = _mm256_sub_epi32(_mm256_sllv_epi32(_mm256_set1_epi32(1), n), _mm256_set1_epi32(1));
        // Per row (64-bit lane): the hi bits (odd dword, moved down) without the lo bits.
        _mm256_storeu_si256(reinterpret_cast<__m256i *>(out), _mm256_andnot_si256(below, _mm256_srli_epi64(below, 32)));
    }
};

// A triangle that narrow_fits, rows [y0, y1) within f's, with L's lanes (L::count columns
// from min_x: the triangle is at most that wide).
template <depth_func Test, bool HasDepth, class L>
[[gnu::always_inline]] inline void narrow_rows_with(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, bool depth_write, int y0, int y1) {
    using vec = typename L::vec;
    using mask = typename L::mask;
    const vec column = L::column();
    const vec zoff = L::mul(L::set1(f.zdx), column), ioff = L::mul(L::set1(f.idx), column);
    const vec zstep = L::set1(4.0f * f.zdx), istep = L::set1(4.0f * f.idx);
    const span_batch spans(f);
    const float z0 = f.z, zdy = f.zdy, i0 = f.i, idy = f.idy;  // locals: the stores could alias f
    const int min_x = f.min_x, min_y = f.min_y;
    const __m128 z0v = _mm_set1_ps(z0), zdyv = _mm_set1_ps(zdy), i0v = _mm_set1_ps(i0), idyv = _mm_set1_ps(idy);
    alignas(32) std::uint64_t cover[4];
    alignas(16) float zrow_at[4], irow_at[4];  // the four rows' plane values z0 + zdy·dy, i0 + idy·dy
    for (int y = y0; y < y1; ++y) {
        const int r = (y - y0) & 3;
        if (r == 0) {
            const int dy = y - min_y;
            spans.masks(dy, cover);
            const __m128 dy_f = _mm_cvtepi32_ps(_mm_add_epi32(_mm_set1_epi32(dy), _mm_setr_epi32(0, 1, 2, 3)));
            _mm_store_ps(zrow_at, _mm_add_ps(z0v, _mm_mul_ps(zdyv, dy_f)));
            _mm_store_ps(irow_at, _mm_add_ps(i0v, _mm_mul_ps(idyv, dy_f)));
        }
        const vec z = lanes_from<L>(zrow_at[r], zoff, zstep);
        const vec in = lanes_from<L>(irow_at[r], ioff, istep);
        mask pass = static_cast<mask>(cover[r]);  // (the bits beyond L::count are 0: the span is narrower)
        if constexpr (HasDepth) {
            float *zrow = depth->row(y) + min_x;
            pass = depth_pass<Test, L>(pass, z, L::load(pass, zrow));
            if (depth_write) L::store(zrow, pass, z);
        }
        L::store(canvas.pixels[y] + min_x, pass, L::clamp01(in));
    }
}

// narrow_rows_with eight lanes when the triangle is at most eight columns wide, else sixteen.
template <depth_func Test, bool HasDepth>
[[gnu::always_inline]] inline void narrow_rows(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, bool depth_write, int y0, int y1) {
    if (f.max_x - f.min_x < lanes8::count) narrow_rows_with<Test, HasDepth, lanes8>(canvas, depth, f, depth_write, y0, y1);
    else narrow_rows_with<Test, HasDepth, lanes16>(canvas, depth, f, depth_write, y0, y1);
}

}  // namespace

void fill_rows_narrow_avx512(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, depth_func test,
                             bool depth_write, int y0, int y1) {
    if (!depth) return narrow_rows<depth_func::always, false>(canvas, depth, f, false, y0, y1);
    with_depth_test(test, [&](auto t) { narrow_rows<t.value, true>(canvas, depth, f, depth_write, y0, y1); });
}

void fill_fast_bins_avx512(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                           int y0, int y1, band_prefetch &ahead) {
    constexpr std::size_t TRIANGLES_AHEAD = 6;
    // The set-up triangle TRIANGLES_AHEAD entries on (its two cache lines), into the next
    // bin near a bin's end: a bin skips through its piece's list, which the hardware
    // prefetcher does not follow, and a band's bins are short on many threads (prefetching
    // only within each bin leaves the first triangles of every bin unfetched).
    with_depth_test(test, [&](auto t) {
        for (int j = 0; j < bin_count; ++j) {
            const band_bin &bin = bins[j];
            const band_bin *next = j + 1 < bin_count ? &bins[j + 1] : nullptr;
            for (std::size_t k = 0; k < bin.count; ++k) {
                ahead.step();
                const fast_triangle *later = nullptr;
                if (const std::size_t on = k + TRIANGLES_AHEAD; on < bin.count) later = &bin.triangle(bin.index[on]);
                else if (next && on - bin.count < next->count) later = &next->triangle(next->index[on - bin.count]);
                if (later) {
                    _mm_prefetch(reinterpret_cast<const char *>(later), _MM_HINT_T0);
                    _mm_prefetch(reinterpret_cast<const char *>(later) + sizeof(fast_triangle) - 1, _MM_HINT_T0);
                }
                const fast_triangle &f = bin.triangle(bin.index[k]);
                const int first = std::max(y0, f.min_y), end = std::min(y1, f.max_y + 1);
                if (first >= end) continue;
                if (f.wide < 0 && narrow_fits(f, canvas.width))
                    narrow_rows<t.value, true>(canvas, &depth, f, true, first, end);
                else
                    fill_fast_rows(canvas, &depth, f, f.wide >= 0 ? &bin.wide[f.wide] : nullptr, test, true, first, end);
            }
        }
    });
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"
#endif
