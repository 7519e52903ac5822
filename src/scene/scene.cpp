// scene.cpp — the flat scene: objects + lights + camera → one canvas.
#include "scene.h"

#include <cmath>
#include <optional>
#include <string>

namespace tiny3d {

namespace {

error scene_error(const std::string &reason) { return error{"", 0, -1, "scene: " + reason}; }

status check_style(const object_style &s) {
    if (!(std::isfinite(s.line_thickness) && s.line_thickness > 0.0f))
        return scene_error("line thickness must be finite and > 0");
    if (!(std::isfinite(s.line_intensity) && s.line_intensity >= 0.0f))
        return scene_error("line intensity must be finite and >= 0");
    return {};
}

}  // namespace

result<mat4_t> camera_view_projection(const camera &cam, int width, int height) {
    if (width <= 0 || height <= 0) return scene_error("canvas size must be positive");
    auto proj = perspective_checked(cam.fov_y, static_cast<float>(width) / static_cast<float>(height),
                                    cam.near_plane, cam.far_plane);
    if (!proj) return scene_error("camera: " + proj.message());
    return mat4_multiply(proj.value(), mat4_look_at(cam.eye, cam.target, cam.up));
}

// Everything computed once per mesh, plus the per-frame buffers of one object.
struct scene::object {
    mesh shape;
    object_style style;
    mat4_t model = mat4_identity();
    std::vector<vec3_t> edge_normal;  // model space, per edge (corrected model)
    edge_adjacency adjacency;         // for hide_back_edges
    raster_mesh triangles;            // for filled drawing (empty until first needed)
    std::optional<raster_clusters> clusters;  // of `triangles`: whole back-facing chunks skipped
    std::vector<vec3_t> world;        // per frame: positions in world space
    std::vector<float> ink;           // per frame: per-edge intensity
};

struct scene::buffers {
    wireframe_workspace wire;
    render_context raster{1};
    bool filled = false;  // the last render drew filled objects (raster's depth is theirs)
};

scene::scene() : buffers_(std::make_unique<buffers>()) {}
scene::~scene() = default;

result<std::size_t> scene::add_object(const mesh &m, const object_style &style) {
    if (status s = check_style(style); !s) return s.err();
    auto obj = std::make_unique<object>();
    obj->shape = m;
    if (obj->shape.edges.empty()) mesh_derive_edges(obj->shape);
    if (status s = mesh_validate(obj->shape); !s) return scene_error("object " + std::to_string(objects_.size()) + ": " + s.message());
    obj->style = style;
    obj->edge_normal = mesh_edge_normals(obj->shape);
    obj->adjacency = mesh_edge_faces(obj->shape);
    auto tris = make_raster_mesh(obj->shape, mesh_vertex_normals(obj->shape));
    if (!tris) return scene_error("object " + std::to_string(objects_.size()) + ": " + tris.message());
    obj->triangles = std::move(tris.value());
    // Meshes only move by their model matrix here, so the clusters stay valid.
    if (auto clusters = make_raster_clusters(obj->triangles)) obj->clusters = std::move(clusters.value());
    obj->world.resize(obj->shape.positions.size());
    obj->ink.resize(obj->shape.edges.size());
    objects_.push_back(std::move(obj));
    return objects_.size() - 1;
}

std::size_t scene::object_count() const { return objects_.size(); }
void scene::set_model(std::size_t i, const mat4_t &model) { objects_[i]->model = model; }
const mat4_t &scene::model(std::size_t i) const { return objects_[i]->model; }
object_style &scene::style(std::size_t i) { return objects_[i]->style; }

const zbuffer *scene::depth() const { return buffers_->filled ? &buffers_->raster.depth() : nullptr; }

status scene::render(canvas_t &canvas) {
    auto rig = make_light_rig(lights, ambient);
    if (!rig) return scene_error(rig.message());
    auto view_proj = camera_view_projection(cam, canvas.width, canvas.height);
    if (!view_proj) return view_proj.err();
    for (const auto &obj : objects_)
        if (status s = check_style(obj->style); !s) return s;

    // Filled objects first, depth-tested among themselves.
    bool any_filled = false;
    for (const auto &obj : objects_) any_filled = any_filled || obj->style.mode == draw_mode::filled;
    buffers_->filled = false;
    if (any_filled) {
        if (status s = buffers_->raster.begin_frame(canvas, background, samples); !s) return s;
        for (const auto &obj : objects_) {
            if (obj->style.mode != draw_mode::filled) continue;
            draw_params params;
            params.model = obj->model;
            params.view_projection = view_proj.value();
            params.lights = rig.value();
            params.shade = obj->style.shade;
            params.clusters = obj->clusters ? &*obj->clusters : nullptr;
            buffers_->raster.draw(obj->triangles, params);
        }
        buffers_->raster.end_frame();
        buffers_->filled = true;
    } else {
        canvas_clear(&canvas, background);
    }

    // Wireframes on top, each edge lit in world space.
    for (const auto &obj : objects_) {
        if (obj->style.mode != draw_mode::wireframe) continue;
        if (status s = transform_points(obj->model, obj->shape.positions, obj->world); !s) return s;
        const normal_transform to_world = make_normal_transform(obj->model);
        for (std::size_t e = 0; e < obj->shape.edges.size(); ++e) {
            const vec3_t a = obj->world[obj->shape.edges[e].a], b = obj->world[obj->shape.edges[e].b];
            const float lit = edge_model == edge_lighting::faithful_lambert
                                  ? shade_edge_faithful(rig.value(), a, b)
                                  : shade_edge(rig.value(), a, b, apply_normal_transform(to_world, obj->edge_normal[e]));
            obj->ink[e] = lit;
        }
        wireframe_options options;
        options.method = line_method::coverage;
        options.thickness = obj->style.line_thickness;
        options.intensity = obj->style.line_intensity;
        options.edge_intensity = obj->ink;
        options.hide_back_edges = obj->style.hide_back_edges;
        options.adjacency = &obj->adjacency;
        if (any_filled && hidden_lines) options.depth_test = &buffers_->raster.depth();
        const mat4_t mvp = mat4_multiply(view_proj.value(), obj->model);
        if (status s = render_wireframe(canvas, obj->shape, mvp, options, buffers_->wire); !s)
            return scene_error("wireframe: " + s.message());
    }
    return {};
}

}  // namespace tiny3d
