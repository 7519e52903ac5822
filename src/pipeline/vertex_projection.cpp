// vertex_projection.cpp — clip space → screen (viewport convention in include/pipeline.h) and the
// report's project_vertex.
#include <cmath>

#include "pipeline.h"

namespace tiny3d {

namespace {

// Clip space → screen by the library's viewport (NDC by one reciprocal) or the report's
// (NDC by division, as its code does, so its pixels come out bit for bit).
screen_point to_screen(vec4_t clip, int width, int height, bool report_viewport) {
    if (!(clip.w > 0.0f) || !std::isfinite(clip.w)) return {0.0f, 0.0f, 0.0f, clip.w, true};
    float ndc_x, ndc_y, ndc_z;
    if (report_viewport) {
        ndc_x = clip.x / clip.w, ndc_y = clip.y / clip.w, ndc_z = clip.z / clip.w;
    } else {
        const float inv_w = 1.0f / clip.w;
        ndc_x = clip.x * inv_w, ndc_y = clip.y * inv_w, ndc_z = clip.z * inv_w;
    }
    if (!std::isfinite(ndc_x) || !std::isfinite(ndc_y) || !std::isfinite(ndc_z))
        return {0.0f, 0.0f, 0.0f, clip.w, true};
    const float sx = report_viewport ? report_ndc_to_screen_x(ndc_x, width) : ndc_to_screen_x(ndc_x, float(width));
    const float sy = report_viewport ? report_ndc_to_screen_y(ndc_y, height) : ndc_to_screen_y(ndc_y, float(height));
    return {sx, sy, (ndc_z + 1.0f) * 0.5f, clip.w, false};
}

}  // namespace

screen_point clip_to_screen(vec4_t clip, int width, int height) { return to_screen(clip, width, height, false); }

screen_point clip_to_report_screen(vec4_t clip, int width, int height) { return to_screen(clip, width, height, true); }

screen_point project_point(vec3_t v, const mat4_t &model_view_proj, int width, int height) {
    return clip_to_screen(mat4_mul_vec4(model_view_proj, vec4_from_vec3(v, 1.0f)), width, height);
}

}  // namespace tiny3d

int project_vertex(vec3_t v, mat4_t model, mat4_t proj, int width, int height, float *x_out, float *y_out) {
    // Model first, then projection, as the report does (two products, not proj·model).
    const vec4_t clip = mat4_mul_vec4(proj, mat4_mul_vec4(model, vec4_from_vec3(v, 1.0f)));
    const tiny3d::screen_point p = tiny3d::clip_to_report_screen(clip, width, height);
    if (p.behind) return 0;
    if (x_out) *x_out = p.x;
    if (y_out) *y_out = p.y;
    return 1;
}
