// mesh_internal.h — helpers shared by mesh.cpp and triangulate.cpp (not installed).
#ifndef TINY3D_MESH_INTERNAL_H
#define TINY3D_MESH_INTERNAL_H

#include <array>
#include <cstddef>

#include "mesh.h"

namespace tiny3d {

// Σ p_k × p_{k+1} over face f's corners in double: twice its vector area (Newell).
// Precondition: face_in_range(m, f).
std::array<double, 3> newell_vector(const mesh &m, std::size_t f);
// Every corner of face f refers to an existing position.
bool face_in_range(const mesh &m, std::size_t f);

}  // namespace tiny3d

#endif
