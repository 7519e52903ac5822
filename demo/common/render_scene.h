// render_scene.h — render's default scene around a mesh: the auto-framed camera, the key and
// fill lights and the surface defaults. Shared by demo/render.cpp and the benchmark that
// measures render's output (tests/bench/gif.cpp), so that the two draw the same frames.
//
// In: the mesh's bounding sphere (render maps the mesh onto the unit sphere first), the
// view's aspect ratio, and what the command line overrides. Out: view and projection
// matrices, the camera's frame in world space, and the lights in world space.
#ifndef TINY3D_DEMO_RENDER_SCENE_H
#define TINY3D_DEMO_RENDER_SCENE_H

#include <algorithm>
#include <cmath>
#include <vector>

#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "tiny3d_result.h"

namespace demo::render_scene {

inline constexpr double kFovDegrees = 40.0;
inline constexpr float kElevation = 0.35f;   // radians above the horizon (20°)
inline constexpr float kFill = 0.85f;        // the bounding sphere spans this much of the view
inline constexpr float kBackground = 0.04f;
inline constexpr float kAmbient = 0.1f;
inline constexpr double kCrease = 60.0;      // degrees: sharper edges stay sharp
inline constexpr float kSpecular = 0.25f;    // a modest plastic highlight (Blinn-Phong ks)
inline constexpr float kShininess = 40.0f;   // its sharpness (exponent s)
inline constexpr float kLightTotal = 0.85f;  // split evenly among the lights without an intensity
inline constexpr double kPi = 3.14159265358979323846;

// What the command line may set; the rest is framed from the bounding sphere.
struct view_request {
    double fov_degrees = kFovDegrees;  // vertical
    bool ortho = false;
    vec3_t eye{}, target{}, up{0, 1, 0};
    bool eye_given = false, target_given = false;
};

struct camera {
    mat4_t view, projection;
    vec3_t right, up, back;  // the camera's frame in world space (for the lights)
};

// glOrtho: the box [l, r] × [b, t] × [−n, −f] in eye space onto NDC.
inline mat4_t ortho(float l, float r, float b, float t, float n, float f) {
    mat4_t m = mat4_identity();
    m.m[0] = 2 / (r - l);
    m.m[5] = 2 / (t - b);
    m.m[10] = -2 / (f - n);
    m.m[12] = -(r + l) / (r - l);
    m.m[13] = -(t + b) / (t - b);
    m.m[14] = -(f + n) / (f - n);
    return m;
}

// The default camera position: on the side of the centre that shows the mesh's front
// (+z for y up, −y for z up), kElevation above the horizon.
inline vec3_t auto_eye(vec3_t center, vec3_t up, float distance) {
    vec3_t back = tiny3d::vec3_cross(vec3_t{1, 0, 0}, up);
    if (!(tiny3d::vec3_length(back) > 1e-6f)) back = tiny3d::vec3_any_perpendicular(up);
    back = tiny3d::vec3_normalize(back);
    return center + (back * std::cos(kElevation) + tiny3d::vec3_normalize(up) * std::sin(kElevation)) * distance;
}

// Backed off until the sphere fills kFill of the narrower field of view; the depth range
// holds the sphere (a turn about its centre keeps the mesh inside it).
inline camera make_camera(const view_request &v, const tiny3d::bounding_sphere &bounds, float aspect) {
    const float fov = float(v.fov_degrees * kPi / 180.0);
    const float half_narrow = std::min(0.5f * fov, std::atan(std::tan(0.5f * fov) * aspect));
    const float r = bounds.radius;
    const vec3_t target = v.target_given ? v.target : bounds.center;
    const vec3_t eye = v.eye_given ? v.eye : auto_eye(bounds.center, v.up, r / std::sin(kFill * half_narrow));
    camera c;
    c.view = tiny3d::mat4_look_at(eye, target, v.up);
    // Rows of the view rotation are the camera's axes in world space.
    c.right = {c.view.m[0], c.view.m[4], c.view.m[8]};
    c.up = {c.view.m[1], c.view.m[5], c.view.m[9]};
    c.back = {c.view.m[2], c.view.m[6], c.view.m[10]};
    const float depth = tiny3d::vec3_dot(bounds.center - eye, c.back * -1.0f);
    const float far_plane = std::max(depth + 1.05f * r, 1e-3f * r);
    const float near_plane = std::max(depth - 1.05f * r, 1e-3f * far_plane);
    if (v.ortho) {
        const float half_h = r / kFill / std::min(1.0f, aspect);
        c.projection = ortho(-half_h * aspect, half_h * aspect, -half_h, half_h, near_plane, far_plane);
    } else {
        c.projection = tiny3d::mat4_perspective(fov, aspect, near_plane, far_plane);
    }
    return c;
}

// Lights given as directions in the camera's frame (x right, y up, z towards the viewer;
// intensity < 0: a share of what kLightTotal leaves), turned into world space. None given:
// a key light from the upper left front and a dim fill from the right.
inline tiny3d::result<tiny3d::light_rig> make_lights(std::vector<light_t> lights, float ambient, const camera &c) {
    if (lights.empty()) {
        lights.push_back({{-1.0f, 1.0f, 1.0f}, 0.68f});
        lights.push_back({{1.0f, -0.2f, 0.5f}, 0.22f});
    }
    float given = 0;
    int unset = 0;
    for (const light_t &l : lights) {
        if (l.intensity < 0) ++unset;
        else given += l.intensity;
    }
    for (light_t &l : lights) {
        if (l.intensity < 0) l.intensity = std::max(0.0f, kLightTotal - given) / float(unset);
        l.direction = c.right * l.direction.x + c.up * l.direction.y + c.back * l.direction.z;
    }
    return tiny3d::make_light_rig(lights, ambient);
}

}  // namespace demo::render_scene

#endif
