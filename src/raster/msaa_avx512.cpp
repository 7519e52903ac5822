// msaa_avx512.cpp — the multisample fill's AVX-512 kernels (msaa_kernel::avx512). 8× and
// 16×: one pixel's depths in one register and its colours in another. Per pixel: the three
// edge values at every sample stepped by one add each, coverage as a mask register (the
// sign bits of their OR), the depth test as a masked compare and the writes as blends —
// where the SSE2 kernel needs two or four groups of four. 4×: the SSE2 kernel's source
// compiled here (msaa_sse2_fill.inc), where it has 32 vector registers.
//
// Compiled for AVX-512 inside the target region of avx512_region_open.inc (as
// line_tabulated_avx512.cpp is): the headers are included before the region opens, so
// their inline functions stay baseline x86-64. Run only on CPUs that have it
// (best_msaa_kernel). No FMA contraction: the portable kernel's float operations, rounded
// step by step, lane by lane.
#include <algorithm>
#include <cstdint>

#include "msaa_kernels.h"
#include "../simd_config.h"

#ifdef TINY3D_AVX512
#include <emmintrin.h>
#include <immintrin.h>

#include "../avx512_region_open.inc"

namespace tiny3d::detail {
namespace {

// 4×: the SSE2 kernel's source, compiled here for AVX-512 (msaa_sse2_fill.inc).
#include "msaa_sse2_fill.inc"

// One register of S samples: 16 floats (zmm) for 16×, 8 (ymm) for 8× — a pixel's depths or
// colours exactly, so no access reaches a neighbouring pixel (a 16-lane access with lanes
// masked off still overlaps the next pixel's samples and defeats store-to-load forwarding:
// 8× in zmm took 21 ms against 12 in ymm here). Masks: bit s = sample s.
template <int S>
struct samples;

template <>
struct samples<16> {
    using vf = __m512;
    using vi = __m512i;
    using mask = __mmask16;
    static vf set(float v) { return _mm512_set1_ps(v); }
    static vi set_int(std::int64_t v) { return _mm512_set1_epi32(static_cast<std::int32_t>(v)); }
    static vi load_int(const std::int32_t *p) { return _mm512_loadu_si512(p); }
    static vf load(const float *p) { return _mm512_loadu_ps(p); }
    static vf load(vf held_off, mask held, const float *p) { return _mm512_mask_loadu_ps(held_off, held, p); }
    static void store(float *p, mask m, vf v) { _mm512_mask_storeu_ps(p, m, v); }
    static void store(float *p, vf v) { _mm512_storeu_ps(p, v); }
    static vf blend(mask m, vf a, vf b) { return _mm512_mask_blend_ps(m, a, b); }
    static vf add(vf a, vf b) { return _mm512_add_ps(a, b); }
    static vf mul(vf a, vf b) { return _mm512_mul_ps(a, b); }
    static vi add(vi a, vi b) { return _mm512_add_epi32(a, b); }
    static vi to_int(vf v) { return _mm512_cvtps_epi32(v); }
    static float min_of(vf v) { return _mm512_reduce_min_ps(v); }
    static float max_of(vf v) { return _mm512_reduce_max_ps(v); }
    static vf broadcast(__m128 v) { return _mm512_broadcastss_ps(v); }
    // The samples outside an edge: the sign bits of b0 | b1 | b2.
    static mask outside(vi b0, vi b1, vi b2) { return _mm512_movepi32_mask(_mm512_ternarylogic_epi32(b0, b1, b2, 0xFE)); }
    template <int Predicate>
    static mask compare(mask in, vf a, vf b) { return _mm512_mask_cmp_ps_mask(in, a, b, Predicate); }
};

template <>
struct samples<8> {
    using vf = __m256;
    using vi = __m256i;
    using mask = __mmask8;
    static vf set(float v) { return _mm256_set1_ps(v); }
    static vi set_int(std::int64_t v) { return _mm256_set1_epi32(static_cast<std::int32_t>(v)); }
    static vi load_int(const std::int32_t *p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p)); }
    static vf load(const float *p) { return _mm256_loadu_ps(p); }
    static vf load(vf held_off, mask held, const float *p) { return _mm256_mask_loadu_ps(held_off, held, p); }
    static void store(float *p, mask m, vf v) { _mm256_mask_storeu_ps(p, m, v); }
    static void store(float *p, vf v) { _mm256_storeu_ps(p, v); }
    static vf blend(mask m, vf a, vf b) { return _mm256_mask_blend_ps(m, a, b); }
    static vf add(vf a, vf b) { return _mm256_add_ps(a, b); }
    static vf mul(vf a, vf b) { return _mm256_mul_ps(a, b); }
    static vi add(vi a, vi b) { return _mm256_add_epi32(a, b); }
    static vi to_int(vf v) { return _mm256_cvtps_epi32(v); }
    // (Set-up only: the eight lanes widened, the upper ones masked off.)
    static float min_of(vf v) { return _mm512_mask_reduce_min_ps(0xFF, _mm512_castps256_ps512(v)); }
    static float max_of(vf v) { return _mm512_mask_reduce_max_ps(0xFF, _mm512_castps256_ps512(v)); }
    static vf broadcast(__m128 v) { return _mm256_broadcastss_ps(v); }
    static mask outside(vi b0, vi b1, vi b2) { return _mm256_movepi32_mask(_mm256_ternarylogic_epi32(b0, b1, b2, 0xFE)); }
    template <int Predicate>
    static mask compare(mask in, vf a, vf b) { return _mm256_mask_cmp_ps_mask(in, a, b, Predicate); }
};

