#include "candela/spectrum/color_space.h"

#include "candela/core/check.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {

Matrix3d Matrix3d::operator*(const Matrix3d& o) const {
    Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r.m[i][j] += m[i][k] * o.m[k][j];
    return r;
}

Matrix3d Matrix3d::inverse() const {
    const auto& a = m;
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    CANDELA_CHECK(det != 0.0);
    Matrix3d r;
    r.m[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det;
    r.m[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
    r.m[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
    r.m[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det;
    r.m[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
    r.m[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
    r.m[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det;
    r.m[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
    r.m[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
    return r;
}

namespace {
// XYZ of chromaticity (x, y) at luminance 1.
Vec3d xyz_of_xy(double x, double y) { return Vec3d(x / y, 1.0, (1.0 - x - y) / y); }
}  // namespace

const SrgbColorSpace& srgb_color_space() {
    static const SrgbColorSpace cs = [] {
        SrgbColorSpace s;
        // Rec. 709 primaries (ITU-R BT.709); the white is D65's table, as pbrt-v4 computes it.
        const Vec3d r = xyz_of_xy(0.64, 0.33), g = xyz_of_xy(0.30, 0.60), b = xyz_of_xy(0.15, 0.06);
        s.white_xyz = spectrum_to_xyz(d65_illuminant());
        Matrix3d p;
        const Vec3d cols[3] = {r, g, b};
        for (int j = 0; j < 3; ++j) {
            p.m[0][j] = cols[j].x;
            p.m[1][j] = cols[j].y;
            p.m[2][j] = cols[j].z;
        }
        const Vec3d c = p.inverse() * s.white_xyz;  // the primaries' weights that make the white
        const double w[3] = {c.x, c.y, c.z};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) s.xyz_from_rgb.m[i][j] = p.m[i][j] * w[j];
        s.rgb_from_xyz = s.xyz_from_rgb.inverse();
        return s;
    }();
    return cs;
}

}  // namespace candela
