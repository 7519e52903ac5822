// msaa_avx512.cpp — the multisample fill's AVX-512 kernels (msaa_kernel::avx512). 8× and
// 16×: one pixel's depths in one register and its colours in another. Per pixel: the three
// edge values at every sample stepped by one add each, coverage as a mask register (the
// sign bits of their OR), the depth test as a masked compare and the writes as blends —
// where the SSE2 kernel needs two or four groups of four. 4×: a 2 × 2 block of pixels per
// register (fill_rows_blocks) for narrow triangles; for the others the SSE2 kernel's source
// compiled here (msaa_sse2_fill.inc), where it has 32 vector registers.
//
// Compiled for AVX-512 inside the target region of avx512_region_open.inc (as
// line_tabulated_avx512.cpp is): the headers are included before the region opens, so
// their inline functions stay baseline x86-64. Run only on CPUs that have it
// (kernels_run, src/kernels.cpp). No FMA contraction: the portable kernel's float operations, rounded
// step by step, lane by lane.
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "msaa_kernels.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX512
#include <emmintrin.h>
#include <immintrin.h>

#include "../../avx512_region_open.inc"

namespace tiny3d::detail {
namespace {

// 4×: the SSE2 kernel's source, compiled here for AVX-512 (msaa_sse2_fill.inc).
#include "msaa_sse2_fill.inc"

// One register of S samples: 16 floats (zmm) for 16×, 8 (ymm) for 8× — a pixel's depths or
// colours exactly, so no access reaches a neighbouring pixel (a 16-lane access with lanes
// masked off still overlaps the next pixel's samples and defeats store-to-load forwarding).
// Masks: bit s = sample s.
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

// Narrow triangles whose boxes are at most this many columns wide are walked whole, every
// pixel of the box, without the row spans' divisions (most of Scene S's triangles: a few
// empty pixels cost less than two divisions per row); the others row span by row span. The
// 4× block kernel likewise.
constexpr int SCAN_COLUMNS_AVX512 = 16;

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
    const bool scan = f.narrow && f.max_x - f.min_x < SCAN_COLUMNS_AVX512;
    for (int y = y0; y < y1; ++y) {
        // The row's span: 32-bit divisions when narrow (shorter latency), else 64-bit.
        std::int64_t e64[3];
        int lo, hi;
        if (scan) {
            for (int k = 0; k < 3; ++k) e64[k] = f.e[k] + f.b[k] * (y - f.min_y);
            lo = 0, hi = f.max_x - f.min_x;
        } else if (f.narrow) {
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
            // row of a small triangle has too few pixels for the hardware prefetcher to start.
            if (y + 1 < y1 && first == lo) {
                const char *below = reinterpret_cast<const char *>(p + static_cast<std::size_t>(store.stride()) * 2 * S);
                for (int line = 0; line < 2 * S * 4; line += 64) _mm_prefetch(below + line, _MM_HINT_T0);
            }
            __m128 column = _mm_set1_ps(static_cast<float>(first));  // exactly (< 2^24)
            for (int x = first; x <= last; ++x, p += 2 * S, ++touched, column = _mm_add_ps(column, one)) {
                // A sample is in when all three edge values are ≥ 0. A pixel without one is
                // stored back as it was, without a branch (cheaper than its mispredictions at
                // the spans' ends).
                const mask in = static_cast<mask>(~V::outside(b0, b1, b2));
                b0 = V::add(b0, step0), b1 = V::add(b1, step1), b2 = V::add(b2, step2);
                const __m128 at = _mm_add_ps(plane_row, _mm_mul_ps(plane_dx, column));
                const __m128 shade = _mm_min_ps(_mm_max_ps(_mm_shuffle_ps(at, at, 0x55), zero), one);  // clamp01
                const typename V::vf z = V::add(V::broadcast(at), dz);
                // Until its first touch this frame a pixel's samples hold depth 1 and the clear
                // colour: loaded whatever they hold and selected away (the loads need not wait
                // for the touched byte), no branch.
                const mask held = static_cast<mask>(0u - static_cast<unsigned>(*touched));
                *touched = static_cast<std::uint8_t>(*touched | (in != 0));
                const typename V::vf stored = V::blend(held, ones, V::load(p));
                const mask pass = passing<S, Test>(in, z, stored);
                if (depth_write) V::store(p, V::blend(pass, stored, z));
                else V::store(p, static_cast<mask>(~held), ones);
                V::store(p + S, V::blend(pass, V::blend(held, clear, V::load(p + S)), V::broadcast(shade)));
            }
        }
    }
}

// 4× on narrow triangles: a 2 × 2 block of pixels per step, its 16 samples in one register
// (lane 4q + s: sample s of pixel q = 2r + j, column j and row r of the block) — the
// 4-sample tile's own block (sample_store: columns paired from 0, rows from the tile's
// origin), its 16 depths and 16 colours two aligned 64-byte lines, loaded and stored whole
// as they are, so a later triangle's loads of the same block are forwarded from this one's
// stores. For small triangles (Scene S's are ~13 px) a 2 × 2 block beats four pixels of a
// row: fewer groups to visit and half as many row starts (documentation/antialias.md,
// "How a multisampled frame is drawn").

// Clipped (f.clipped_x): the pixels beside the bounds may hold covered samples, so the lanes
// of a block's column past them are masked off; otherwise no sample there is inside f and
// the mask is left out, the block's column stepped in float (no mask to build per block).
template <depth_func Test, bool Clipped>
void fill_rows_blocks(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, bool depth_write, int y0,
                      int y1) {
    constexpr int S = 4;
    using V = samples<16>;
    // Lane 4q + s: sample s's offset from its pixel's centre (ox, oy: the pattern's four,
    // once per pixel) and from pixel 0's (bx = j + dx/16, by = r + dy/16, exact). The edge
    // offsets a·bx + b·by = −Δy·(16j + dx) + Δx·(16r + dy) are integers below 2^22
    // (f.narrow: |a|, |b| < 2^19), so the float products and the sum are exact; the depth
    // offsets are the portable kernel's float operations (sample s alone: the column and row
    // are in the planes' steps).
    const __m512i lane_column = _mm512_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 1);
    const __m512i lane_row = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1);
    const __m512 ox = _mm512_broadcast_f32x4(_mm_load_ps(pat.fdx)), oy = _mm512_broadcast_f32x4(_mm_load_ps(pat.fdy));
    const __m512 bx = V::add(ox, _mm512_cvtepi32_ps(lane_column)), by = V::add(oy, _mm512_cvtepi32_ps(lane_row));
    const int columns = f.max_x - f.min_x + 1;
    const bool scan = columns <= SCAN_COLUMNS_AVX512;
    edge_extremes off;  // (row spans only) over pixel 0's lanes: the pattern's own offsets
    __m512i d[3];
    for (int k = 0; k < 3; ++k) {
        d[k] = _mm512_cvtps_epi32(_mm512_add_ps(_mm512_mul_ps(V::set(static_cast<float>(f.a[k])), bx),
                                                _mm512_mul_ps(V::set(static_cast<float>(f.b[k])), by)));
        if (scan) continue;
        off.lo[k] = _mm512_mask_reduce_min_epi32(0xF, d[k]);
        off.hi[k] = _mm512_mask_reduce_max_epi32(0xF, d[k]);
    }
    const __m512 dz = _mm512_add_ps(_mm512_mul_ps(V::set(f.zdx), ox), _mm512_mul_ps(V::set(f.zdy), oy));
    const __m512i step0 = V::set_int(2 * f.a[0]), step1 = V::set_int(2 * f.a[1]), step2 = V::set_int(2 * f.a[2]);
    const __m512 ones = V::set(1.0f), zero = _mm512_setzero_ps();
    const __m512 zdx = V::set(f.zdx), idx = V::set(f.idx), zdy = V::set(f.zdy), idy = V::set(f.idy);
    const __m512 z0 = V::set(f.z), i0 = V::set(f.i);
    const __m512i two_columns = _mm512_set1_epi32(2);
    const __m512i last_column = _mm512_set1_epi32(f.max_x - f.min_x);
    const __m512 two_columns_f = V::set(2.0f);
    const int odd = f.min_x & 1;  // the blocks start one column left of min_x
    // The tile's blocks pair rows from its origin: the first block may start a row above y0
    // and the last end a row below y1 (a row of the tile or its padding). Their lanes are
    // masked off, so their samples are stored back as they were. The tile is at rest, so a
    // mark only tells the resolve where to read: one per block, on its first pixel
    // (sample_store), whatever rows or samples were drawn (a branch on the rows drawn, or a
    // read of the marks, took the layout's gain back).
    const __mmask16 writes = depth_write ? 0xFFFF : 0;
    // The edge values at a row pair's first block (column `first` relative to min_x): 32
    // bits, wrapping as the 64-bit values' truncation does.
    auto start = [&](const std::int32_t e[3], int first, __m512i &b0, __m512i &b1, __m512i &b2) {
        b0 = V::add(V::set_int(e[0] + static_cast<std::int32_t>(f.a[0]) * first), d[0]);
        b1 = V::add(V::set_int(e[1] + static_cast<std::int32_t>(f.a[1]) * first), d[1]);
        b2 = V::add(V::set_int(e[2] + static_cast<std::int32_t>(f.a[2]) * first), d[2]);
    };
    const int top = y0 - ((y0 - store.origin()) & 1);
    __m512i scan_b0, scan_b1, scan_b2;
    const __m512i down0 = V::set_int(2 * f.b[0]), down1 = V::set_int(2 * f.b[1]), down2 = V::set_int(2 * f.b[2]);
    if (scan) {
        std::int32_t e[3];
        for (int k = 0; k < 3; ++k) e[k] = static_cast<std::int32_t>(f.e[k] + f.b[k] * (top - f.min_y));
        start(e, -odd, scan_b0, scan_b1, scan_b2);
    }
    for (int y = top; y < y1; y += 2) {
        const bool upper = y >= y0, lower = y + 1 < y1;  // the block's rows drawn
        const __mmask16 rows_drawn = static_cast<__mmask16>((upper ? 0x00FF : 0) | (lower ? 0xFF00 : 0));
        const int dy = y - f.min_y;
        int lo = 0, hi = columns - 1;
        __m512i b0, b1, b2;
        if (scan) {  // every row pair from the same first block: the last pair's values + 2·b
            b0 = scan_b0, b1 = scan_b1, b2 = scan_b2;
            scan_b0 = V::add(scan_b0, down0), scan_b1 = V::add(scan_b1, down1), scan_b2 = V::add(scan_b2, down2);
        } else {
            // (row sets e whatever it returns; narrow: within a row of the box, e fits 32 bits)
            std::int32_t e[3], e1[3];
            int lo1, hi1;
            const bool row0 = off.row(f, y, e, lo, hi) && upper, row1 = lower && off.row(f, y + 1, e1, lo1, hi1);
            if (!row0 && !row1) continue;
            if (!row0) lo = lo1, hi = hi1;
            else if (row1) lo = std::min(lo, lo1), hi = std::max(hi, hi1);
            start(e, lo - ((lo + odd) & 1), b0, b1, b2);
        }
        const int first = lo - ((lo + odd) & 1);  // relative to min_x, at an even canvas column
        __m512i column = _mm512_add_epi32(_mm512_set1_epi32(first), lane_column);
        __m512 at = _mm512_cvtepi32_ps(column);  // (exactly: < 2^24; stepped exactly)
        const __m512 rows = _mm512_cvtepi32_ps(_mm512_add_epi32(_mm512_set1_epi32(dy), lane_row));  // exactly
        const __m512 z_row = V::add(z0, V::mul(zdy, rows)), i_row = V::add(i0, V::mul(idy, rows));
        std::uint8_t *touched = store.touched_row(y) + f.min_x + first;
        float *p = store.pixel(f.min_x + first, y);
        for (int x = first; x <= hi; x += 2, p += 32, touched += 2, at = V::add(at, two_columns_f)) {
            // In: every edge value ≥ 0, and the pixel in the block's rows drawn (and, clipped,
            // inside the bounds' columns).
            __mmask16 inside = rows_drawn;
            if constexpr (Clipped) {
                inside = _mm512_mask_cmple_epu32_mask(inside, column, last_column);
                column = _mm512_add_epi32(column, two_columns);
            }
            const __mmask16 in = _mm512_mask_testn_epi32_mask(inside, _mm512_ternarylogic_epi32(b0, b1, b2, 0xFE),
                                                              _mm512_set1_epi32(INT32_MIN));
            b0 = V::add(b0, step0), b1 = V::add(b1, step1), b2 = V::add(b2, step2);
            // No early exit for a block without a covered sample: it is loaded and stored back
            // as it was, which costs less than the branch's mispredictions (about half the
            // blocks of a small triangle's box are empty, unpredictably).
            const __m512 z = V::add(V::add(z_row, V::mul(zdx, at)), dz);
            const __m512 shade = _mm512_min_ps(_mm512_max_ps(V::add(i_row, V::mul(idx, at)), zero), ones);  // clamp01
            // The 4-sample tile is at rest between bands (sample_store): an untouched pixel's
            // samples hold depth 1 and the clear colour in memory too, so the lines are used as
            // loaded, touched or not (no test of the touched bytes; frames identical). The
            // block's mark is set without a test of the coverage (a store beats a branch).
            // The depth write is a mask, not a branch (with the branch GCC moved the pass mask
            // through a general register and back).
            const __m512 stored = _mm512_load_ps(p), colours = _mm512_load_ps(p + sample_store::colour_offset(S, true));
            const __mmask16 pass = passing<16, Test>(in, z, stored);
            _mm512_store_ps(p, _mm512_mask_blend_ps(_kand_mask16(pass, writes), stored, z));
            _mm512_store_ps(p + sample_store::colour_offset(S, true), _mm512_mask_blend_ps(pass, colours, shade));
            *touched = 1;
        }
    }
}

