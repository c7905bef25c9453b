// Chi-square test of TrowbridgeReitz::sample_wm against its density, the visible-normal
// distribution D_w (tests/support/chi2.h), over the upper hemisphere of normals parametrised
// around the pole (materials/axis_domain.h), so that a narrow distribution spans many cells.
#include <gtest/gtest.h>

#include "candela/materials/trowbridge_reitz.h"
#include "materials/axis_domain.h"
#include "materials/lobe_cases.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

// The chi-square tests in this file, for the Sidak correction.
constexpr int kChi2Tests = 8;

void expect_visible_normals_fit(const TrowbridgeReitz& tr, Vec3f w) {
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    AxisDomain hemisphere(Vec3f(0, 0, 1), kPiD / 2.0);
    auto sampler = [&](Sampler& rng) { return tr.sample_wm(w, rng.next_vec2f()); };
    auto pdf = [&](Vec3f wm) { return tr.pdf(w, wm); };
    Chi2Result r = chi2_test(hemisphere, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(TrowbridgeReitzChi2, NormalIncidence) {
    expect_visible_normals_fit(TrowbridgeReitz(0.1f), direction(1.0f, 0.0f));
}
TEST(TrowbridgeReitzChi2, Oblique) {
    expect_visible_normals_fit(TrowbridgeReitz(0.3f), direction(0.5f, 1.0f));
}
TEST(TrowbridgeReitzChi2, Grazing) {
    expect_visible_normals_fit(TrowbridgeReitz(0.3f), direction(0.05f, 2.0f));
}
TEST(TrowbridgeReitzChi2, BelowTheSurface) {
    expect_visible_normals_fit(TrowbridgeReitz(0.5f), direction(-0.7f, -1.0f));
}
TEST(TrowbridgeReitzChi2, NearlySmooth) {
    expect_visible_normals_fit(TrowbridgeReitz(0.01f), direction(0.6f, 0.3f));
}
TEST(TrowbridgeReitzChi2, VeryRough) {
    expect_visible_normals_fit(TrowbridgeReitz(1.0f), direction(0.3f, 0.5f));
}
TEST(TrowbridgeReitzChi2, Anisotropic) {
    expect_visible_normals_fit(TrowbridgeReitz(0.05f, 0.4f), direction(0.5f, 1.0f));
}
TEST(TrowbridgeReitzChi2, AnisotropicGrazingBelow) {
    expect_visible_normals_fit(TrowbridgeReitz(0.4f, 0.1f), direction(-0.1f, 0.4f));
}

}  // namespace
}  // namespace candela::test
