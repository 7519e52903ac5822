// inverse.cpp — determinant and general inverse of a mat4_t, in double.
//
// Laplace expansion by complementary minors (D. Eberly, "The Laplace Expansion
// Theorem: Computing the Determinants and Inverses of Matrices"): the six 2×2 minors of
// rows 0–1 (s) and of rows 2–3 (c) give det = s0c5 − s1c4 + s2c3 + s3c2 − s4c1 + s5c0
// and every cofactor as a three-term sum.
#include <cmath>
#include <cstdio>
#include <string>

#include "math3d.h"

namespace {

// Relative singularity threshold against Hadamard's bound |det| ≤ Π‖row‖: a ratio this
// small means the rows are dependent up to double rounding of float data.
constexpr double kSingularRatio = 1e-12;

struct minors {
    double a[4][4];  // a[row][col]
    double s[6], c[6];
    double det;
};

// Rows r0, r1 and columns c0, c1: a[r0][c0]·a[r1][c1] − a[r1][c0]·a[r0][c1].
double minor2(const double (&a)[4][4], int r0, int r1, int c0, int c1) {
    return a[r0][c0] * a[r1][c1] - a[r1][c0] * a[r0][c1];
}

minors expand(const mat4_t &m) {
    minors x{};
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) x.a[row][col] = m.m[col * 4 + row];
    // s[k], c[k]: minors of rows 0–1 and rows 2–3 on the k-th column pair.
    constexpr int kColumnPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    for (int k = 0; k < 6; ++k) {
        x.s[k] = minor2(x.a, 0, 1, kColumnPairs[k][0], kColumnPairs[k][1]);
        x.c[k] = minor2(x.a, 2, 3, kColumnPairs[k][0], kColumnPairs[k][1]);
    }
    const double *s = x.s, *c = x.c;
    x.det = s[0] * c[5] - s[1] * c[4] + s[2] * c[3] + s[3] * c[2] - s[4] * c[1] + s[5] * c[0];
    return x;
}

tiny3d::error singular(const std::string &why) { return tiny3d::error{"", 0, -1, "mat4_inverse: " + why}; }

std::string short_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

}  // namespace

namespace tiny3d {

double mat4_determinant(mat4_t m) { return expand(m).det; }

result<mat4_t> mat4_inverse(mat4_t m) {
    for (float v : m.m)
        if (!std::isfinite(v)) return singular("singular matrix (an entry is not finite)");
    const minors x = expand(m);
    const auto &a = x.a;
    const double *s = x.s, *c = x.c;
    double hadamard = 1.0;
    for (const auto &row : a) hadamard *= std::sqrt(row[0] * row[0] + row[1] * row[1] + row[2] * row[2] + row[3] * row[3]);
    if (!(std::fabs(x.det) > kSingularRatio * hadamard))
        return singular("singular matrix (|det| = " + short_number(std::fabs(x.det)) +
                        " is below 1e-12 of the product of the row lengths)");
    // Adjugate (transposed cofactors), b[row][col].
    const double b[4][4] = {
        {a[1][1] * c[5] - a[1][2] * c[4] + a[1][3] * c[3], -a[0][1] * c[5] + a[0][2] * c[4] - a[0][3] * c[3],
         a[3][1] * s[5] - a[3][2] * s[4] + a[3][3] * s[3], -a[2][1] * s[5] + a[2][2] * s[4] - a[2][3] * s[3]},
        {-a[1][0] * c[5] + a[1][2] * c[2] - a[1][3] * c[1], a[0][0] * c[5] - a[0][2] * c[2] + a[0][3] * c[1],
         -a[3][0] * s[5] + a[3][2] * s[2] - a[3][3] * s[1], a[2][0] * s[5] - a[2][2] * s[2] + a[2][3] * s[1]},
        {a[1][0] * c[4] - a[1][1] * c[2] + a[1][3] * c[0], -a[0][0] * c[4] + a[0][1] * c[2] - a[0][3] * c[0],
         a[3][0] * s[4] - a[3][1] * s[2] + a[3][3] * s[0], -a[2][0] * s[4] + a[2][1] * s[2] - a[2][3] * s[0]},
        {-a[1][0] * c[3] + a[1][1] * c[1] - a[1][2] * c[0], a[0][0] * c[3] - a[0][1] * c[1] + a[0][2] * c[0],
         -a[3][0] * s[3] + a[3][1] * s[1] - a[3][2] * s[0], a[2][0] * s[3] - a[2][1] * s[1] + a[2][2] * s[0]},
    };
    const double inv_det = 1.0 / x.det;
    mat4_t r = {};
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) {
            const float v = float(b[row][col] * inv_det);
            if (!std::isfinite(v)) return singular("the inverse overflows float (|det| = " + short_number(std::fabs(x.det)) + ")");
            r.m[col * 4 + row] = v;
        }
    return r;
}

}  // namespace tiny3d
