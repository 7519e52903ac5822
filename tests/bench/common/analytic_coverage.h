// analytic_coverage.h — a prototype analytic-coverage renderer for the antialias bench
// (tests/bench/antialias.cpp): not part of libtiny3d.a. It answers by measurement whether
// exact per-pixel area coverage beats multisampling on error per millisecond
// (documentation/antialias.md, "Analytic coverage against multisampling").
//
// Coverage: the exact area of each triangle inside each pixel square [x, x+1] × [y, y+1]
// (px, y down), by signed-area accumulation — per row, each edge adds the area of the row
// to its right within each cell it crosses, and a prefix sum along the row gives the area
// of the triangle inside each cell — the same number as clipping the triangle against the
// pixel and taking the shoelace area, in O(perimeter + box) per triangle.
//
// Compositing: "coverage accumulation" front to back with saturating coverage (OpenGL's
// polygon antialiasing with GL_SRC_ALPHA_SATURATE): the triangles are sorted by their
// nearest window depth, nearest first; a pixel with accumulated coverage α takes
// t = min(c, 1 − α) of a triangle covering c, colour += t · shade (the triangle's Gouraud
// or flat intensity at the pixel centre, clamped to 0..1), α += t; finally colour += (1 − α)
// · clear. No z-buffer. Its known artefact, conflation: coverage is treated as disjoint from
// what is already covered, so a hidden triangle whose covered part of a pixel lies under a
// nearer one leaks into it (occluding contours over a surface with edges in the pixel), and
// interpenetrating or cyclically overlapping triangles are mis-ordered (one order per
// triangle, not per pixel). Adjacent triangles of one surface share an edge with
// complementary coverage, so they show no seam.
//
// Limits (a prototype): one thread; flat or Gouraud shading only, no texture; a triangle
// any of whose vertices is behind the near plane (w ≤ 0 or z outside −w..w) or whose
// box leaves the canvas is skipped and counted (skipped()).
#ifndef TINY3D_BENCH_ANALYTIC_COVERAGE_H
#define TINY3D_BENCH_ANALYTIC_COVERAGE_H

#include <cstdint>
#include <vector>

#include "canvas.h"
#include "raster.h"

namespace bench {

// The pixel box of one triangle and the area of the triangle inside each of its pixels.
class coverage_box {
public:
    // Areas of the triangle (x[k], y[k]) (px, either orientation, finite, |coordinates| < 2^20)
    // inside pixels [x0, x0 + w) × [y0, y0 + h), the triangle's box. area(i, j) ∈ [0, 1],
    // exact up to float rounding (~1e-6 per pixel near 1024 px).
    void compute(const float x[3], const float y[3]);
    int x0 = 0, y0 = 0, w = 0, h = 0;
    float area(int i, int j) const { return areas_[static_cast<std::size_t>(j) * w + i]; }
    const float *row(int j) const { return areas_.data() + static_cast<std::size_t>(j) * w; }

private:
    void edge(float ax, float ay, float bx, float by);
    std::vector<float> acc_, areas_;
    int stride_ = 0;
};

class analytic_renderer {
public:
    // Clears `canvas` to clear_intensity and draws the mesh as described above (draw_params:
    // model, view_projection, lights, shade flat or gouraud, cull). False (nothing drawn)
    // for another shading mode or a texture.
    bool render(canvas_t &canvas, const tiny3d::raster_mesh &mesh, const tiny3d::draw_params &params,
                float clear_intensity);
    long skipped() const { return skipped_; }

private:
    struct vertex {
        float x, y, z, shade;
        bool usable;
    };
    std::vector<vertex> vertices_;
    std::vector<std::uint32_t> keys_, order_, tmp_order_, tmp_keys_;
    std::vector<float> alpha_;
    coverage_box box_;
    long skipped_ = 0;
};

}  // namespace bench

#endif
