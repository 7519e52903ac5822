// scene.h — a flat scene: objects, lights and one camera, rendered into a canvas in one call.
//
// A scene graph kept flat (no hierarchy: no demo needs one). An object is a mesh plus its
// model matrix plus how to draw it:
//  * wireframe — the mesh's edges through tiny3d::render_wireframe, each edge's ink from
//    the lighting module: the corrected model (edge normal = mean of the adjacent faces'
//    normals, shade_edge, with ambient) or the report's per-edge Lambert
//    (shade_edge_faithful), chosen by scene::edge_model;
//  * filled — triangles through tiny3d::render_context with a z-buffer, shaded flat,
//    Gouraud or Phong (tiny3d::shading).
// Lights and positions are in world space; the camera gives view and projection.
// Filled objects are drawn first (depth-tested among themselves, with scene::samples per
// pixel), then the wireframes: hidden where a filled object is in front of them
// (scene::hidden_lines, wireframe_options::depth_test), or always on top.
// After the first frame, rendering allocates nothing (every buffer is kept and reused).
#ifndef TINY3D_SCENE_H
#define TINY3D_SCENE_H

#include <cstddef>
#include <memory>
#include <vector>

#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "tiny3d_result.h"
#include "wireframe.h"

namespace tiny3d {

enum class draw_mode { wireframe, filled };

// A perspective camera (gluLookAt + gluPerspective). Angles in radians, distances in
// world units.
struct camera {
    vec3_t eye = {0.0f, 0.0f, 5.0f};
    vec3_t target = {0.0f, 0.0f, 0.0f};
    vec3_t up = {0.0f, 1.0f, 0.0f};
    float fov_y = 0.8f;  // vertical field of view, 0 < fov_y < π
    float near_plane = 0.1f;
    float far_plane = 100.0f;
};

// projection · view for a canvas of width × height pixels (aspect = width / height).
// Error for a bad field of view, near/far planes or canvas size.
result<mat4_t> camera_view_projection(const camera &cam, int width, int height);

// How one object is drawn (everything but the mesh, which add_object takes).
struct object_style {
    draw_mode mode = draw_mode::wireframe;
    shading shade = shading::gouraud;  // filled objects
    float line_thickness = 1.0f;       // wireframe objects, pixels
    float line_intensity = 1.0f;       // wireframe ink scale (times the lighting)
    bool hide_back_edges = false;      // wireframe: skip edges whose faces all face away
};

class scene {
public:
    scene();
    ~scene();
    scene(const scene &) = delete;
    scene &operator=(const scene &) = delete;

    std::vector<light_t> lights;          // world space, at most MAX_LIGHTS
    float ambient = 0.1f;                 // 0..1
    camera cam;
    edge_lighting edge_model = edge_lighting::face_normals;
    float background = 0.0f;              // clear intensity
    sample_count samples = sample_count::x1;  // filled objects' samples per pixel (raster.h)
    bool hidden_lines = true;             // false: wireframes always on top of filled objects

    // Adds an object drawing `m` (copied; edges are derived if missing) with the identity
    // model matrix. Everything per mesh (edge normals, adjacency, the triangle mesh) is
    // computed here, once. Returns the object's index, or an error for an invalid mesh
    // (mesh_validate) or style (non-finite or ≤ 0 thickness, negative intensity).
    result<std::size_t> add_object(const mesh &m, const object_style &style);
    std::size_t object_count() const;
    // Model matrix (object → world) of object i; set it every frame for moving objects.
    void set_model(std::size_t i, const mat4_t &model);
    const mat4_t &model(std::size_t i) const;
    object_style &style(std::size_t i);

    // Clears the canvas to `background` and draws every object. Errors: bad lights or
    // ambient (make_light_rig's message), bad camera, a wireframe error.
    status render(canvas_t &canvas);
    // The window depths (0 near .. 1 far, raster.h) of the filled objects the last render
    // drew, one per canvas pixel (the nearest sample's when multisampled) — what the
    // wireframes' hidden-line test read; for tiny3d::depth_point_visible, to draw other
    // marks hidden as the wireframes are. Null before the first render, after a render
    // without filled objects or one that failed before drawing them. Valid until the next
    // render.
    const zbuffer *depth() const;

private:
    struct object;
    std::vector<std::unique_ptr<object>> objects_;
    struct buffers;
    std::unique_ptr<buffers> buffers_;
};

}  // namespace tiny3d

#endif
