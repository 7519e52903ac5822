// raster_lab.cpp — the PLY ray-cast program (the lab exercise it reproduces: a ray per
// pixel, z-buffer): the lab's camera (eq. 1–12), its per-pixel ray / plane / inside tests
// (eq. 13–21) with a z-buffer on n/d, and a fast path that runs the very same per-pixel
// test only inside each triangle's projected box.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "../math3d/dvec3.h"
#include "canvas.h"  // write_file_atomic
#include "lab.h"
#include "mesh.h"

namespace tiny3d {

namespace {

using v3 = detail::dvec3;
v3 load(const double *p) { return {p[0], p[1], p[2]}; }
void store(double *p, v3 v) { p[0] = v.x, p[1] = v.y, p[2] = v.z; }
v3 from(vec3_t p) { return detail::widen(p); }

// Rays closer than this (relative) to parallel with a triangle's plane skip it ("d near 0").
constexpr double PARALLEL_EPSILON = 1e-9;
constexpr double LAB_FAR = 999999.0;  // the lab's initial z-buffer depth
constexpr int LAB_COLOR_BASE = 155, LAB_COLOR_CYCLE = 100;
constexpr int FAST_BOX_MARGIN = 2;    // px added around each projected box

// One triangle with everything the per-pixel test needs that does not depend on the pixel.
struct lab_triangle {
    v3 v0, v1, v2;
    v3 abc;         // plane normal, eq. 14
    double n;       // eq. 16 numerator (the camera is fixed)
    double abc_len;
    v3 c1, c2, c3;  // the first cross products of eq. 19–21
    std::uint8_t color;
};

std::vector<lab_triangle> lab_triangles(const mesh &m, const lab_camera &cam) {
    std::vector<lab_triangle> tris;
    const v3 camera = load(cam.camera);
    std::size_t index = 0;
    for (const corner_triangle &corners : mesh_triangles(m)) {
        lab_triangle t;
        t.v0 = from(m.positions[m.indices[corners[0]]]);
        t.v1 = from(m.positions[m.indices[corners[1]]]);
        t.v2 = from(m.positions[m.indices[corners[2]]]);
        t.abc = cross(t.v1 - t.v0, t.v2 - t.v0);              // eq. 14
        const double d_plane = -dot(t.abc, t.v0);            // eq. 15
        t.n = -dot(t.abc, camera) - d_plane;                 // eq. 16
        t.abc_len = std::sqrt(dot(t.abc, t.abc));
        t.c1 = cross(t.v2 - t.v0, t.v1 - t.v0);
        t.c2 = cross(t.v0 - t.v1, t.v2 - t.v1);
        t.c3 = cross(t.v1 - t.v2, t.v0 - t.v2);
        t.color = static_cast<std::uint8_t>(LAB_COLOR_BASE + index++ % LAB_COLOR_CYCLE);
        tris.push_back(t);
    }
    return tris;
}

// eq. 13: the image-plane point of pixel (r, c).
v3 image_point(const lab_camera &cam, int r, int c, int side) {
    const double fc = static_cast<double>(c) / (side - 1), fr = static_cast<double>(r) / (side - 1);
    return load(cam.topleft) + fc * (load(cam.right) - load(cam.left)) + fr * (load(cam.bottom) - load(cam.top));
}

// eq. 17–21 and the z-buffer step for one pixel ray and one triangle.
inline void lab_test(const lab_triangle &t, v3 camera, v3 ray, double ray_len, double &zbuf, std::uint8_t &pixel) {
    const double d = dot(t.abc, ray);  // eq. 17
    if (!(std::fabs(d) > PARALLEL_EPSILON * t.abc_len * ray_len)) return;
    const double dist = t.n / d;
    const v3 p = camera + dist * ray;  // eq. 18
    if (dot(t.c1, cross(p - t.v0, t.v1 - t.v0)) < 0) return;  // eq. 19
    if (dot(t.c2, cross(p - t.v1, t.v2 - t.v1)) < 0) return;  // eq. 20
    if (dot(t.c3, cross(p - t.v2, t.v0 - t.v2)) < 0) return;  // eq. 21
    if (dist > zbuf) return;
    zbuf = dist;
    pixel = t.color;
}

lab_image blank(int side) {
    lab_image img;
    img.width = img.height = side;
    img.pixels.assign(static_cast<std::size_t>(side) * side, 0);
    return img;
}

}  // namespace

result<lab_camera> ply_lab_camera(const mesh &m, double rx, double ry, double rz) {
    if (!std::isfinite(rx) || !std::isfinite(ry) || !std::isfinite(rz))
        return error{"", 0, -1, "lab camera: rotation angles must be finite"};
    v3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const vec3_t &p : m.positions) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
        lo = {std::min(lo.x, +p.x * 1.0), std::min(lo.y, p.y * 1.0), std::min(lo.z, p.z * 1.0)};
        hi = {std::max(hi.x, p.x * 1.0), std::max(hi.y, p.y * 1.0), std::max(hi.z, p.z * 1.0)};
    }
    if (!(lo.x <= hi.x)) return error{"", 0, -1, "lab camera: the mesh has no finite vertex"};
    lab_camera cam;
    const v3 center = 0.5 * (lo + hi);
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    if (!(extent > 0)) return error{"", 0, -1, "lab camera: the mesh's bounding box has zero extent"};
    // eq. 1–3: rotate about X, then Y, then Z.
    auto rotate = [&](v3 v) {
        v = {v.x, std::cos(rx) * v.y - std::sin(rx) * v.z, std::sin(rx) * v.y + std::cos(rx) * v.z};
        v = {std::cos(ry) * v.x + std::sin(ry) * v.z, v.y, -std::sin(ry) * v.x + std::cos(ry) * v.z};
        return v3{std::cos(rz) * v.x - std::sin(rz) * v.y, std::sin(rz) * v.x + std::cos(rz) * v.y, v.z};
    };
    const v3 up = rotate({0, 0, 1});
    const v3 camera = 1.5 * extent * rotate({1, 0, 0}) + center;  // eq. 4
    v3 left = cross(up, center - camera);                          // eq. 5
    const double a = std::sqrt(dot(left, left));                   // eq. 6
    left = (extent / (2 * a)) * left + center;                     // eq. 7
    const v3 right = (extent / (2 * a)) * cross(center - camera, up) + center;  // eq. 8–9
    const v3 top = (extent / 2) * up + center;                     // eq. 10
    const v3 bottom = (-extent / 2) * up + center;                 // eq. 11
    const v3 topleft = (extent / 2) * up + left;                   // eq. 12
    store(cam.center, center);
    cam.extent = extent;
    store(cam.camera, camera);
    store(cam.up, up);
    store(cam.left, left);
    store(cam.right, right);
    store(cam.top, top);
    store(cam.bottom, bottom);
    store(cam.topleft, topleft);
    return cam;
}

