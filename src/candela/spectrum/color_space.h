#pragma once
// Linear sRGB (Rec. 709 primaries) and CIE XYZ, with the white of the D65 table
// (dense_spectrum.h) as pbrt-v4's RGBColorSpace::sRGB computes it, so that XYZ of the D65
// illuminant maps to RGB (1, 1, 1) exactly up to rounding.
#include "candela/math/rgb.h"
#include "candela/math/vec.h"

namespace candela {

struct Matrix3d {
    double m[3][3] = {};
    Vec3d operator*(const Vec3d& v) const {
        return Vec3d(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                     m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
    }
    Matrix3d operator*(const Matrix3d& o) const;
    Matrix3d inverse() const;
};

struct SrgbColorSpace {
    Matrix3d xyz_from_rgb;
    Matrix3d rgb_from_xyz;
    Vec3d white_xyz;  // of D65, Y = 1
};
const SrgbColorSpace& srgb_color_space();

inline Rgb xyz_to_linear_srgb(const Vec3d& xyz) {
    const Vec3d v = srgb_color_space().rgb_from_xyz * xyz;
    return Rgb(float(v.x), float(v.y), float(v.z));
}
inline Vec3d linear_srgb_to_xyz(const Rgb& c) {
    return srgb_color_space().xyz_from_rgb * Vec3d(c.r, c.g, c.b);
}

}  // namespace candela
