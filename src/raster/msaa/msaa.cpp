// msaa.cpp — multisampled filled triangles (msaa.h): sample patterns, the sample store and
// its resolve, the per-triangle setup and the row fill (portable and SSE2 kernels).
#include "msaa.h"
#include "msaa_kernels.h"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <string>
#include <type_traits>

#include "../../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

namespace tiny3d::detail {

namespace {

// A pattern on the grid of 1/2^bits px from offsets given in 1/2^list_bits px (list_bits ≤ bits).
sample_pattern make_pattern(std::initializer_list<std::pair<int, int>> offsets, int list_bits, int bits) {
    sample_pattern p;
    p.count = static_cast<int>(offsets.size());
    p.bits = bits;
    const int scale = 1 << (bits - list_bits);
    int s = 0;
    for (const auto &[lx, ly] : offsets) {
        const int x = lx * scale, y = ly * scale;
        p.dx[s] = static_cast<std::int16_t>(x);
        p.dy[s] = static_cast<std::int16_t>(y);
        p.fdx[s] = static_cast<float>(x) / static_cast<float>(p.one());
        p.fdy[s] = static_cast<float>(y) / static_cast<float>(p.one());
        p.min_dx = std::min(p.min_dx, x), p.max_dx = std::max(p.max_dx, x);
        p.min_dy = std::min(p.min_dy, y), p.max_dy = std::max(p.max_dy, y);
        ++s;
    }
    return p;
}

// The pixels [x0, x1] × [y0, y1] with a sample of the pattern inside the box, clamped to clip
// (bits = pat.bits; a constant where the caller has one). True when the clamp cut the
// columns.
inline bool pattern_bounds(const snapped_box &b, const sample_pattern &pat, int bits, pixel_rect clip, int &x0, int &x1,
                           int &y0, int &y1) {
    axis_bounds(b.min_Y, b.max_Y, pat.min_dy, pat.max_dy, bits, clip.y0, clip.y1, y0, y1);
    return axis_bounds(b.min_X, b.max_X, pat.min_dx, pat.max_dx, bits, clip.x0, clip.x1, x0, x1);
}

// The offsets d[k][s] themselves (the portable kernel).
struct sample_offsets : edge_extremes {
    std::int64_t d[3][MSAA_MAX_SAMPLES];
    sample_offsets(const msaa_triangle &f, const sample_pattern &pat) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = INT64_MAX, hi[k] = INT64_MIN;
            for (int s = 0; s < pat.count; ++s) {
                d[k][s] = sample_edge_offset(f.a[k], f.b[k], pat, s);
                lo[k] = std::min(lo[k], d[k][s]), hi[k] = std::max(hi[k], d[k][s]);
            }
        }
    }
};

// The sum of a pixel's S sample colours in the order of the SSE2 resolve: lane j of four
// sums samples j, j + 4, … in turn, then (lane 0 + lane 2) + (lane 1 + lane 3).
inline float resolve_sum(const float *c, int S) {
    if (S % 4) return std::accumulate(c, c + S, 0.0f);
    float lane[4];
    for (int j = 0; j < 4; ++j) {
        lane[j] = c[j];
        for (int g = 4; g < S; g += 4) lane[j] += c[g + j];
    }
    return (lane[0] + lane[2]) + (lane[1] + lane[3]);
}

// The portable kernel: 64-bit edges, one sample at a time.
void fill_rows_portable(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test,
                        int y0, int y1) {
    const sample_offsets off(f, pat);
    const int S = pat.count;
    float dz[MSAA_MAX_SAMPLES];
    for (int s = 0; s < S; ++s) dz[s] = f.zdx * pat.fdx[s] + f.zdy * pat.fdy[s];
    for (int y = y0; y < y1; ++y) {
        const int dy = y - f.min_y;
        std::int64_t e[3];
        int lo, hi;
        off.row(f, y, e, lo, hi);
        const float zr = f.z + f.zdy * static_cast<float>(dy), ir = f.i + f.idy * static_cast<float>(dy);
        for (int x = lo; x <= hi; ++x) {
            unsigned mask = 0;
            for (int s = 0; s < S; ++s) {
                bool in = true;
                for (int k = 0; k < 3; ++k) in = in && e[k] + f.a[k] * x + off.d[k][s] >= 0;
                mask |= static_cast<unsigned>(in) << s;
            }
            if (!mask) continue;
            float *p = store.touch(f.min_x + x, y);
            const float zc = zr + f.zdx * static_cast<float>(x), shade = clamp01(ir + f.idx * static_cast<float>(x));
            float *colours = p + store.colour_offset();
            for (int s = 0; s < S; ++s) {
                const float z = zc + dz[s];
                if (!((mask >> s) & 1) || !depth_passes(test, z, p[s])) continue;
                p[s] = z;
                colours[s] = shade;
            }
        }
    }
}

