// seam_split.h — a mesh cut into patches that each keep their own copy of the positions they
// use, as the Utah teapot's Bézier patches are shipped: the surface is the same, but the
// seams between patches repeat their vertices (for the crease-normal tests).
#ifndef TINY3D_SEAM_SPLIT_H
#define TINY3D_SEAM_SPLIT_H

#include <cstdint>
#include <map>
#include <utility>

#include "mesh.h"

namespace seam_split {

// Faces go to patch (face index / faces_per_patch); each patch duplicates the positions it
// uses, so positions on a seam between patches appear once per patch. Faces, their order
// and their winding are kept; corner attributes are dropped.
inline tiny3d::mesh split_into_patches(const tiny3d::mesh &m, std::size_t faces_per_patch) {
    tiny3d::mesh out;
    std::map<std::pair<std::size_t, std::uint32_t>, std::uint32_t> copy;  // (patch, position) → new index
    for (std::size_t f = 0; f < m.face_count(); ++f) {
        const std::size_t patch = f / faces_per_patch;
        for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) {
            const auto key = std::make_pair(patch, m.indices[k]);
            auto it = copy.find(key);
            if (it == copy.end()) {
                it = copy.emplace(key, static_cast<std::uint32_t>(out.positions.size())).first;
                out.positions.push_back(m.positions[m.indices[k]]);
            }
            out.indices.push_back(it->second);
        }
        out.face_start.push_back(static_cast<std::uint32_t>(out.indices.size()));
    }
    return out;
}

}  // namespace seam_split

#endif
