// texture_walk.h — the anisotropic filter's tap walk over one mip level (texture/: textures,
// mip chains, lookups). In: a level and N taps on a line in its texel space; out: the taps'
// bilinear lookups, summed in a fixed order. Called by texture.cpp's anisotropic filter
// through the kernel table (kernel_table::walk_taps; null: walk_taps_portable, the family's
// reference, which every kernel matches bit for bit). Not installed.
#ifndef TINY3D_TEXTURE_WALK_H
#define TINY3D_TEXTURE_WALK_H

namespace tiny3d::detail {

struct tap_walk {
    const float *texels;  // the level, width × height, rows in order; repeat addressing
    int width, height;    // width · height < 2^31
    float fx0, fy0;       // tap 0 in texel space, (u·width − ½, v·height − ½): centres at i + ½
    float sx, sy;         // from one tap to the next, in texels
    int taps;             // 1 … 64
};

// The sum of the bilinear lookups at (fx0 + i·sx, fy0 + i·sy), i < taps, each texel index in
// [−width, 2·width − 1) (likewise y). Tap i goes to lane i mod 8 and the lanes are summed as
// ((0 + 4) + (2 + 6)) + ((1 + 5) + (3 + 7)), an eight-lane kernel's order: the same bits.
float walk_taps_portable(const tap_walk &w);
float walk_taps_avx2(const tap_walk &w);  // builds with the AVX2 kernels, for CPUs with AVX2

}  // namespace tiny3d::detail

#endif
