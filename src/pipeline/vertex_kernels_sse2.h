// vertex_kernels_sse2.h — the render context's vertex kernels, four vertices per SSE2
// register: projection (clip = M·p, then the vertex stage's project4 and the snap) and Gouraud shading with
// directional lights. Each is lane by lane the portable reference of vertex_transform.cpp
// (the same float operations in the same order, hence the same bits; tested in
// tests/vertex_stage_test.cpp). Included only by vertex_transform.cpp, which chooses.
#ifndef TINY3D_VERTEX_KERNELS_SSE2_H
#define TINY3D_VERTEX_KERNELS_SSE2_H

#include "../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>

#include <limits>

#include "project4.h"
#include "vertex_transform.h"

namespace tiny3d::detail {
// Internal linkage: each kernel is inlined into its one caller, vertex_transform.cpp's loop.
namespace {

// unit_or_zero (lighting.h) of four vectors in SoA form, lane by lane with the same float
// operations, hence the same bits: v·(1/√|v|²), or 0 when |v|² ≤ 1e-30 or not finite.
inline void unit_or_zero_x4(__m128 &x, __m128 &y, __m128 &z) {
    const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z));
    constexpr float MIN_LENGTH_SQUARED = 1e-30f;  // as unit_or_zero (math3d.h)
    const __m128 usable = _mm_and_ps(_mm_cmpgt_ps(len2, _mm_set1_ps(MIN_LENGTH_SQUARED)),
                                     _mm_cmplt_ps(len2, _mm_set1_ps(std::numeric_limits<float>::infinity())));
    const __m128 scale = _mm_and_ps(usable, _mm_div_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(len2)));
    x = _mm_and_ps(usable, _mm_mul_ps(x, scale));
    y = _mm_and_ps(usable, _mm_mul_ps(y, scale));
    z = _mm_and_ps(usable, _mm_mul_ps(z, scale));
}

// project_one for four vertices: clip = M·p (mul_point_scalar's operations on four
// lanes), then project4 and snap_screen_point lane by lane, so every field
// gets project_one's bits. Vertices index[0..3] of `positions`, written to the same indices
// of out and out_clip.
inline void project_x4(const mat4_t &m, const vec3_t *positions, const std::uint32_t index[4], float guard, int width,
                       int height, int subpixel_bits, xvertex *out, vec4_t *out_clip) {
    const vec3_t &p0 = positions[index[0]], &p1 = positions[index[1]], &p2 = positions[index[2]], &p3 = positions[index[3]];
    const __m128 px = _mm_setr_ps(p0.x, p1.x, p2.x, p3.x);
    const __m128 py = _mm_setr_ps(p0.y, p1.y, p2.y, p3.y);
    const __m128 pz = _mm_setr_ps(p0.z, p1.z, p2.z, p3.z);
    auto row = [&](int r) {  // m[r]·x + m[4+r]·y + m[8+r]·z + m[12+r]
        return _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(m.m[r]), px), _mm_mul_ps(_mm_set1_ps(m.m[4 + r]), py)),
                                     _mm_mul_ps(_mm_set1_ps(m.m[8 + r]), pz)),
                          _mm_set1_ps(m.m[12 + r]));
    };
    __m128 x = row(0), y = row(1), z = row(2), w = row(3);
    const projected4 s = project4(x, y, z, w, guard, static_cast<float>(width), static_cast<float>(height), true);
    alignas(16) std::uint32_t outcode[4];
    _mm_store_si128(reinterpret_cast<__m128i *>(outcode), s.outcode);
    alignas(16) float depth[4];
    _mm_store_ps(depth, s.depth);
    // snap_screen_point: usable when in front and |x|, |y| ≤ SNAP_MAX_COORD (false for NaN and ±∞ too).
    const __m128 abs_mask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff)), limit = _mm_set1_ps(SNAP_MAX_COORD);
    const int usable = _mm_movemask_ps(_mm_and_ps(s.in_front, _mm_and_ps(_mm_cmple_ps(_mm_and_ps(s.x, abs_mask), limit),
                                                                         _mm_cmple_ps(_mm_and_ps(s.y, abs_mask), limit))));
    const __m128 sub = _mm_set1_ps(static_cast<float>(1 << subpixel_bits));
    alignas(16) std::int32_t snap_x[4], snap_y[4];
    _mm_store_si128(reinterpret_cast<__m128i *>(snap_x), _mm_cvtps_epi32(_mm_mul_ps(s.x, sub)));
    _mm_store_si128(reinterpret_cast<__m128i *>(snap_y), _mm_cvtps_epi32(_mm_mul_ps(s.y, sub)));
    _MM_TRANSPOSE4_PS(x, y, z, w);
    const __m128 clip[4] = {x, y, z, w};
    for (int l = 0; l < 4; ++l) {
        xvertex &v = out[index[l]];
        alignas(16) float c[4];
        _mm_store_ps(c, clip[l]);
        out_clip[index[l]] = {c[0], c[1], c[2], c[3]};
        v.outcode = static_cast<std::uint8_t>(outcode[l]);
        v.depth = depth[l];
        v.snapped = !(v.outcode & clip_near) && ((usable >> l) & 1);
        v.snapped_x = snap_x[l];
        v.snapped_y = snap_y[l];
    }
}