#ifdef TINY3D_SSE2
#include "msaa_sse2_fill.inc"  // compare, select, fill_rows_sse2

// msaa_fill_for's SSE2 functions: the SSE2 kernel where f is chunkable, else the portable one.
template <int S, depth_func Test>
void fill_sse2(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test, int y0,
               int y1) {
    if (!clamp_to_rows(f, y0, y1)) return;
    if (!f.chunkable) return fill_rows_portable(store, f, pat, test, y0, y1);
    if constexpr (S == 4) {
        if (f.narrow) {
            if (store.blocks()) return fill_rows_sse2_narrow4<Test, true>(store, f, pat, y0, y1);
            return fill_rows_sse2_narrow4<Test, false>(store, f, pat, y0, y1);
        }
        if (store.blocks()) return fill_rows_sse2<4, Test, true>(store, f, pat, y0, y1);
    }
    fill_rows_sse2<S, Test, false>(store, f, pat, y0, y1);
}

// A resolved pixel's S samples back at rest (sample_store): depth 1, the clear colour.
template <int S>
inline void restore_sse2(float *p, __m128 far, __m128 clear) {
    for (int g = 0; g < S / 4; ++g) _mm_store_ps(p + 4 * g, far), _mm_store_ps(p + S + 4 * g, clear);
}

// resolve() for S = 4, 8, 16, the sums in resolve_sum's order.
template <int S>
void resolve_row_sse2(float *p, const std::uint8_t *touched, int width, float clear_colour, float *colour, float *z) {
    const __m128 inv = _mm_set1_ps(1.0f / S), clear = _mm_set1_ps(clear_colour), far = _mm_set1_ps(1.0f);
    int x = 0;
    if constexpr (S == 4) {
        // Four pixels at a time: per pixel (s0 + s2) + (s1 + s3) and the nearest sample, by
        // transposing the four pixels' sample vectors. The tile is at rest (sample_store): an
        // unmarked pixel among them sums to exactly 4·clear, nearest 1, so no select.
        for (; x + 4 <= width; x += 4, p += 4 * 2 * S) {
            std::uint32_t t4;
            std::memcpy(&t4, touched + x, sizeof t4);
            if (t4 == 0) {
                _mm_storeu_ps(colour + x, clear), _mm_storeu_ps(z + x, far);
                continue;
            }
            auto pairs = [&](int offset, auto op) {  // op over (s0, s2) and (s1, s3) of pixels 0..3
                const __m128 q0 = _mm_loadu_ps(p + offset), q1 = _mm_loadu_ps(p + 2 * S + offset);
                const __m128 q2 = _mm_loadu_ps(p + 4 * S + offset), q3 = _mm_loadu_ps(p + 6 * S + offset);
                const __m128 v01 = op(_mm_unpacklo_ps(q0, q1), _mm_unpackhi_ps(q0, q1));  // (0:02, 1:02, 0:13, 1:13)
                const __m128 v23 = op(_mm_unpacklo_ps(q2, q3), _mm_unpackhi_ps(q2, q3));
                return op(_mm_movelh_ps(v01, v23), _mm_movehl_ps(v23, v01));
            };
            const __m128 c = _mm_mul_ps(pairs(S, [](__m128 u, __m128 v) { return _mm_add_ps(u, v); }), inv);
            const __m128 d = pairs(0, [](__m128 u, __m128 v) { return _mm_min_ps(u, v); });
            _mm_storeu_ps(colour + x, c), _mm_storeu_ps(z + x, d);
            for (int k = 0; k < 4; ++k) restore_sse2<S>(p + k * 2 * S, far, clear);
        }
    }
    for (; x < width; ++x, p += 2 * S) {
        if (!touched[x]) {
            // Sixteen untouched pixels at once (the background).
            if (x + 16 <= width &&
                _mm_movemask_epi8(_mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i *>(touched + x)),
                                                 _mm_setzero_si128())) == 0xFFFF) {
                for (int k = 0; k < 16; k += 4) _mm_storeu_ps(colour + x + k, clear), _mm_storeu_ps(z + x + k, far);
                x += 15;
                p += 15 * 2 * S;
                continue;
            }
            colour[x] = clear_colour;
            z[x] = 1.0f;
            continue;
        }
        __m128 sum = _mm_loadu_ps(p + S), nearest = _mm_loadu_ps(p);
        for (int g = 1; g < S / 4; ++g) {
            sum = _mm_add_ps(sum, _mm_loadu_ps(p + S + 4 * g));
            nearest = _mm_min_ps(nearest, _mm_loadu_ps(p + 4 * g));
        }
        sum = _mm_add_ps(sum, _mm_movehl_ps(sum, sum));
        sum = _mm_add_ss(sum, _mm_shuffle_ps(sum, sum, 1));
        nearest = _mm_min_ps(nearest, _mm_movehl_ps(nearest, nearest));
        nearest = _mm_min_ss(nearest, _mm_shuffle_ps(nearest, nearest, 1));
        colour[x] = _mm_cvtss_f32(_mm_mul_ss(sum, inv));
        z[x] = _mm_cvtss_f32(nearest);
        restore_sse2<S>(p, far, clear);
    }
}
#endif

