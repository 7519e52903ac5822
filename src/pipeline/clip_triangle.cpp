// clip_triangle.cpp — Sutherland–Hodgman clipping of triangles in clip space (near and far
// planes, and the x/y guard band), attributes interpolated with the same parameter.
#include "pipeline.h"

namespace tiny3d {

namespace {

constexpr int PLANE_COUNT = 6;

// Signed distance to plane `index` (bit 1 << index); inside when ≥ 0.
float plane_distance(int index, vec4_t p, float guard) {
    switch (index) {
        case 0: return p.z + p.w;              // near: z ≥ −w
        case 1: return p.w - p.z;              // far: z ≤ w
        case 2: return p.x + guard * p.w;      // left: x ≥ −g·w
        case 3: return guard * p.w - p.x;      // right: x ≤ g·w
        case 4: return p.y + guard * p.w;      // bottom
        default: return guard * p.w - p.y;     // top
    }
}

clip_vertex lerp_vertex(const clip_vertex &a, const clip_vertex &b, float t, int attr_count) {
    clip_vertex r;
    r.position = {a.position.x + (b.position.x - a.position.x) * t, a.position.y + (b.position.y - a.position.y) * t,
                  a.position.z + (b.position.z - a.position.z) * t, a.position.w + (b.position.w - a.position.w) * t};
    for (int k = 0; k < attr_count; ++k) r.attr[k] = a.attr[k] + (b.attr[k] - a.attr[k]) * t;
    for (int k = attr_count; k < CLIP_MAX_ATTRIBUTES; ++k) r.attr[k] = 0.0f;
    return r;
}

}  // namespace

int clip_polygon(const clip_vertex *in, int n, unsigned planes, float guard, int attr_count, clip_vertex *out) {
    if (n != 3 || attr_count < 0 || attr_count > CLIP_MAX_ATTRIBUTES) return 0;
    clip_vertex buffer[2][CLIP_MAX_VERTICES];
    for (int k = 0; k < n; ++k) buffer[0][k] = in[k];
    int count = n, src = 0;
    for (int i = 0; i < PLANE_COUNT && count >= 3; ++i) {
        if (!(planes & (1u << i))) continue;
        const clip_vertex *poly = buffer[src];
        clip_vertex *next = buffer[1 - src];
        int m = 0;
        for (int k = 0; k < count; ++k) {
            const clip_vertex &a = poly[k], &b = poly[(k + 1) % count];
            const float da = plane_distance(i, a.position, guard), db = plane_distance(i, b.position, guard);
            const bool a_in = da >= 0.0f, b_in = db >= 0.0f;
            if (a_in) next[m++] = a;
            // The edge crosses the plane: add the crossing (t = da / (da − db), in [0, 1]),
            // measured from the INSIDE end: from a far-off end (1e30) t ≈ 1 − 1e-28 rounds
            // to 1 and a + (b − a)·t cancels to garbage; from the inside end t is tiny and exact.
            if (a_in != b_in && m < CLIP_MAX_VERTICES)
                next[m++] = a_in ? lerp_vertex(a, b, da / (da - db), attr_count)
                                 : lerp_vertex(b, a, db / (db - da), attr_count);
        }
        count = m;
        src = 1 - src;
    }
    if (count < 3) return 0;
    for (int k = 0; k < count; ++k) out[k] = buffer[src][k];
    return count;
}

}  // namespace tiny3d