// The depth test, as depth_passes decides it per sample (a NaN depth passes only not_equal
// and always), limited to the samples of `in`.
template <int S, depth_func Test>
inline typename samples<S>::mask passing(typename samples<S>::mask in, typename samples<S>::vf z,
                                         typename samples<S>::vf stored) {
    using V = samples<S>;
    if constexpr (Test == depth_func::never) return 0;
    else if constexpr (Test == depth_func::less) return V::template compare<_CMP_LT_OQ>(in, z, stored);
    else if constexpr (Test == depth_func::less_equal) return V::template compare<_CMP_LE_OQ>(in, z, stored);
    else if constexpr (Test == depth_func::equal) return V::template compare<_CMP_EQ_OQ>(in, z, stored);
    else if constexpr (Test == depth_func::greater) return V::template compare<_CMP_GT_OQ>(in, z, stored);
    else if constexpr (Test == depth_func::greater_equal) return V::template compare<_CMP_GE_OQ>(in, z, stored);
    else if constexpr (Test == depth_func::not_equal) return V::template compare<_CMP_NEQ_UQ>(in, z, stored);
    else return in;
}

// S = 8 or 16 samples, one register per pixel's depths and one per its colours.
template <int S, depth_func Test>
void fill_rows(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, bool depth_write,
               float clear_colour, int y0, int y1) {
    using V = samples<S>;
    using mask = typename V::mask;
    // The edge offsets a/16·dx + b/16·dy per sample, in float: a·(dx/16) is the integer
    // −Δy·dx, |·| < 2^18, so every product and sum is exact and converts to the portable
    // kernel's integers; the depth offsets are the portable kernel's float operations.
    const typename V::vf ox = V::load(pat.fdx), oy = V::load(pat.fdy);
    edge_extremes off;
    typename V::vi d[3];
    for (int k = 0; k < 3; ++k) {
        if (!f.narrow) {  // long edges: the float offsets may round; the exact integers instead
            alignas(64) std::int32_t exact[S];
            sample_offsets_exact(f, pat, k, exact);
            d[k] = V::load_int(exact);
            off.lo[k] = *std::min_element(exact, exact + S);
            off.hi[k] = *std::max_element(exact, exact + S);
            continue;
        }
        const typename V::vf v = V::add(V::mul(V::set(static_cast<float>(f.a[k])), ox),
                                        V::mul(V::set(static_cast<float>(f.b[k])), oy));
        d[k] = V::to_int(v);
        off.lo[k] = static_cast<std::int64_t>(V::min_of(v));
        off.hi[k] = static_cast<std::int64_t>(V::max_of(v));
    }
    const int chunk = chunk_columns(f, off);
    const typename V::vf dz = V::add(V::mul(V::set(f.zdx), ox), V::mul(V::set(f.zdy), oy));
    const typename V::vi step0 = V::set_int(f.a[0]), step1 = V::set_int(f.a[1]), step2 = V::set_int(f.a[2]);
    const typename V::vf ones = V::set(1.0f), clear = V::set(clear_colour);
    // Depth in lane 0, intensity in lane 1: both planes' row value plus step · column in one
    // multiply and add (the portable kernel's float operations, lane by lane).
    const __m128 plane0 = _mm_setr_ps(f.z, f.i, 0.0f, 0.0f), plane_dy = _mm_setr_ps(f.zdy, f.idy, 0.0f, 0.0f);
    const __m128 plane_dx = _mm_setr_ps(f.zdx, f.idx, 0.0f, 0.0f);
    const __m128 one = _mm_set1_ps(1.0f), zero = _mm_setzero_ps();
    for (int y = y0; y < y1; ++y) {
        // The row's span: 32-bit divisions when narrow (9 % faster at 16×), else 64-bit.
        std::int64_t e64[3];
        int lo, hi;
        if (f.narrow) {
            std::int32_t e[3];
            if (!off.row(f, y, e, lo, hi)) continue;
            e64[0] = e[0], e64[1] = e[1], e64[2] = e[2];
        } else if (!off.row(f, y, e64, lo, hi)) {
            continue;
        }
        const __m128 plane_row = _mm_add_ps(plane0, _mm_mul_ps(plane_dy, _mm_set1_ps(static_cast<float>(y - f.min_y))));
        // The row in chunks of columns (one chunk unless f is wide: chunk_columns).
        for (int first = lo, last; first <= hi; first = last + 1) {
            last = std::min(hi, first + (chunk - 1));
            // The samples' edge values at column `first` (32 bits), stepped by a per column.
            typename V::vi b0 = V::add(V::set_int(chunk_start(f, e64[0] + f.a[0] * first)), d[0]);
            typename V::vi b1 = V::add(V::set_int(chunk_start(f, e64[1] + f.a[1] * first)), d[1]);
            typename V::vi b2 = V::add(V::set_int(chunk_start(f, e64[2] + f.a[2] * first)), d[2]);
            std::uint8_t *touched = store.touched_row(y) + f.min_x + first;
            float *p = store.pixel(f.min_x + first, y);
            // The next row's first pixels are most likely below this row's: fetched ahead, as a
            // row of a small triangle has too few pixels for the hardware prefetcher (−2 % for
            // the 8× and 16× frames of Scene S).
            if (y + 1 < y1 && first == lo) {
                const char *below = reinterpret_cast<const char *>(p + static_cast<std::size_t>(store.width()) * 2 * S);
                for (int line = 0; line < 2 * S * 4; line += 64) _mm_prefetch(below + line, _MM_HINT_T0);
            }
            __m128 column = _mm_set1_ps(static_cast<float>(first));  // exactly (< 2^24)
            for (int x = first; x <= last; ++x, p += 2 * S, ++touched, column = _mm_add_ps(column, one)) {
                // A sample is in when all three edge values are ≥ 0.
                const mask in = static_cast<mask>(~V::outside(b0, b1, b2));
                b0 = V::add(b0, step0), b1 = V::add(b1, step1), b2 = V::add(b2, step2);
                if (!in) continue;
                const __m128 at = _mm_add_ps(plane_row, _mm_mul_ps(plane_dx, column));
                const __m128 shade = _mm_min_ps(_mm_max_ps(_mm_shuffle_ps(at, at, 0x55), zero), one);  // clamp01
                const typename V::vf z = V::add(V::broadcast(at), dz);
                // Until its first touch this frame a pixel's samples hold depth 1 and the clear
                // colour: read as such (a load with no lane set reads no memory), no branch.
                const mask held = static_cast<mask>(0u - static_cast<unsigned>(*touched));
                *touched = 1;
                const typename V::vf stored = V::load(ones, held, p);
                const mask pass = passing<S, Test>(in, z, stored);
                if (depth_write) V::store(p, V::blend(pass, stored, z));
                else V::store(p, static_cast<mask>(~held), ones);
                V::store(p + S, V::blend(pass, V::load(clear, held, p + S), V::broadcast(shade)));
            }
        }
    }
}

