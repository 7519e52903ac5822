// render — any OBJ or PLY mesh, filled and shaded or as a wireframe, as an auto-framed
// turntable (the default) or from a camera given on the command line.
//
//   render FILE.obj|FILE.ply|- [--format auto|obj|ply] [--mode flat|gouraud|phong|wireframe|hidden-line]
//          [--texture FILE.pgm] [--filter nearest|bilinear|trilinear|anisotropic] [--anisotropy N]
//          [--turntable N] [--eye X,Y,Z] [--target X,Y,Z] [--up X,Y,Z]
//          [--fov DEG] [--ortho] [--light X,Y,Z[,I]]... [--ambient X] [--specular KS] [--shininess S]
//          [--crease DEG] [--aa N] [--info] + the common
//          options (--out, --frames, --size, --threads, --png); render --help explains each.
//
// The scene: the mesh turns about the up axis through its bounding sphere's centre, one
// turn in --turntable frames (frame k at 2π·k/N; 1 = a still). The camera looks at that
// centre from 20° above the horizon, backed off until the sphere fills 85 % of the
// narrower field of view, so every frame holds the whole mesh; --eye/--target/--up move it
// (coordinates in the mesh file's own units and axes). Lights are directions in the
// camera's frame (x right, y up, z towards the viewer), so the lighting stays put while
// the mesh turns. Positions of --eye/--target are in the mesh's coordinates.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/demo_cli.h"
#include "common/render_scene.h"
#include "canvas.h"
#include "lighting.h"
#include "lines.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "wireframe.h"

