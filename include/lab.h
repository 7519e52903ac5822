// lab.h — the library part of the PLY ray-cast program (the lab exercise it reproduces: a
// ray per pixel, z-buffer): the lab's camera (eq. 1–12), the faithful per-pixel ray
// caster (eq. 13–21), its fast projected-box variant and the lab's image files.
// Implementation: src/lab/raster_lab.cpp; the program is demo/ply_render.cpp.
//
// Conventions: the lab's own (double precision, angles in radians); it uses the mesh
// module and nothing of the render context (raster.h).
#ifndef TINY3D_LAB_H
#define TINY3D_LAB_H

#include <cstdint>
#include <string>
#include <vector>

#include "mesh.h"
#include "tiny3d_result.h"

namespace tiny3d {

inline constexpr int LAB_IMAGE_SIDE = 256;

// The lab's camera: bounding box centre and extent E, the rotated camera and up vectors
// (eq. 1–4) and the image rectangle (eq. 5–12), in double precision.
struct lab_camera {
    double center[3], extent;
    double camera[3], up[3];
    double left[3], right[3], top[3], bottom[3], topleft[3];
};

// Builds the lab camera for mesh positions and rotation angles in RADIANS (X, then Y,
// then Z, eq. 1–3 applied as Rz·Ry·Rx). Error when the mesh has no finite position.
result<lab_camera> ply_lab_camera(const mesh &m, double rx, double ry, double rz);

// A lab image: side × side bytes, row-major, 0 = background, 155 + (i mod 100) for the
// triangle i (faces fan-split in file order) nearest along the pixel's ray.
struct lab_image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;
};

// The faithful method: for each pixel the ray through eq. 13, every triangle tested with
// eq. 14–21, z-buffer on n/d (a later triangle wins exact ties, as the lab's "greater
// than" test implies); rays within 1e-9 relative of parallel to a plane skip it.
lab_image raycast_lab(const mesh &m, const lab_camera &cam, int side = LAB_IMAGE_SIDE);

// The fast path: the same per-pixel tests, but each triangle only visits the pixels of its
// projected bounding box (projection through the lab camera, widened by 2 px). The image
// is identical to raycast_lab's (same arithmetic, same order per pixel).
lab_image render_lab_fast(const mesh &m, const lab_camera &cam, int side = LAB_IMAGE_SIDE);

// Writes the lab image as P6 PPM (grey: r = g = b) or, when path ends in ".pgm", as P5.
status save_lab_image(const lab_image &img, const std::string &path);

}  // namespace tiny3d

#endif