template <int S>
void fill_rows_dispatch(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test,
                        bool depth_write, float clear_colour, int y0, int y1) {
    switch (test) {
        case depth_func::never: return;
        case depth_func::less: return fill_rows<S, depth_func::less>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::less_equal:
            return fill_rows<S, depth_func::less_equal>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::equal: return fill_rows<S, depth_func::equal>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::greater: return fill_rows<S, depth_func::greater>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::greater_equal:
            return fill_rows<S, depth_func::greater_equal>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::not_equal:
            return fill_rows<S, depth_func::not_equal>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::always: return fill_rows<S, depth_func::always>(store, f, pat, depth_write, clear_colour, y0, y1);
    }
}

}  // namespace

void fill_rows_avx512(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test,
                      bool depth_write, float clear_colour, int y0, int y1) {
    if (pat.count == 4) return fill_rows_sse2_dispatch<4>(store, f, pat, test, depth_write, clear_colour, y0, y1);
    if (pat.count == 16) return fill_rows_dispatch<16>(store, f, pat, test, depth_write, clear_colour, y0, y1);
    return fill_rows_dispatch<8>(store, f, pat, test, depth_write, clear_colour, y0, y1);
}

}  // namespace tiny3d::detail

#include "../avx512_region_close.inc"

#endif  // TINY3D_AVX512
