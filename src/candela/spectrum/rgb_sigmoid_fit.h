#pragma once
// The optimizer behind the RGB-to-spectrum table (Jakob & Hanika 2019, sec. 3-4; pbrt-v4's
// rgb2spec_opt): the sigmoid polynomial whose reflectance, lit by D65 and seen by the CIE 1931
// observer, has a given linear sRGB colour, found by Gauss-Newton on the CIELAB difference.
// tools/rgb2spec/ runs it over the table's nodes (rgb_to_spectrum_table.h); tests check its
// residuals.
//
// The forward model is the one the renderer's round trip computes (dense_spectrum.h's
// spectrum_to_xyz): sums over every nm from 360 to 830 of x-bar, y-bar, z-bar times D65 (Y = 1)
// times the reflectance, divided by the integral of y-bar. The polynomial is solved for in the
// normalized wavelength t = (lambda - 360) / 470 in [0, 1], where the three coefficients have
// comparable sizes and the Jacobian is well conditioned, and converted to nm at the end.
#include <array>

#include "candela/math/rgb.h"
#include "candela/math/vec.h"
#include "candela/spectrum/dense_spectrum.h"
#include "candela/spectrum/rgb_sigmoid.h"

namespace candela {

// Coefficients (a, b, c) of x(t) = a t^2 + b t + c over the normalized wavelength t.
using SigmoidCoefficients = Vec3d;

class RgbSigmoidFit {
  public:
    RgbSigmoidFit();

    // CIE XYZ of the reflectance s(x(t)) under D65 (Y of a perfect white = 1).
    Vec3d reflectance_xyz(const SigmoidCoefficients& k) const;
    // CIELAB of an XYZ colour relative to D65's white.
    Vec3d lab(const Vec3d& xyz) const;
    // Lab(target) - Lab(reflectance of k): the residual Gauss-Newton drives to zero.
    Vec3d residual(const SigmoidCoefficients& k, const Rgb& target) const;
    // Gauss-Newton from k (the previous node's solution, or 0): updates k and returns the final
    // residual's Euclidean norm (a CIELAB Delta E 1976).
    double solve(const Rgb& target, SigmoidCoefficients& k) const;

    // A guard against a step that runs away (pbrt-v4's optimizer caps at 200, which stops dark
    // saturated colours short: their coefficients grow as 1 / sqrt(luminance)); solutions of the
    // table's nodes stay far below it.
    static constexpr double kMaxCoefficient = 1e6;

  private:
    // Lab and its Jacobian d Lab / d k at k.
    void lab_and_jacobian(const SigmoidCoefficients& k, Vec3d& lab_out, double jacobian[3][3]) const;

    std::array<Vec3d, kDenseSamples> weight_{};  // per nm: (x-bar, y-bar, z-bar) D65 / Y integral
    Vec3d white_{};                               // XYZ of D65
};

// The same spectrum with x in nm: c0 lambda^2 + c1 lambda + c2 (rounded to float).
RgbSigmoid sigmoid_in_nm(const SigmoidCoefficients& k);

}  // namespace candela