namespace {

constexpr int kDefaultWidth = 640, kDefaultHeight = 480;
constexpr int kDefaultTurntable = 36;
constexpr float kEdgeThickness = 1.2f;    // px, wireframe modes
constexpr float kFarInk = 0.35f;          // wireframe depth cue
using namespace demo::render_scene;  // the default scene's constants, camera and lights

struct settings {
    std::string path, mode = "phong", texture_path, lines = "coverage", cull = "back", filter = "trilinear", format = "auto";
    int anisotropy = 8;
    int turntable = kDefaultTurntable;
    view_request view;
    bool up_given = false, info = false;
    float ambient = kAmbient;
    double crease = kCrease;
    float specular = kSpecular, shininess = kShininess;
    bool crease_given = false;
    double progress_every = 2.0;  // seconds between progress lines of a long frame
    std::vector<light_t> lights;  // camera frame; intensity < 0 = "split the rest evenly"
};

// Progress of a long frame on stderr: the render context reports every band it draws; a
// line is printed once the frame has run `every` seconds, then at most every `every` seconds
// (0: every band), so a frame of minutes does not look hung and a short one prints nothing.
struct frame_progress {
    using clock = std::chrono::steady_clock;
    double every = 2.0;
    int frame = 0;
    clock::time_point start{}, last{};
    void begin(int frame_number) {
        frame = frame_number;
        start = last = clock::now();
    }
    static void report(const tiny3d::render_context::progress &p, void *self) {
        frame_progress &me = *static_cast<frame_progress *>(self);
        const clock::time_point now = clock::now();
        if (std::chrono::duration<double>(now - me.start).count() < me.every ||
            (me.last != me.start && std::chrono::duration<double>(now - me.last).count() < me.every))
            return;
        me.last = now;
        std::fprintf(stderr, "render: frame %d: %d of %d bands drawn (%zu triangles), %.0f s\n", me.frame, p.bands_done,
                     p.bands_total, p.triangles, std::chrono::duration<double>(now - me.start).count());
    }
};

// "X,Y,Z" or "X,Y,Z,I": a direction towards the light and an optional intensity.
std::string parse_light(const std::string &text, std::vector<light_t> &lights) {
    light_t light{};
    light.intensity = -1.0f;
    std::string direction = text;
    const std::size_t commas = std::count(text.begin(), text.end(), ',');
    if (commas == 3) {
        const std::size_t last = text.rfind(',');
        double intensity = 0;
        if (std::string e = demo::parse_number("--light", text.substr(last + 1), 0.0, 100.0, intensity); !e.empty())
            return "--light wants X,Y,Z or X,Y,Z,I (I in 0..100), got '" + text + "'";
        light.intensity = float(intensity);
        direction = text.substr(0, last);
    }
    if (std::string e = demo::parse_vec3("--light", direction, light.direction); !e.empty())
        return "--light wants X,Y,Z or X,Y,Z,I, got '" + text + "'";
    if (!(tiny3d::vec3_length(light.direction) > 0.0f)) return "--light: the direction must not be zero, got '" + text + "'";
    lights.push_back(light);
    return "";
}

int print_info(const settings &s, const tiny3d::loaded_mesh &loaded) {
    const tiny3d::mesh &m = loaded.geometry;
    const tiny3d::bounding_box box = tiny3d::mesh_bounding_box(m);
    const tiny3d::bounding_sphere sphere = tiny3d::mesh_bounding_sphere(m);
    std::printf("file       %s\n", s.path.c_str());
    std::printf("vertices   %zu\n", m.positions.size());
    std::printf("faces      %zu\n", m.face_count());
    std::printf("triangles  %zu\n", tiny3d::mesh_triangles(m).size());
    std::printf("edges      %zu\n", m.edges.size());
    if (!m.lines.empty()) std::printf("lines      %zu (segments outside any face)\n", m.lines.size());
    std::printf("uvs        %s\n", m.corner_uvs.empty() ? "no" : "yes (per corner)");
    std::printf("normals    %s\n", m.corner_normals.empty() ? "no (computed from the faces)" : "yes (per corner)");
    if (m.positions.empty()) {
        std::printf("bounds     none (no positions)\n");
    } else {
        std::printf("bounds     min (%g, %g, %g)  max (%g, %g, %g)\n", box.min.x, box.min.y, box.min.z, box.max.x,
                    box.max.y, box.max.z);
        std::printf("sphere     centre (%g, %g, %g)  radius %g\n", sphere.center.x, sphere.center.y, sphere.center.z,
                    sphere.radius);
    }
    const std::size_t warnings = loaded.warnings.size() + loaded.warnings_not_listed;
    std::printf("warnings   %s\n", warnings == 0 ? "none" : std::to_string(warnings).c_str());
    for (const tiny3d::load_warning &w : loaded.warnings) std::printf("  %s\n", w.message().c_str());
    if (loaded.warnings_not_listed > 0) std::printf("  (%zu more not listed)\n", loaded.warnings_not_listed);
    const tiny3d::raster_simd_choice kernels = tiny3d::default_raster_simd();
    std::printf("kernels: %s", tiny3d::raster_simd_name(kernels.simd));
    if (!kernels.requested.empty() && !kernels.honoured)
        std::printf(" (TINY3D_KERNELS=%s: not an instruction set this CPU runs; the best one instead)",
                    kernels.requested.c_str());
    std::printf("\n");
    return 0;
}

tiny3d::shading shading_named(const std::string &mode) {
    if (mode == "flat") return tiny3d::shading::flat;
    if (mode == "gouraud") return tiny3d::shading::gouraud;
    return tiny3d::shading::phong;
}

tiny3d::cull_mode cull_named(const std::string &name) {
    if (name == "none") return tiny3d::cull_mode::none;
    if (name == "front") return tiny3d::cull_mode::front;
    return tiny3d::cull_mode::back;
}

}  // namespace

