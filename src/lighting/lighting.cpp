// lighting.cpp — lights, Lambert per edge (faithful) and per face (flat / Gouraud / Phong).
#include "lighting.h"
#include "flat_normal.h"

#include <string>

using tiny3d::clamp01;
using tiny3d::unit_or_zero;

float lambert_intensity(vec3_t start, vec3_t end, vec3_t light_dir) {
    return clamp01(tiny3d::vec3_dot(unit_or_zero(end - start), unit_or_zero(light_dir)));
}

namespace tiny3d {

namespace {

bool finite3(vec3_t v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

error light_error(std::size_t index, const std::string &what) {
    return error{"", 0, -1, "light " + std::to_string(index) + ": " + what};
}

}  // namespace

result<light_rig> make_light_rig(std::span<const light_t> lights, float ambient) {
    if (lights.size() > static_cast<std::size_t>(MAX_LIGHTS))
        return error{"", 0, -1,
                     std::to_string(lights.size()) + " lights, at most " + std::to_string(MAX_LIGHTS)};
    if (!(ambient >= 0.0f && ambient <= 1.0f))
        return error{"", 0, -1, "ambient " + std::to_string(ambient) + " is outside 0..1"};
    light_rig rig{};
    rig.ambient = ambient;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        light_t l = lights[i];
        if (!(std::isfinite(l.intensity) && l.intensity >= 0.0f))
            return light_error(i, "intensity must be finite and >= 0");
        if (l.kind == light_kind::point) {
            if (!finite3(l.position)) return light_error(i, "position is not finite");
        } else if (l.kind == light_kind::directional) {
            if (!finite3(l.direction)) return light_error(i, "direction is not finite");
            l.direction = unit_or_zero(l.direction);
            if (tiny3d::vec3_dot(l.direction, l.direction) == 0.0f) return light_error(i, "direction is zero");
        } else {
            return light_error(i, "unknown kind " + std::to_string(static_cast<int>(l.kind)));
        }
        rig.lights[rig.count++] = l;
    }
    return rig;
}

vec3_t flat_unit_normal(vec3_t a, vec3_t b, vec3_t c) {
    // (b − a) × (c − a) in double: in float it overflows for faces of size ~1e19 and
    // underflows below ~1e-19, which would turn a real face into "no normal".
    const double ux = double(b.x) - a.x, uy = double(b.y) - a.y, uz = double(b.z) - a.z;
    const double vx = double(c.x) - a.x, vy = double(c.y) - a.y, vz = double(c.z) - a.z;
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
    return len > 0.0 && std::isfinite(len) ? vec3_t{float(nx / len), float(ny / len), float(nz / len)}
                                           : vec3_t{0.0f, 0.0f, 0.0f};
}

float shade_flat(const light_rig &rig, vec3_t a, vec3_t b, vec3_t c) {
    return shade_point(rig, (a + b + c) * (1.0f / 3.0f), flat_unit_normal(a, b, c));
}

float shade_gouraud_vertex(const light_rig &rig, vec3_t p, vec3_t normal) {
    return shade_point(rig, p, unit_or_zero(normal));
}

normal_transform make_normal_transform(mat4_t model) {
    // a(r, c): element (row r, column c) of the upper 3×3 (column-major storage).
    auto a = [&model](int r, int c) { return model.m[c * 4 + r]; };
    normal_transform t{};
    // Cofactor C(r, c) = (−1)^(r+c) · minor(r, c); with cyclic indices the sign is built in.
    for (int r = 0; r < 3; ++r) {
        const int r1 = (r + 1) % 3, r2 = (r + 2) % 3;
        for (int c = 0; c < 3; ++c) {
            const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            t.m[r * 3 + c] = a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1);
        }
    }
    // det = Σ_c a(0, c)·C(0, c); a mirroring model (det < 0) would turn normals inward.
    const float det = a(0, 0) * t.m[0] + a(0, 1) * t.m[1] + a(0, 2) * t.m[2];
    if (det < 0.0f)
        for (float &v : t.m) v = -v;
    return t;
}

float shade_edge_faithful(const light_rig &rig, vec3_t a, vec3_t b) {
    const vec3_t midpoint = (a + b) * 0.5f;
    float sum = 0.0f;
    for (int i = 0; i < rig.count; ++i) {
        const light_t &l = rig.lights[i];
        const vec3_t to_light = l.kind == light_kind::point ? l.position - midpoint : l.direction;
        sum += l.intensity * lambert_intensity(a, b, to_light);
    }
    return clamp01(sum);
}

}  // namespace tiny3d