template <int S, depth_func Test>
void fill_avx512(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test,
                 bool depth_write, float clear_colour, int y0, int y1) {
    if (!f.chunkable)
        return msaa_fill_for(msaa_kernel::portable, S, test)(store, f, pat, test, depth_write, clear_colour, y0, y1);
    if (!clamp_to_rows(f, y0, y1)) return;
    if constexpr (S == 4) {
        if (!store.blocks()) fill_rows_sse2<4, Test, false>(store, f, pat, depth_write, clear_colour, y0, y1);
        else if (f.narrow && f.clipped_x) fill_rows_blocks<Test, true>(store, f, pat, depth_write, y0, y1);
        else if (f.narrow) fill_rows_blocks<Test, false>(store, f, pat, depth_write, y0, y1);
        else fill_rows_sse2<4, Test, true>(store, f, pat, depth_write, clear_colour, y0, y1);
    } else {
        fill_rows<S, Test>(store, f, pat, depth_write, clear_colour, y0, y1);
    }
}

}  // namespace

msaa_row_fill fill_function_avx512(int samples, depth_func test) {
    return fill_function(samples, test, [](auto s, auto t) -> msaa_row_fill { return &fill_avx512<s.value, t.value>; });
}

// Eight columns of a row of blocks (four blocks: sixteen pixels of two rows) at a time.
// Per 128-bit lane q a block's register holds pixel q's four samples. The SSE2 resolve's
// transpose (unpacks, then the low and high halves) runs on all four lanes of two pairs
// of blocks at once, the colour sums and depth minima both, leaving in lane q pixel q of
// blocks 0..3; one permute puts them in column order, row 0 in the low half and row 1 in
// the high half. An untouched pixel's samples hold (1, clear) at rest, whose sum is
// exactly 4·clear and minimum 1: no select.
void resolve_blocks4_avx512(float *p, const std::uint8_t *touched0, const std::uint8_t *touched1, int pixels,
                            float clear_colour, float *colour0, float *z0, float *colour1, float *z1) {
    const __m512 far = _mm512_set1_ps(1.0f), clear = _mm512_set1_ps(clear_colour), quarter = _mm512_set1_ps(0.25f);
    // Lane i < 8: column i of row 0 (block i/2, pixel i%2: lane 4·(i%2) + i/2); lanes 8..15 row 1.
    const __m512i column_order = _mm512_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7, 8, 12, 9, 13, 10, 14, 11, 15);
    for (int x = 0; x < pixels; x += 8, p += 4 * 32) {
        // Row 0's eight pixels from the low halves, row 1's (if any) from the high halves.
        auto put = [&](__m512 colours, __m512 depths) {
            _mm256_storeu_ps(colour0 + x, _mm512_castps512_ps256(colours));
            _mm256_storeu_ps(z0 + x, _mm512_castps512_ps256(depths));
            if (!colour1) return;
            _mm256_storeu_ps(colour1 + x, _mm512_extractf32x8_ps(colours, 1));
            _mm256_storeu_ps(z1 + x, _mm512_extractf32x8_ps(depths, 1));
        };
        std::uint64_t t0, t1 = 0;
        std::memcpy(&t0, touched0 + x, sizeof t0);
        if (touched1) std::memcpy(&t1, touched1 + x, sizeof t1);
        if ((t0 | t1) == 0) {
            put(clear, far);
            continue;
        }
        // (s0 + s2) + (s1 + s3) (op = add) or the minimum in the same order (op = min) of
        // every pixel, from the four blocks' registers at `offset` (depths 0, colours 16).
        auto reduce = [p](int offset, auto op) {
            const __m512 b0 = _mm512_load_ps(p + offset), b1 = _mm512_load_ps(p + 32 + offset);
            const __m512 b2 = _mm512_load_ps(p + 64 + offset), b3 = _mm512_load_ps(p + 96 + offset);
            // Per lane: (s0 + s2, s0' + s2', s1 + s3, s1' + s3') of blocks 0 and 1 (2 and 3).
            const __m512 v01 = op(_mm512_unpacklo_ps(b0, b1), _mm512_unpackhi_ps(b0, b1));
            const __m512 v23 = op(_mm512_unpacklo_ps(b2, b3), _mm512_unpackhi_ps(b2, b3));
            return op(_mm512_shuffle_ps(v01, v23, _MM_SHUFFLE(1, 0, 1, 0)),
                      _mm512_shuffle_ps(v01, v23, _MM_SHUFFLE(3, 2, 3, 2)));
        };
        const __m512 colours = _mm512_mul_ps(
            _mm512_permutexvar_ps(column_order, reduce(16, [](__m512 u, __m512 v) { return _mm512_add_ps(u, v); })), quarter);
        const __m512 depths =
            _mm512_permutexvar_ps(column_order, reduce(0, [](__m512 u, __m512 v) { return _mm512_min_ps(u, v); }));
        put(colours, depths);
        for (int k = 0; k < 4; ++k) _mm512_store_ps(p + 32 * k, far), _mm512_store_ps(p + 32 * k + 16, clear);
    }
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"

#endif  // TINY3D_AVX512
