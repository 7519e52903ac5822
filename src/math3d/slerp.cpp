// slerp.cpp — the report's vec3_slerp (faithful, made safe) and the robust variant.
#include <algorithm>
#include <cmath>

#include "dvec3.h"
#include "math3d.h"

namespace {

// The report switches to lerp + renormalise above this cosine.
constexpr float kReportLerpCosine = 0.9995f;
// Below this sin θ₀ with a·b < 0 (within ~17° of antipodal) the report's 1/sin θ₀ turns the Quake
// normalisation's 1.75e-3 length error into directions wrong by up to 0.9 (and divides
// by ~0 at θ₀ = π); the faithful variant hands such pairs to the robust one. Measured
// worst error in the last 15° band: 0.9 at 0.05, 0.37 at 0.1, 0.08 at 0.2, 1.7e-3 at 0.3.
constexpr float kFaithfulMinSin = 0.3f;

using tiny3d::detail::dvec3;
dvec3 to_double(vec3_t v) { return tiny3d::detail::widen(v); }
bool is_zero(vec3_t v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }
bool all_finite(vec3_t v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

vec3_t vec3_slerp(vec3_t a, vec3_t b, float t) {
    if (!std::isfinite(t)) return {0.0f, 0.0f, 0.0f};
    a = vec3_normalize_fast(a);  // zero or NaN → zero
    b = vec3_normalize_fast(b);
    if (is_zero(a)) a = b;
    if (is_zero(b)) b = a;
    if (is_zero(a)) return {0.0f, 0.0f, 0.0f};
    float dot = a.x * b.x + a.y * b.y + a.z * b.z;
    if (dot > kReportLerpCosine) return vec3_normalize_fast(a + t * (b - a));
    dot = std::clamp(dot, -1.0f, 1.0f);
    const float theta_0 = std::acos(dot);
    const float sin_theta_0 = std::sin(theta_0);
    if (dot < 0.0f && sin_theta_0 < kFaithfulMinSin) return tiny3d::vec3_slerp_robust(a, b, t);
    const float theta = theta_0 * t;
    const float sin_theta = std::sin(theta);
    const float s0 = std::cos(theta) - dot * sin_theta / sin_theta_0;
    const float s1 = sin_theta / sin_theta_0;
    return s0 * a + s1 * b;
}

namespace tiny3d {

// Turning â toward b̂ by t·θ in the plane they span: dir = cos(tθ)·â + sin(tθ)·p with p
// the unit vector ⟂ â in that plane, p = ((â×b̂)×â)/|…|, θ = atan2(|â×b̂|, â·b̂). All in
// double: near θ = 0 and θ = π the float inputs still define p to ~1e-16/sin θ.
vec3_t vec3_slerp_robust(vec3_t a, vec3_t b, float t) {
    if (!all_finite(a) || !all_finite(b) || !std::isfinite(t)) return {0.0f, 0.0f, 0.0f};
    const dvec3 ad = to_double(a), bd = to_double(b);
    const double len_a = length(ad), len_b = length(bd);
    if (len_a == 0.0 && len_b == 0.0) return {0.0f, 0.0f, 0.0f};
    const dvec3 ua = len_a > 0.0 ? ad * (1.0 / len_a) : bd * (1.0 / len_b);
    const dvec3 ub = len_b > 0.0 ? bd * (1.0 / len_b) : ua;
    const double out_length = std::max(0.0, (1.0 - t) * len_a + double(t) * len_b);

    const dvec3 normal = cross(ua, ub);
    const double sin_theta = length(normal), cos_theta = dot(ua, ub);
    const double theta = std::atan2(sin_theta, cos_theta);
    dvec3 perpendicular = {0.0, 0.0, 0.0};  // unused when θ = 0 (sin(tθ) = 0)
    if (sin_theta > 0.0) {
        perpendicular = cross(normal, ua);
    } else if (cos_theta < 0.0) {
        // Exactly antipodal: the fixed perpendicular, made exactly ⟂ â in double.
        const dvec3 q = to_double(vec3_any_perpendicular(vec3_t{float(ua.x), float(ua.y), float(ua.z)}));
        perpendicular = q + ua * -dot(q, ua);
    }
    const double p_len = length(perpendicular);
    if (p_len > 0.0) perpendicular = perpendicular * (1.0 / p_len);
    const double angle = double(t) * theta;
    const dvec3 out = (ua * std::cos(angle) + perpendicular * std::sin(angle)) * out_length;
    return {float(out.x), float(out.y), float(out.z)};
}

}  // namespace tiny3d
