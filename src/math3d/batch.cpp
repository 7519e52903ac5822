// batch.cpp — transforming points one at a time and by the span.
//
// The batch kernels compute exactly the scalar expression of mat4_mul_vec4 with w = 1,
// ((m0·x + m4·y) + m8·z) + m12 per row, in the same order, so results are bit-identical
// to apply_transform (x86-64 has no FMA contraction at the baseline ISA). With SSE2 one
// point is one 4-lane column combination: the four rows at once.
#include <string>

#include "math3d.h"
#include "../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

using tiny3d::mul_point_scalar;

namespace {

bool divides_by(float w) { return w != 0.0f && w != 1.0f; }

tiny3d::status size_error(const char *function, std::size_t in, std::size_t out) {
    return tiny3d::error{"", 0, -1,
                         std::string(function) + ": output holds " + std::to_string(out) + " points, input has " +
                             std::to_string(in)};
}

#ifdef TINY3D_SSE2
struct columns {
    __m128 c0, c1, c2, c3;
};

columns load_columns(const mat4_t &m) {
    return {_mm_loadu_ps(m.m), _mm_loadu_ps(m.m + 4), _mm_loadu_ps(m.m + 8), _mm_loadu_ps(m.m + 12)};
}

// (x', y', z', w') = M·(p, 1), lane order x, y, z, w.
inline __m128 mul_point(const columns &c, vec3_t p) {
    __m128 r = _mm_mul_ps(c.c0, _mm_set1_ps(p.x));
    r = _mm_add_ps(r, _mm_mul_ps(c.c1, _mm_set1_ps(p.y)));
    r = _mm_add_ps(r, _mm_mul_ps(c.c2, _mm_set1_ps(p.z)));
    return _mm_add_ps(r, c.c3);  // m12·1 = m12 exactly
}

// Divides all lanes by w where apply_transform would (w ∉ {0, 1}), by 1 otherwise.
inline __m128 divide_like_apply_transform(__m128 r) {
    const __m128 w = _mm_shuffle_ps(r, r, _MM_SHUFFLE(3, 3, 3, 3));
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 keep = _mm_or_ps(_mm_cmpeq_ps(w, _mm_setzero_ps()), _mm_cmpeq_ps(w, one));
    const __m128 divisor = _mm_or_ps(_mm_and_ps(keep, one), _mm_andnot_ps(keep, w));
    return _mm_div_ps(r, divisor);
}

// Writes lanes x, y, z only (8 + 4 bytes), so in-place batches never touch the next point.
inline void store_xyz(vec3_t &out, __m128 r) {
    _mm_storel_pi(reinterpret_cast<__m64 *>(&out.x), r);
    _mm_store_ss(&out.z, _mm_movehl_ps(r, r));
}
#endif

}  // namespace

vec3_t apply_transform(mat4_t m, vec3_t v) { return tiny3d::transform_point(m, v).point; }

namespace tiny3d {

transformed_point transform_point(const mat4_t &m, vec3_t p) {
    const vec4_t h = mul_point_scalar(m, p);
    if (divides_by(h.w)) return {{h.x / h.w, h.y / h.w, h.z / h.w}, h.w, true};
    return {{h.x, h.y, h.z}, h.w, false};
}

vec3_t transform_direction(const mat4_t &m, vec3_t d) {
    return {m.m[0] * d.x + m.m[4] * d.y + m.m[8] * d.z, m.m[1] * d.x + m.m[5] * d.y + m.m[9] * d.z,
            m.m[2] * d.x + m.m[6] * d.y + m.m[10] * d.z};
}

status transform_points(const mat4_t &m, std::span<const vec3_t> in, std::span<vec3_t> out) {
    if (out.size() < in.size()) return size_error("transform_points", in.size(), out.size());
#ifdef TINY3D_SSE2
    const columns c = load_columns(m);
    for (std::size_t i = 0; i < in.size(); ++i) store_xyz(out[i], divide_like_apply_transform(mul_point(c, in[i])));
#else
    for (std::size_t i = 0; i < in.size(); ++i) out[i] = transform_point(m, in[i]).point;
#endif
    return {};
}

status transform_points_homogeneous(const mat4_t &m, std::span<const vec3_t> in, std::span<vec4_t> out) {
    if (out.size() < in.size()) return size_error("transform_points_homogeneous", in.size(), out.size());
#ifdef TINY3D_SSE2
    const columns c = load_columns(m);
    for (std::size_t i = 0; i < in.size(); ++i) _mm_storeu_ps(&out[i].x, mul_point(c, in[i]));
#else
    for (std::size_t i = 0; i < in.size(); ++i) out[i] = mul_point_scalar(m, in[i]);
#endif
    return {};
}

}  // namespace tiny3d