// make_msaa_triangle on the grid of 1/2^Bits px (= pat.bits): the shifts and scales are
// constants (a runtime shift count and 1/2^bits are a variable shift and a multiply per use).
template <int Bits>
bool make_msaa_triangle_on(const std::int32_t X[3], const std::int32_t Y[3], std::int64_t area2,
                           const sample_pattern &pat, pixel_rect clip, const float depth[3], const float intensity[3],
                           msaa_triangle &out) {
    constexpr std::int64_t one = std::int64_t{1} << Bits;
    const snapped_box box = snapped_box::of(X, Y);
    out.clipped_x = pattern_bounds(box, pat, Bits, clip, out.min_x, out.max_x, out.min_y, out.max_y);
    if (out.min_x > out.max_x || out.min_y > out.max_y) return false;
    // triangle_setup_snapped's edges (oriented by s, top-left bias) at the centre (cx, cy) of
    // pixel (min_x, min_y).
    const std::int64_t s = area2 > 0 ? 1 : -1;
    const std::int64_t cx = one * static_cast<std::int64_t>(out.min_x) + one / 2;
    const std::int64_t cy = one * static_cast<std::int64_t>(out.min_y) + one / 2;
    for (int k = 0; k < 3; ++k) {
        const snapped_edge edge = snapped_edge_at(X, Y, s, k, cx, cy);
        out.a[k] = -edge.dy * one;
        out.b[k] = edge.dx * one;
        out.e[k] = edge.e;
    }
    // Sample points lie within one px of the snapped box: |E| < 2·(span + one)·span < 2^31.
    out.narrow = box.max_X - box.min_X < span_limit(Bits) && box.max_Y - box.min_Y < span_limit(Bits);
    out.chunkable = true;
    for (int k = 0; k < 3; ++k)
        out.chunkable = out.chunkable && std::abs(out.a[k]) + std::abs(out.b[k]) < (std::int64_t{1} << 28);
    double x[3], y[3];
    snapped_to_px(X, Y, x, y, Bits);
    set_planes(x, y, depth, intensity, out);
    return true;
}

void fill_nothing(sample_store &, const msaa_triangle &, const sample_pattern &, depth_func, int, int) {}

void fill_portable(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test, int y0,
                   int y1) {
    if (clamp_to_rows(f, y0, y1)) fill_rows_portable(store, f, pat, test, y0, y1);
}

}  // namespace

