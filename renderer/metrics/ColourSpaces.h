#pragma once
// Colour conversions FLIP needs: sRGB transfer, linear sRGB <-> CIE XYZ (D65), XYZ <-> YCxCz
// (the linear opponent space FLIP filters in) and XYZ -> CIELAB, all relative to the D65
// white of the sRGB primaries (Y of white = 1).
#include <array>

namespace pb::metrics::colour {

using Vec3 = std::array<double, 3>;

double srgbToLinear(double encoded); // IEC 61966-2-1 piecewise curve, input in [0,1]

Vec3 linearRgbToXyz(const Vec3& rgb);
Vec3 xyzToLinearRgb(const Vec3& xyz);
Vec3 whitePoint(); // XYZ of linear RGB (1,1,1)

// YCxCz (Zhang & Wandell's S-CIELAB opponent space): Y = 116 Y/Yn - 16,
// Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn). Linear in XYZ, so it can be filtered.
Vec3 xyzToYcxcz(const Vec3& xyz);
Vec3 ycxczToXyz(const Vec3& ycxcz);

Vec3 xyzToLab(const Vec3& xyz); // CIE 1976 L*a*b*

} // namespace pb::metrics::colour
