#include "candela/spectrum/rgb_sigmoid_fit.h"

#include <cmath>

#include "candela/spectrum/cie_tables.h"
#include "candela/spectrum/color_space.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {

namespace {

constexpr double kLambdaMin = 360.0, kLambdaSpan = 470.0;
constexpr int kMaxIterations = 50;
// Delta E (CIE 1976) below which a colour counts as matched: ~1e-6 in sRGB, three orders under the
// round trip's tolerance and far below what the table's interpolation adds.
constexpr double kTolerance = 1e-5;

// rgb_sigmoid.h's s(x) in double, s = q or 1 - q with q = 1 / (2 r (r + |x|)), r = sqrt(1 + x^2),
// and ds/dx = 1 / (2 r^3).
double sigmoid(double x, double r) {
    const double q = 1.0 / (2.0 * r * (r + std::abs(x)));
    return x < 0.0 ? q : 1.0 - q;
}
double sigmoid(double x) { return sigmoid(x, std::sqrt(1.0 + x * x)); }

// The cube root by Newton's method: only IEEE-exact operations, so the table comes out the same
// on every machine (libm's cbrt may differ in the last bit). With t = m 2^e, m in [1/2, 1), the
// start 2^floor(e/3) is within a factor 1.6 of the root, and seven steps reach double precision.
double cube_root(double t) {
    if (!(t > 0.0)) return 0.0;
    int e = 0;
    std::frexp(t, &e);
    double y = std::ldexp(1.0, e >= 0 ? e / 3 : -((2 - e) / 3));
    for (int i = 0; i < 7; ++i) y = (2.0 * y + t / (y * y)) / 3.0;
    return y;
}

// CIELAB's companding f(t) and f'(t) (CIE 15:2004, 8.2.1): a cube root, linear near black.
constexpr double kDelta = 6.0 / 29.0;
double lab_f(double t) {
    return t > kDelta * kDelta * kDelta ? cube_root(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}
double lab_f_derivative(double t) {
    if (!(t > kDelta * kDelta * kDelta)) return 1.0 / (3.0 * kDelta * kDelta);
    const double c = cube_root(t);
    return 1.0 / (3.0 * c * c);
}

// Solves a x = r by Cramer's rule; false if a is singular.
bool solve3(const double a[3][3], const Vec3d& r, Vec3d& x) {
    auto det3 = [](const double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det3(a);
    if (!(std::abs(d) > 1e-300)) return false;
    for (int j = 0; j < 3; ++j) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int c = 0; c < 3; ++c) m[i][c] = c == j ? r[i] : a[i][c];
        x[j] = det3(m) / d;
    }
    return std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z);
}

// Scales k down to |coefficients| <= kMaxCoefficient, keeping the polynomial's roots (where the
// reflectance crosses 1/2) and flattening only the sigmoid's slope (as pbrt-v4's optimizer).
SigmoidCoefficients capped(const SigmoidCoefficients& k) {
    const double m = max_component(abs(k));
    return m > RgbSigmoidFit::kMaxCoefficient ? k * (RgbSigmoidFit::kMaxCoefficient / m) : k;
}

}  // namespace

RgbSigmoidFit::RgbSigmoidFit() {
    const DenseSpectrum& d65 = d65_illuminant();
    const DenseSpectrum &x = cie_x_bar(), &y = cie_y_bar(), &z = cie_z_bar();
    for (int i = 0; i < kDenseSamples; ++i) {
        const double w = double(d65.v[size_t(i)]) / double(kCieYIntegral);
        weight_[size_t(i)] = Vec3d(double(x.v[size_t(i)]), double(y.v[size_t(i)]), double(z.v[size_t(i)])) * w;
    }
    white_ = srgb_color_space().white_xyz;
}

Vec3d RgbSigmoidFit::reflectance_xyz(const SigmoidCoefficients& k) const {
    Vec3d xyz;
    for (int i = 0; i < kDenseSamples; ++i) {
        const double t = double(i) / kLambdaSpan;
        xyz += weight_[size_t(i)] * sigmoid((k.x * t + k.y) * t + k.z);
    }
    return xyz;
}