const sample_pattern &pattern_of(int samples) {
    static const sample_pattern one = make_pattern({{0, 0}}, RASTER_SUBPIXEL_BITS, RASTER_SUBPIXEL_BITS);
    static const sample_pattern four =
        make_pattern({{-2, -6}, {6, -2}, {-6, 2}, {2, 6}}, RASTER_SUBPIXEL_BITS, RASTER_SUBPIXEL_BITS);
    static const sample_pattern eight = make_pattern(
        {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}}, RASTER_SUBPIXEL_BITS, RASTER_SUBPIXEL_BITS);
    // Sample (i, j), i, j = 0..3, at ((4i + j − 7.5)/16, (4j − i − 4.5)/16) px: in 1/32 px,
    // (8i + 2j − 15, 8j − 2i − 9).
    static const sample_pattern sixteen =
        make_pattern({{-15, -9}, {-13, -1}, {-11, 7}, {-9, 15}, {-7, -11}, {-5, -3}, {-3, 5}, {-1, 13},
                      {1, -13}, {3, -5}, {5, 3}, {7, 11}, {9, -15}, {11, -7}, {13, 1}, {15, 9}},
                     5, MSAA_16_SUBPIXEL_BITS);
    switch (samples) {
        case 4: return four;
        case 8: return eight;
        case 16: return sixteen;
        default: return one;
    }
}

void sample_store::resize(int width, int rows, int samples, float clear_colour, bool blocks) {
    constexpr std::size_t ALIGN_FLOATS = 64 / sizeof(float);
    blocks = blocks && samples == 4;
    const int stride = (width + STRIDE_PIXELS - 1) / STRIDE_PIXELS * STRIDE_PIXELS;
    // (blocks: an odd last row paired with a row of padding)
    const std::size_t pixels = static_cast<std::size_t>(stride) * static_cast<std::size_t>(rows + (blocks && rows % 2));
    const float *before = base_;
    if (data_.size() < pixels * 2 * samples + ALIGN_FLOATS) data_.resize(pixels * 2 * samples + ALIGN_FLOATS);
    if (touched_.size() < pixels) touched_.resize(pixels);
    const std::size_t misalign = reinterpret_cast<std::uintptr_t>(data_.data()) % 64 / sizeof(float);
    base_ = data_.data() + (misalign ? ALIGN_FLOATS - misalign : 0);
    const bool same = base_ == before && stride == stride_ && rows == rows_ && samples == samples_ &&
                      blocks == blocks_ && std::memcmp(&clear_colour, &rest_colour_, sizeof clear_colour) == 0;
    stride_ = stride;
    width_ = width;
    rows_ = rows;
    samples_ = samples;
    blocks_ = blocks;
    if (same) return;  // (at rest already: a first resize has base_ != before)
    // Both layouts are runs of colour_offset() depths, then as many colours (a pixel's in
    // rows, a block's in blocks).
    const std::size_t run = static_cast<std::size_t>(colour_offset());
    for (float *p = base_, *end = base_ + pixels * 2 * samples; p < end; p += 2 * run) {
        std::fill_n(p, run, 1.0f);
        std::fill_n(p + run, run, clear_colour);
    }
    rest_colour_ = clear_colour;
}

void sample_store::start(int y0, int y1) {
    origin_ = y0;
    end_ = std::min(y1, y0 + rows_);
    if (origin_ < end_) std::fill(touched_row(origin_), touched_row(end_), std::uint8_t{0});
}

void sample_store::put_at_rest(float *pixel) const {
    std::fill(pixel, pixel + samples_, 1.0f);
    std::fill_n(pixel + colour_offset(), samples_, rest_colour_);
}