// shade_gouraud_vertex(rig, ·, apply_normal_transform(nt, normals[l])) for l = 0..3 with
// directional lights only (no position needed): the scalar code's operations in the same
// order on four lanes, so each result has the same bits as the scalar one.
inline void shade_gouraud_x4(const light_rig &rig, const normal_transform &nt, const vec3_t *normals, const std::uint32_t index[4],
                      float out[4]) {
    const vec3_t &n0 = normals[index[0]], &n1 = normals[index[1]], &n2 = normals[index[2]], &n3 = normals[index[3]];
    const __m128 nx = _mm_setr_ps(n0.x, n1.x, n2.x, n3.x);
    const __m128 ny = _mm_setr_ps(n0.y, n1.y, n2.y, n3.y);
    const __m128 nz = _mm_setr_ps(n0.z, n1.z, n2.z, n3.z);
    auto row = [&](int r) {  // nt.m[3r]·n.x + nt.m[3r+1]·n.y + nt.m[3r+2]·n.z
        return _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(nt.m[3 * r]), nx), _mm_mul_ps(_mm_set1_ps(nt.m[3 * r + 1]), ny)),
                          _mm_mul_ps(_mm_set1_ps(nt.m[3 * r + 2]), nz));
    };
    __m128 x = row(0), y = row(1), z = row(2);
    unit_or_zero_x4(x, y, z);  // apply_normal_transform
    unit_or_zero_x4(x, y, z);  // shade_gouraud_vertex → shade_point's unit normal
    __m128 sum = _mm_set1_ps(rig.ambient);
    for (int k = 0; k < rig.count; ++k) {
        const light_t &l = rig.lights[k];
        const __m128 cosine = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, _mm_set1_ps(l.direction.x)), _mm_mul_ps(y, _mm_set1_ps(l.direction.y))),
                                         _mm_mul_ps(z, _mm_set1_ps(l.direction.z)));
        const __m128 lit = _mm_cmpgt_ps(cosine, _mm_setzero_ps());
        sum = _mm_add_ps(sum, _mm_and_ps(lit, _mm_mul_ps(_mm_set1_ps(l.intensity), cosine)));
    }
    // clamp01 (NaN → 0: maxps returns its second operand when one is NaN).
    _mm_store_ps(out, _mm_min_ps(_mm_max_ps(sum, _mm_setzero_ps()), _mm_set1_ps(1.0f)));
}

}  // namespace
}  // namespace tiny3d::detail

#endif  // TINY3D_SSE2
#endif