Vec3d RgbSigmoidFit::lab(const Vec3d& xyz) const {
    const double fx = lab_f(xyz.x / white_.x), fy = lab_f(xyz.y / white_.y), fz = lab_f(xyz.z / white_.z);
    return Vec3d(116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz));
}

Vec3d RgbSigmoidFit::residual(const SigmoidCoefficients& k, const Rgb& target) const {
    return lab(linear_srgb_to_xyz(target)) - lab(reflectance_xyz(k));
}

void RgbSigmoidFit::lab_and_jacobian(const SigmoidCoefficients& k, Vec3d& lab_out, double jacobian[3][3]) const {
    // XYZ and d XYZ / d k, summed together.
    Vec3d xyz, d_xyz[3];
    for (int i = 0; i < kDenseSamples; ++i) {
        const double t = double(i) / kLambdaSpan;
        const double x = (k.x * t + k.y) * t + k.z;
        const double r = std::sqrt(1.0 + x * x);
        xyz += weight_[size_t(i)] * sigmoid(x, r);
        const Vec3d g = weight_[size_t(i)] * (0.5 / (r * r * r));
        d_xyz[0] += g * (t * t);
        d_xyz[1] += g * t;
        d_xyz[2] += g;
    }
    lab_out = lab(xyz);
    // d Lab / d XYZ is sparse: L depends on Y, a on X and Y, b on Y and Z.
    const double gx = lab_f_derivative(xyz.x / white_.x) / white_.x;
    const double gy = lab_f_derivative(xyz.y / white_.y) / white_.y;
    const double gz = lab_f_derivative(xyz.z / white_.z) / white_.z;
    for (int j = 0; j < 3; ++j) {
        const Vec3d& d = d_xyz[j];
        jacobian[0][j] = 116.0 * gy * d.y;
        jacobian[1][j] = 500.0 * (gx * d.x - gy * d.y);
        jacobian[2][j] = 200.0 * (gy * d.y - gz * d.z);
    }
}

double RgbSigmoidFit::solve(const Rgb& target, SigmoidCoefficients& k) const {
    const Vec3d target_lab = lab(linear_srgb_to_xyz(target));
    Vec3d fit_lab;
    double jacobian[3][3];
    lab_and_jacobian(k, fit_lab, jacobian);
    Vec3d r = target_lab - fit_lab;
    for (int it = 0; it < kMaxIterations && length_squared(r) >= kTolerance * kTolerance; ++it) {
        // The Gauss-Newton step solves J step = r: three residuals, three unknowns, so it is
        // Newton's step for Lab(k) = target. Where the sigmoid saturates the linearization
        // overshoots, so the step is halved until the residual shrinks.
        Vec3d step;
        if (!solve3(jacobian, r, step)) break;
        bool improved = false;
        for (int halvings = 0; halvings < 12 && !improved; ++halvings, step *= 0.5) {
            const SigmoidCoefficients next = capped(k + step);
            Vec3d next_lab;
            double next_jacobian[3][3];
            lab_and_jacobian(next, next_lab, next_jacobian);
            if (length_squared(target_lab - next_lab) < length_squared(r)) {
                k = next;
                r = target_lab - next_lab;
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) jacobian[i][j] = next_jacobian[i][j];
                improved = true;
            }
        }
        if (!improved) break;
    }
    return length(r);
}

RgbSigmoid sigmoid_in_nm(const SigmoidCoefficients& k) {
    // x = a t^2 + b t + c with t = (lambda - l0) s, s = 1 / 470:
    // a s^2 lambda^2 + (b s - 2 a l0 s^2) lambda + (c - b l0 s + a l0^2 s^2).
    const double s = 1.0 / kLambdaSpan, l0 = kLambdaMin;
    return RgbSigmoid{float(k.x * s * s), float(k.y * s - 2.0 * k.x * l0 * s * s),
                      float(k.z - k.y * l0 * s + k.x * l0 * l0 * s * s)};
}

}  // namespace candela