void sample_store::resolve(canvas_t &canvas, zbuffer &depth, msaa_kernel kernel) {
    const int S = samples_;
    const float clear_colour = rest_colour_;
    const float inv = 1.0f / static_cast<float>(S);
    const kernel_table &k = kernels_for(kernel);
    int first_column = 0;  // (the columns before it resolved already)
    if (blocks_ && k.resolve_blocks4) {  // a row of blocks at a time, eight columns per step
        first_column = width_ / 8 * 8;
        for (int y = origin_; y < end_; y += 2) {
            const bool two = y + 1 < end_;
            k.resolve_blocks4(pixel(0, y), touched_row(y), two ? touched_row(y + 1) : nullptr, first_column,
                                   clear_colour, canvas.pixels[y], depth.row(y), two ? canvas.pixels[y + 1] : nullptr,
                                   two ? depth.row(y + 1) : nullptr);
        }
    }
    for (int y = origin_; y < end_; ++y) {
        const std::uint8_t *touched = touched_row(y);
        float *colour = canvas.pixels[y], *z = depth.row(y);
#ifdef TINY3D_SSE2
        // A row's first multiple of 8 columns by the table's eight-pixel resolve (if it has
        // one for N samples), the rest by SSE2's.
        const auto simd_row = [&]<int N>(std::integral_constant<int, N>, auto *eight_pixels) {
            const int wide = eight_pixels ? width_ / 8 * 8 : 0;
            if (wide > 0) eight_pixels(pixel(0, y), touched, wide, clear_colour, colour, z);
            resolve_row_sse2<N>(pixel(wide, y), touched + wide, width_ - wide, clear_colour, colour + wide, z + wide);
        };
        switch (!k.resolve_rows_simd || blocks_ ? 0 : S) {
            case 4: resolve_row_sse2<4>(pixel(0, y), touched, width_, clear_colour, colour, z); continue;  // (rows tile)
            case 8: simd_row(std::integral_constant<int, 8>{}, k.resolve_rows8); continue;
            case 16: simd_row(std::integral_constant<int, 16>{}, k.resolve_rows16); continue;
            default: break;
        }
#endif
        for (int x = first_column; x < width_; ++x) {
            // (An unmarked pixel holds the clear values, in memory when at rest; but the block
            // kernel marks only a block's first pixel, so the block tile's are read.)
            if (!touched[x] && !blocks_) {
                colour[x] = clear_colour;
                z[x] = 1.0f;
                continue;
            }
            float *p = pixel(x, y);
            colour[x] = resolve_sum(p + colour_offset(), S) * inv;
            z[x] = *std::min_element(p, p + S);
            put_at_rest(p);
        }
    }
}

void msaa_bounds(const std::int32_t X[3], const std::int32_t Y[3], const sample_pattern &pat, pixel_rect clip, int &x0,
                 int &x1, int &y0, int &y1) {
    pattern_bounds(snapped_box::of(X, Y), pat, pat.bits, clip, x0, x1, y0, y1);
}

bool make_msaa_triangle(const std::int32_t X[3], const std::int32_t Y[3], std::int64_t area2, const sample_pattern &pat,
                        pixel_rect clip, const float depth[3], const float intensity[3], msaa_triangle &out) {
    if (pat.bits == MSAA_16_SUBPIXEL_BITS)
        return make_msaa_triangle_on<MSAA_16_SUBPIXEL_BITS>(X, Y, area2, pat, clip, depth, intensity, out);
    return make_msaa_triangle_on<RASTER_SUBPIXEL_BITS>(X, Y, area2, pat, clip, depth, intensity, out);
}

#ifdef TINY3D_SSE2
msaa_row_fill msaa_fill_sse2(int samples, depth_func test) {
    return fill_function(samples, test, [](auto s, auto t) -> msaa_row_fill { return &fill_sse2<s.value, t.value>; });
}
#endif

msaa_row_fill msaa_fill_for(msaa_kernel kernel, int samples, depth_func test) {
    if (test == depth_func::never) return fill_nothing;
    const auto simd = kernels_for(kernel).msaa_fill;
    if (simd && (samples == 4 || samples == 8 || samples == 16)) return simd(samples, test);
    return fill_portable;
}

void fill_with(msaa_kernel kernel, int samples, sample_store &store, const msaa_triangle &f, const sample_pattern &pat,
               depth_func test, int y0, int y1) {
    msaa_fill_for(kernel, samples, test)(store, f, pat, test, y0, y1);
}

}  // namespace tiny3d::detail

namespace tiny3d {

result<sample_count> parse_sample_count(const std::string &text) {
    std::string t = text;
    if (!t.empty() && (t.back() == 'x' || t.back() == 'X')) t.pop_back();
    if (t == "1") return sample_count::x1;
    if (t == "4") return sample_count::x4;
    if (t == "8") return sample_count::x8;
    if (t == "16") return sample_count::x16;
    return error{"", 0, -1, "samples per pixel \"" + text + "\": expected 1, 4, 8 or 16"};
}

}  // namespace tiny3d
