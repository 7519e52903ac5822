// cluster_view.h — cluster culling for the render context's schedule (internal). In: a
// draw's model-view-projection and the target. Out: per chunk, whether it is proven
// back-facing (schedule/raster_clusters.cpp). Called by the render context's set-up loop
// (set_up_piece). Not installed.
#ifndef TINY3D_RASTER_CLUSTER_VIEW_H
#define TINY3D_RASTER_CLUSTER_VIEW_H

#include "raster.h"

namespace tiny3d::detail {

// What one draw needs to classify chunks (raster_cluster): the MVP rows, the eye and the
// screen, with the per-draw constants of cluster_back_facing precomputed.
struct cluster_view {
    double row[4][4];         // MVP rows x, y, z, w: row[r][c] (the float matrix, exactly)
    double abs_row[4][4];     // |row[r][c]|
    double row_length[4];     // |xyz part of row r|
    double plane[6][4];       // near z + w, far w − z, x + g·w, g·w − x, y + g·w, g·w − y
    double plane_length[6];   // |xyz part|
    double plane_guard[6];    // the plane's w coefficient (1 or g), for its float error
    int plane_row[6];         // the plane's x, y or z row
    double eye[3];            // object-space eye position (when cone_usable)
    double eye_slack;         // rounding allowance for distances to the eye
    double area_scale;        // hw·hh·|κ|: a triangle's screen double area (px²) is
                              // area_scale · |N| · n·(p − eye) / (w0·w1·w2)
    double half_w, half_h;
    bool cone_usable;         // a perspective eye with front = counter-clockwise, and cull_mode::back
};
cluster_view make_cluster_view(const mat4_t &mvp, int width, int height, float guard, cull_mode cull);

// Whether chunk c is back-facing as a whole: every vertex has outcode 0 (inside near, far
// and guard band) and every triangle's snapped area is nonzero and back-facing.
// Conservative: claimed only when the float transform and the 1/16 px snapping of
// render_context cannot make any triangle of the chunk decide otherwise.
bool cluster_back_facing(const cluster_view &v, const raster_cluster &c);

}  // namespace tiny3d::detail

#endif
