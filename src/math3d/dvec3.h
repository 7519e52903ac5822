// dvec3.h — (internal) a double-precision 3-vector and its few operations, for the code
// that evaluates geometry in double (slerp, cluster culling bounds, the PLY lab's ray
// caster). Plain arithmetic: NaN in, NaN out.
#ifndef TINY3D_DVEC3_H
#define TINY3D_DVEC3_H

#include <cmath>

#include "math3d.h"

namespace tiny3d::detail {

struct dvec3 {
    double x, y, z;
};
inline dvec3 widen(vec3_t v) { return {v.x, v.y, v.z}; }
inline dvec3 operator+(dvec3 a, dvec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline dvec3 operator-(dvec3 a, dvec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline dvec3 operator*(dvec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline dvec3 operator*(double s, dvec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(dvec3 a, dvec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline dvec3 cross(dvec3 a, dvec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double length(dvec3 a) { return std::sqrt(dot(a, a)); }

}  // namespace tiny3d::detail

#endif