int main(int argc, char **argv) {
    demo::command_line cli(
        "render", "FILE.obj|FILE.ply",
        "Any OBJ or PLY mesh, filled and shaded or as a wireframe. By default an auto-framed\n"
        "turntable: the mesh turns once about the up axis in 36 frames (frame_000.pgm ...), seen\n"
        "from 20 degrees above, lit by a key and a fill light. --eye/--target/--up/--fov/--ortho\n"
        "set the camera (positions in the mesh's own coordinates); --turntable 1 gives a still.");
    settings s;
    cli.positional("FILE.obj|FILE.ply", s.path, true);
    // The --frames range is checked against --turntable's value.
    cli.add_sequence_options([&s] { return s.turntable; }, kDefaultWidth, kDefaultHeight);
    cli.add_threads(2);
    cli.add_samples(tiny3d::sample_count::x4);
    cli.choice("--mode", s.mode, {"flat", "gouraud", "phong", "wireframe", "hidden-line"},
               "shading (default phong: per-pixel normals), or edges: wireframe draws every edge, hidden-line "
               "draws only the edges the mesh's own surface does not hide (back-facing and depth-tested)");
    cli.text("--texture", "FILE.pgm", s.texture_path,
             "multiply the shading by a grey PGM texture (the mesh needs texture coordinates)");
    cli.choice("--filter", s.filter, {"nearest", "bilinear", "trilinear", "anisotropic"},
               "the texture filter: trilinear (default: mipmaps, blended between levels), anisotropic (up to "
               "--anisotropy trilinear taps along the pixel's footprint: sharp at grazing angles), bilinear or "
               "nearest (the base level only)");
    cli.integer("--anisotropy", s.anisotropy, 1, 64, "most taps of --filter anisotropic (default 8)");
    cli.choice("--lines", s.lines, {"coverage", "tabulated", "faithful"},
               "the line in the edge modes: exact coverage (default), tabulated or the report's draw_line_f");
    cli.choice("--cull", s.cull, {"back", "none", "front"}, "which faces to skip (default back)");
    cli.integer("--turntable", s.turntable, 1, 100000, "frames for one turn (default 36; 1 = a still image)");
    cli.vector3("--eye", s.view.eye, s.view.eye_given, "camera position (default: auto-framed, 20 degrees above the centre)");
    cli.vector3("--target", s.view.target, s.view.target_given, "point the camera looks at (default: the mesh's centre)");
    cli.vector3("--up", s.view.up, s.up_given, "up axis: turntable axis and screen up (default 0,1,0)");
    cli.number("--fov", s.view.fov_degrees, 1.0, 170.0, "vertical field of view in degrees (default 40)");
    cli.flag("--ortho", s.view.ortho, "orthographic projection (the view's height spans the mesh)");
    cli.custom("--light", "X,Y,Z[,I]",
               "a directional light towards X,Y,Z in the camera's frame (x right, y up, z towards you), "
               "intensity I (default: 0.85 shared by the lights without one); replaces the default two",
               [&s](const std::string &v) { return parse_light(v, s.lights); }, true);
    cli.number("--ambient", s.ambient, 0.0f, 1.0f, "ambient light 0..1 (default 0.1)");
    cli.number("--specular", s.specular, 0.0f, 10.0f,
               "Blinn-Phong highlight strength ks (default 0.25, a modest plastic; 0 = diffuse only)");
    cli.number("--shininess", s.shininess, 1.0f, 10000.0f,
               "highlight sharpness s: its size shrinks about as 1/s (default 40)");
    cli.custom("--crease", "DEG",
               "normals smooth across edges whose faces meet at up to DEG degrees and stay sharp across "
               "sharper ones (default 60; 180 = smooth everywhere, 0 = flat faces); vertices at the same "
               "position count as one. The mesh's own normals (OBJ vn, PLY nx,ny,nz) are used unless this is given",
               [&s](const std::string &v) {
                   s.crease_given = true;
                   return demo::parse_number("--crease", v, 0.0, 180.0, s.crease);
               });
    cli.choice("--format", s.format, {"auto", "obj", "ply"},
               "the mesh's format (default auto: by the name's .obj/.ply, else by the content); FILE '-' reads "
               "standard input");
    cli.number("--progress-every", s.progress_every, 0.0, 3600.0,
               "seconds a frame runs before its progress (bands drawn) is shown on stderr, and between two such "
               "lines (default 2; 0 = every band)");
    cli.flag("--info", s.info, "print the mesh's counts, bounds and loader warnings; render nothing");
    if (const int status = cli.parse(argc, argv); status >= 0) return status;
    if (s.up_given && !(tiny3d::vec3_length(s.view.up) > 0.0f)) return cli.usage_error("--up must not be zero, got '0,0,0'");
    const demo::common_options &o = cli.common;
    if ((s.mode == "wireframe" || s.mode == "hidden-line") && !s.texture_path.empty())
        return cli.usage_error("--texture needs a filled --mode, not '" + s.mode + "'");

    tiny3d::load_options load;
    load.format = s.format == "obj" ? tiny3d::mesh_format::obj
                  : s.format == "ply" ? tiny3d::mesh_format::ply
                                      : tiny3d::mesh_format::by_name;
    // "-": standard input, read to its end like any pipe (named "<stdin>" in messages).
    auto loaded = s.path == "-" ? [&] {
        auto bytes = tiny3d::read_file_bytes("/dev/stdin");
        if (!bytes) return tiny3d::result<tiny3d::loaded_mesh>(tiny3d::error{"<stdin>", 0, -1, bytes.err().reason});
        return tiny3d::parse_mesh(*bytes, "<stdin>", load);
    }()
                                : tiny3d::load_mesh(s.path, load);
    if (!loaded) return cli.fail(loaded.message());
    if (s.info) return print_info(s, *loaded);
    for (const tiny3d::load_warning &w : loaded->warnings) std::fprintf(stderr, "render: warning: %s\n", w.message().c_str());
    tiny3d::mesh &m = loaded->geometry;
    if (m.face_count() == 0 && !m.edges.empty() && s.mode != "wireframe") {
        std::fprintf(stderr, "render: %s has lines but no faces: drawing them as a wireframe\n", s.path.c_str());
        s.mode = "wireframe";
    }
    const bool edges_only = s.mode == "wireframe" || s.mode == "hidden-line";

    if (edges_only ? m.edges.empty() : m.face_count() == 0)
        return cli.fail(s.path + ": nothing to draw (no " + (edges_only ? "edges" : "faces") + ")");
    // The camera works on the mesh mapped onto the unit sphere in double (positions rewritten),
    // so meshes of any size frame alike; positions given on the command line map with it.
    const tiny3d::result<tiny3d::unit_sphere_map> fit = tiny3d::mesh_fit_unit_sphere(m);
    if (!fit) return cli.fail(s.path + ": " + fit.message());
    const tiny3d::bounding_sphere bounds = tiny3d::mesh_bounding_sphere(m);
    view_request unit_view = s.view;
    for (vec3_t *p : {&unit_view.eye, &unit_view.target}) *p = fit->apply(*p);
    tiny3d::texture tex;
    if (!s.texture_path.empty()) {
        if (m.corner_uvs.empty()) return cli.fail(s.path + ": no texture coordinates, which --texture needs");
        auto t = tiny3d::load_texture_pgm(s.texture_path);
        if (!t) return cli.fail(t.message());
        tex = std::move(*t);
    }
    if (m.corner_normals.empty() || s.crease_given)
        if (tiny3d::status st = tiny3d::mesh_set_crease_normals(m, float(s.crease)); !st)
            return cli.fail(s.path + ": " + st.message());
    auto shape = tiny3d::make_raster_mesh(m, {});
    if (!shape) return cli.fail(s.path + ": " + shape.message());
    auto canvas = tiny3d::make_canvas(o.width, o.height);
    if (!canvas) return cli.fail(canvas.message());

    const camera cam = make_camera(unit_view, {{0, 0, 0}, 1.0f}, float(o.width) / float(o.height));
    auto rig = make_lights(s.lights, s.ambient, cam);
    if (!rig) return cli.fail(rig.message());
    const mat4_t view_projection = mat4_multiply(cam.projection, cam.view);

    tiny3d::draw_params params;
    params.view_projection = view_projection;
    params.lights = *rig;
    params.surface.specular = s.specular;
    params.surface.shininess = s.shininess;
    params.shade = shading_named(s.mode);
    params.cull = cull_named(s.cull);
    params.tex = s.texture_path.empty() ? nullptr : &tex;
    params.filter = s.filter == "nearest"       ? tiny3d::texture_filter::nearest
                    : s.filter == "bilinear"    ? tiny3d::texture_filter::bilinear
                    : s.filter == "anisotropic" ? tiny3d::texture_filter::anisotropic
                                                : tiny3d::texture_filter::trilinear;
    params.anisotropy = s.anisotropy;
    tiny3d::render_context ctx(o.threads);
    frame_progress progress{s.progress_every};
    ctx.report_progress(&frame_progress::report, &progress);
    if (ctx.threads() < o.threads)
        std::fprintf(stderr, "render: warning: the system refused to create threads: rendering on %d of the %d asked for\n",
                     ctx.threads(), o.threads);

    tiny3d::wireframe_options wire;
    wire.method = demo::line_method_named(s.lines);
    wire.thickness = kEdgeThickness;
    wire.depth_cue = true;
    wire.depth_cue_far = kFarInk;
    wire.bounds = &bounds;
    // hidden-line: back-facing edges left out, and every other edge depth-tested against the
    // mesh's own filled depth (drawn first, its colour cleared), so edges behind the surface
    // are hidden on concave meshes too.
    const tiny3d::edge_adjacency adjacency = s.mode == "hidden-line" ? tiny3d::mesh_edge_faces(m) : tiny3d::edge_adjacency{};
    wire.hide_back_edges = s.mode == "hidden-line";
    wire.adjacency = wire.hide_back_edges ? &adjacency : nullptr;
    wire.depth_test = wire.hide_back_edges ? &ctx.depth() : nullptr;
    tiny3d::wireframe_workspace workspace;

    if (tiny3d::status st = demo::prepare_out_dir(o); !st) return cli.fail(st.message());
    demo::progress timer("render", o);
    int frames_showing = 0;
    for (int frame = o.first_frame; frame <= o.last_frame; ++frame) {
        const float angle = float(2.0 * kPi * frame / s.turntable);
        const mat4_t model = tiny3d::mat4_rotate_axis(s.view.up, angle);
        timer.start();
        progress.begin(frame);
        if (edges_only) {
            if (s.mode == "hidden-line") {  // the surface's depth only: its colour is cleared below
                if (tiny3d::status st = ctx.begin_frame(**canvas, kBackground); !st) return cli.fail(st.message());
                params.model = model;
                ctx.draw(*shape, params);
                ctx.end_frame();
                if (tiny3d::status st = ctx.frame_status(); !st) return cli.fail(s.path + ": " + st.message());
            }
            canvas_clear(canvas->get(), kBackground);
            if (tiny3d::status st = tiny3d::render_wireframe(**canvas, m, mat4_multiply(view_projection, model), wire,
                                                             workspace);
                !st)
                return cli.fail(st.message());
        } else {
            if (tiny3d::status st = ctx.begin_frame(**canvas, kBackground, o.samples); !st) return cli.fail(st.message());
            params.model = model;
            ctx.draw(*shape, params);
            ctx.end_frame();
            if (tiny3d::status st = ctx.frame_status(); !st) return cli.fail(s.path + ": " + st.message());
        }
        timer.stop();
        // A frame of background only is a warning, not a failure: a flat mesh seen edge-on
        // (a quad in frame 9 of 36) rightly shows nothing. Only a run in which no frame shows
        // anything fails (below).
        if (canvas_count_differing(canvas->get(), kBackground) == 0)
            std::fprintf(stderr, "render: warning: %s: frame %d shows nothing but the background\n", s.path.c_str(),
                         frame);
        else
            ++frames_showing;
        if (tiny3d::status st = timer.save(**canvas, demo::frame_path(o, frame), o.png); !st) return cli.fail(st.message());
    }
    if (tiny3d::status done = timer.finish(); !done) return cli.fail(done.message());
    if (frames_showing == 0)
        return cli.fail(s.path + ": no frame shows anything but the background (the mesh is out of view or " +
                        "has no visible area)");
    return 0;
}
