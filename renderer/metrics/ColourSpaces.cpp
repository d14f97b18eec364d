#include "metrics/ColourSpaces.h"

#include <cmath>

namespace pb::metrics::colour {
namespace {

// Linear sRGB -> XYZ for the D65 white (the sRGB standard's matrix at 7 digits).
constexpr double kRgbToXyz[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                                    {0.2126729, 0.7151522, 0.0721750},
                                    {0.0193339, 0.1191920, 0.9503041}};

// The inverse is computed rather than typed in, so both directions agree to rounding.
struct Inverse {
    double m[3][3];
    Inverse() {
        const auto& a = kRgbToXyz;
        const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                // Cofactor of a[c][r] (transposed) over the determinant.
                const int r0 = (c + 1) % 3, r1 = (c + 2) % 3, c0 = (r + 1) % 3, c1 = (r + 2) % 3;
                m[r][c] = (a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0]) / det;
            }
    }
};

Vec3 multiply(const double (&m)[3][3], const Vec3& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
            m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

// CIELAB's cube root with the linear segment near black (CIE 15).
double labF(double t) {
    constexpr double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3 * delta * delta) + 4.0 / 29.0;
}

} // namespace

double srgbToLinear(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

Vec3 linearRgbToXyz(const Vec3& rgb) {
    return multiply(kRgbToXyz, rgb);
}

Vec3 xyzToLinearRgb(const Vec3& xyz) {
    static const Inverse inverse;
    return multiply(inverse.m, xyz);
}

Vec3 whitePoint() {
    return linearRgbToXyz({1.0, 1.0, 1.0});
}

Vec3 xyzToYcxcz(const Vec3& xyz) {
    static const Vec3 w = whitePoint();
    const double x = xyz[0] / w[0], y = xyz[1] / w[1], z = xyz[2] / w[2];
    return {116 * y - 16, 500 * (x - y), 200 * (y - z)};
}

Vec3 ycxczToXyz(const Vec3& v) {
    static const Vec3 w = whitePoint();
    const double y = (v[0] + 16) / 116;
    return {(y + v[1] / 500) * w[0], y * w[1], (y - v[2] / 200) * w[2]};
}

Vec3 xyzToLab(const Vec3& xyz) {
    static const Vec3 w = whitePoint();
    const double fx = labF(xyz[0] / w[0]), fy = labF(xyz[1] / w[1]), fz = labF(xyz[2] / w[2]);
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

} // namespace pb::metrics::colour
