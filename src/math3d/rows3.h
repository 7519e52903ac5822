// rows3.h — internal to src/math3d: a rotation block computed in double → mat4_t.
#ifndef TINY3D_MATH3D_ROWS3_H
#define TINY3D_MATH3D_ROWS3_H

#include "math3d.h"

namespace tiny3d::detail {

// The 4×4 matrix whose upper-left 3×3 block is r (given row by row), each entry rounded
// once to float; the rest is the identity's.
inline mat4_t from_rows3(const double (&r)[3][3]) {
    mat4_t m = mat4_identity();
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) m.m[col * 4 + row] = float(r[row][col]);
    return m;
}

}  // namespace tiny3d::detail

#endif