lab_image raycast_lab(const mesh &m, const lab_camera &cam, int side) {
    if (side < 2) return {};
    const std::vector<lab_triangle> tris = lab_triangles(m, cam);
    lab_image img = blank(side);
    const v3 camera = load(cam.camera);
    for (int r = 0; r < side; ++r)
        for (int c = 0; c < side; ++c) {
            const v3 ray = image_point(cam, r, c, side) - camera;
            const double ray_len = std::sqrt(dot(ray, ray));
            double zbuf = LAB_FAR;
            std::uint8_t &pixel = img.pixels[static_cast<std::size_t>(r) * side + c];
            for (const lab_triangle &t : tris) lab_test(t, camera, ray, ray_len, zbuf, pixel);
        }
    return img;
}

lab_image render_lab_fast(const mesh &m, const lab_camera &cam, int side) {
    if (side < 2) return {};
    const std::vector<lab_triangle> tris = lab_triangles(m, cam);
    lab_image img = blank(side);
    const v3 camera = load(cam.camera), forward = load(cam.center) - camera;
    const v3 across = load(cam.right) - load(cam.left), down = load(cam.bottom) - load(cam.top);
    const v3 topleft = load(cam.topleft);
    // The rays and their lengths, once per pixel (the same values raycast_lab computes).
    std::vector<v3> rays(static_cast<std::size_t>(side) * side);
    std::vector<double> lengths(rays.size()), zbuf(rays.size(), LAB_FAR);
    for (int r = 0; r < side; ++r)
        for (int c = 0; c < side; ++c) {
            const std::size_t i = static_cast<std::size_t>(r) * side + c;
            rays[i] = image_point(cam, r, c, side) - camera;
            lengths[i] = std::sqrt(dot(rays[i], rays[i]));
        }
    // Pixel coordinates (column, row) of a point seen from the camera: where its ray meets
    // the image plane (through centre, normal `forward`), in units of the pixel grid.
    auto project = [&](v3 p, double &col, double &row) {
        const v3 w = p - camera;
        const double fw = dot(forward, w);
        if (!(fw > 0)) return false;
        const v3 q = camera + (dot(forward, forward) / fw) * w - topleft;
        col = dot(q, across) / dot(across, across) * (side - 1);
        row = dot(q, down) / dot(down, down) * (side - 1);
        return std::isfinite(col) && std::isfinite(row);
    };
    for (const lab_triangle &t : tris) {
        double c0 = INFINITY, c1 = -INFINITY, r0 = INFINITY, r1 = -INFINITY;
        bool whole = false;
        for (const v3 &v : {t.v0, t.v1, t.v2}) {
            double col, row;
            if (!project(v, col, row)) {
                whole = true;
                break;
            }
            c0 = std::min(c0, col), c1 = std::max(c1, col), r0 = std::min(r0, row), r1 = std::max(r1, row);
        }
        const double lim = side - 1;
        const int x0 = whole ? 0 : static_cast<int>(std::clamp(std::floor(c0) - FAST_BOX_MARGIN, 0.0, lim));
        const int x1 = whole ? side - 1 : static_cast<int>(std::clamp(std::ceil(c1) + FAST_BOX_MARGIN, -1.0, lim));
        const int y0 = whole ? 0 : static_cast<int>(std::clamp(std::floor(r0) - FAST_BOX_MARGIN, 0.0, lim));
        const int y1 = whole ? side - 1 : static_cast<int>(std::clamp(std::ceil(r1) + FAST_BOX_MARGIN, -1.0, lim));
        for (int r = y0; r <= y1; ++r)
            for (int c = x0; c <= x1; ++c) {
                const std::size_t i = static_cast<std::size_t>(r) * side + c;
                lab_test(t, camera, rays[i], lengths[i], zbuf[i], img.pixels[i]);
            }
    }
    return img;
}

status save_lab_image(const lab_image &img, const std::string &path) {
    if (img.width <= 0 || img.height <= 0 || img.pixels.size() != static_cast<std::size_t>(img.width) * img.height)
        return error{path, 0, -1, "lab image is empty"};
    const bool pgm = path.size() >= 4 && (path.compare(path.size() - 4, 4, ".pgm") == 0 ||
                                          path.compare(path.size() - 4, 4, ".PGM") == 0);
    std::string bytes = (pgm ? "P5\n" : "P6\n") + std::to_string(img.width) + " " + std::to_string(img.height) + "\n255\n";
    for (std::uint8_t v : img.pixels) bytes.append(pgm ? 1 : 3, static_cast<char>(v));
    return write_file_atomic(path, bytes.data(), bytes.size());
}

}  // namespace tiny3d
