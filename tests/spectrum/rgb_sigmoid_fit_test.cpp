// The optimizer behind the RGB-to-spectrum table (spectrum/rgb_sigmoid_fit.h): its CIELAB, its
// residual, and its solutions at nodes of the table, which the built table must hold.
#include "candela/spectrum/rgb_sigmoid_fit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "candela/spectrum/color_space.h"
#include "candela/spectrum/rgb_to_spectrum.h"
#include "candela/spectrum/rgb_to_spectrum_table.h"
#include "candela/spectrum/spectrum_rgb.h"
#include "spectrum_round_trip.h"

namespace candela {
namespace CANDELA_UNITY_ID {

const RgbSigmoidFit& fit() {
    static const RgbSigmoidFit f;
    return f;
}

TEST(RgbSigmoidFit, LabOfTheWhiteIsOneHundredAndOfBlackZero) {
    const Vec3d white = fit().lab(srgb_color_space().white_xyz);
    EXPECT_NEAR(white.x, 100.0, 1e-12);
    EXPECT_NEAR(white.y, 0.0, 1e-12);
    EXPECT_NEAR(white.z, 0.0, 1e-12);
    const Vec3d black = fit().lab(Vec3d(0.0, 0.0, 0.0));
    EXPECT_NEAR(black.x, 0.0, 1e-12);
    EXPECT_NEAR(black.y, 0.0, 1e-12);
    EXPECT_NEAR(black.z, 0.0, 1e-12);
    // CIE 15: L* = 116 (Y / Yn)^(1/3) - 16; 50 at Y = 0.18419.
    EXPECT_NEAR(fit().lab(srgb_color_space().white_xyz * 0.184187).x, 50.0, 1e-3);
}

TEST(RgbSigmoidFit, ConstantReflectanceIsItsGrey) {
    for (double v : {0.02, 0.18, 0.5, 0.9}) {
        const SigmoidCoefficients grey(0.0, 0.0, (v - 0.5) / std::sqrt(v * (1.0 - v)));
        const Vec3d xyz = fit().reflectance_xyz(grey);
        const Vec3d white = srgb_color_space().white_xyz;
        EXPECT_NEAR(white.y, 1.0, 1e-7);
        EXPECT_NEAR(xyz.x, v * white.x, 1e-12) << v;
        EXPECT_NEAR(xyz.y, v * white.y, 1e-12) << v;  // white.y = 1 up to D65's float scaling
        EXPECT_NEAR(xyz.z, v * white.z, 1e-12) << v;
        EXPECT_LT(length(fit().residual(grey, Rgb(float(v)))), 1e-5) << v;
    }
}

TEST(RgbSigmoidFit, NanometreFormIsTheSameSpectrum) {
    const SigmoidCoefficients k(-31.0, 27.5, -4.25);
    const RgbSigmoid s = sigmoid_in_nm(k);
    for (int lambda = 360; lambda <= 830; lambda += 10) {
        const double t = (lambda - 360.0) / 470.0;
        const double x = (k.x * t + k.y) * t + k.z;
        EXPECT_NEAR(s(float(lambda)), 0.5 + x / (2.0 * std::sqrt(1.0 + x * x)), 2e-6) << lambda;
    }
}

// A node of the sRGB table: slice (largest channel), z index k, x index i, y index j.
Rgb node_colour(int slice, int k, int i, int j) {
    const RgbToSpectrumTable& table = srgb_to_spectrum_table();
    const float z = table.nodes[k];
    float v[3];
    v[slice] = z;
    v[(slice + 1) % 3] = float(double(table.nodes[i]) * double(z));
    v[(slice + 2) % 3] = float(double(table.nodes[j]) * double(z));
    return Rgb(v[0], v[1], v[2]);
}

// Solves the node's column as the generator does (tools/rgb2spec): from zero at z index res / 5
// upwards, or at res / 5 - 1 downwards, each node from the previous one's solution, to k. Returns
// the last residual.
double solve_column_to(int slice, int k, int i, int j, SigmoidCoefficients& c) {
    const int start = srgb_to_spectrum_table().res / 5;
    c = SigmoidCoefficients();
    double residual = 0.0;
    for (int n = k >= start ? start : start - 1;; n += k >= start ? 1 : -1) {
        residual = fit().solve(node_colour(slice, n, i, j), c);
        if (n == k) return residual;
    }
}

TEST(RgbSigmoidFit, SolvesTableNodesToItsToleranceAndTheTableHoldsTheSolutions) {
    const int last = srgb_to_spectrum_table().res - 1;
    struct Node {
        int slice, k, i, j;
    };
    const Node nodes[] = {
        {0, last, 0, 0},              // red primary (1, 0, 0)
        {1, last, 0, 0},              // green primary
        {2, last, 0, 0},              // blue primary
        {1, last, last, 0},           // cyan (0, 1, 1)
        {2, 50, 30, 45},              // an inner colour
        {1, 8, 0, 0},                 // dark saturated green, z ~ 2e-3
        {1, last - 1, last - 2, 60},  // near white
    };
    for (const Node& n : nodes) {
        const Rgb rgb = node_colour(n.slice, n.k, n.i, n.j);
        SCOPED_TRACE(testing::Message() << "node colour (" << rgb.r << ", " << rgb.g << ", " << rgb.b << ")");
        SigmoidCoefficients c;
        const double residual = solve_column_to(n.slice, n.k, n.i, n.j, c);
        EXPECT_LT(residual, 1.01e-5);  // Delta E; the solver stops below 1e-5
        EXPECT_NEAR(length(fit().residual(c, rgb)), residual, 1e-12);
        const RgbSigmoid solved = sigmoid_in_nm(c);
        EXPECT_LT(test::largest_difference(reflectance_rgb(test::sampled(solved)), rgb), 3e-5);
        // The built table holds the same spectrum there (up to the rounding of its normalized
        // floats and of the lookup's position in the cell).
        const RgbSigmoid looked_up = rgb_to_sigmoid(rgb);
        for (int lambda = 360; lambda <= 830; ++lambda)
            ASSERT_NEAR(looked_up(float(lambda)), solved(float(lambda)), 2e-4) << lambda << " nm";
    }
}

}  // namespace
}  // namespace candela
