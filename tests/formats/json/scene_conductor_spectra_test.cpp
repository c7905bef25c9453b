// A conductor whose eta and k are named spectra (pbrt-v4's measured metals), and the `metal`
// shorthand in spectral mode: built at a path's wavelengths, the smooth conductor reflects per
// wavelength the Fresnel reflectance of the complex index n + i k at that wavelength. The
// reference is computed here in double from the closed form of the exact unpolarized Fresnel
// equations for an absorbing medium (Born & Wolf, Principles of Optics, 7th ed., sec. 14.4.1, in
// the a^2 + b^2 form of Heavens), independently of materials/fresnel.h's complex arithmetic.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <complex>
#include <string>
#include <variant>

#include "candela/materials/conductor.h"
#include "candela/materials/material.h"
#include "candela/spectrum/named_spectra.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_material;

// R = (Rs + Rp) / 2 for light from vacuum onto a medium of index n + i k at cos theta = mu.
double fresnel_reference(double mu, double n, double k) {
    const double sin2 = 1.0 - mu * mu;
    const double t0 = n * n - k * k - sin2;
    const double a2_plus_b2 = std::sqrt(t0 * t0 + 4.0 * n * n * k * k);
    const double a = std::sqrt(0.5 * (a2_plus_b2 + t0));
    const double rs = (a2_plus_b2 - 2.0 * a * mu + mu * mu) / (a2_plus_b2 + 2.0 * a * mu + mu * mu);
    const double p_num = mu * mu * a2_plus_b2 - 2.0 * a * mu * sin2 + sin2 * sin2;
    const double p_den = mu * mu * a2_plus_b2 + 2.0 * a * mu * sin2 + sin2 * sin2;
    return 0.5 * (rs + rs * p_num / p_den);
}

// How much the float evaluation's rounding can be amplified: the Fresnel amplitudes are ratios
// whose numerators (n cos_i - cos_t and cos_i - n cos_t) cancel; the relative error of a
// difference is that of its terms times (|x| + |y|) / |x - y|.
double cancellation(double mu, double n, double k) {
    const std::complex<double> eta(n, k);
    const std::complex<double> cos_t = std::sqrt(1.0 - (1.0 - mu * mu) / (eta * eta));
    const double parallel = (std::abs(eta * mu) + std::abs(cos_t)) / std::abs(eta * mu - cos_t);
    const double perpendicular = (mu + std::abs(eta * cos_t)) / std::abs(mu - eta * cos_t);
    return std::max(parallel, perpendicular);
}

// The bound on |float - double|: the lobe's path from (eta, k) to F is about 40 float operations
// (complex products, quotients and a square root), each rounding by at most FLT_EPSILON / 2
// relative; 64 epsilons covers their sum with room for the growth of complex division's error,
// times the cancellation above. F <= 1, so relative and absolute agree up to that factor.
double float_bound(double mu, double n, double k) { return 64.0 * double(FLT_EPSILON) * cancellation(mu, n, k); }

// F of the smooth conductor lobe that `material` builds at the wavelengths `lambda`, seen at
// cos theta = mu: the delta sample's weight f |cos wi| / pdf.
Color lobe_fresnel(const Material& material, const TextureSet& textures, const Color& lambda, float mu) {
    TextureContext ctx;
    ctx.lambda = &lambda;
    const Bsdf bsdf = build_bsdf(material, textures, ctx);
    EXPECT_EQ(bsdf.lobe_count, 1u);
    const auto* lobe = std::get_if<ConductorLobe>(&bsdf.lobes[0]);
    EXPECT_NE(lobe, nullptr);
    if (lobe == nullptr) return Color(0.0f);
    EXPECT_TRUE(lobe->is_delta());
    const Vec3f wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
    const std::optional<BsdfSample> s = lobe->sample(wo, 0.5f, Vec2f(0.5f, 0.5f), TransportMode::kRadiance);
    EXPECT_TRUE(s.has_value());
    if (!s) return Color(0.0f);
    return s->f * (std::abs(s->wi.z) / s->pdf);
}

// Every wavelength 360-830 nm in steps of 5 (and some between the table's nm), four at a time,
// as a path carries them, at normal, oblique and near-grazing incidence.
void expect_matches_named_spectra(const Scene& scene, const std::string& metal) {
    const DenseSpectrum& eta = *named_spectrum("metal-" + metal + "-eta");
    const DenseSpectrum& k = *named_spectrum("metal-" + metal + "-k");
    const Material& material = scene.materials.at(0);
    double worst_ratio = 0.0;
    for (float mu : {1.0f, 0.8f, 0.5f, 0.2f, 0.05f}) {
        for (int start = 360; start <= 830; start += 20) {
            Color lambda;
            for (int i = 0; i < 4; ++i) lambda.set(i, std::min(830.0f, float(start) + 5.0f * float(i) + 0.3f));
            const Color f = lobe_fresnel(material, scene.textures, lambda, mu);
            for (int i = 0; i < 4; ++i) {
                const double n = double(eta(lambda[i])), kk = double(k(lambda[i]));
                const double expected = fresnel_reference(double(mu), n, kk);
                const double bound = float_bound(double(mu), n, kk);
                EXPECT_NEAR(double(f[i]), expected, bound)
                    << metal << " at " << lambda[i] << " nm, cos " << mu << ": n = " << n << ", k = " << kk;
                worst_ratio = std::max(worst_ratio, std::abs(double(f[i]) - expected) / bound);
            }
        }
    }
    testing::Test::RecordProperty(metal + "_worst_error_over_bound", std::to_string(worst_ratio));
}

TEST(SceneConductorSpectra, NamedEtaAndKGiveTheExactFresnelPerWavelength) {
    for (const char* metal : {"Au", "Ag", "Al", "Cu", "CuZn", "MgO", "TiO2"}) {
        const std::string m = metal;
        const Scene s = load_material(R"({"type": "conductor", "eta": {"spectrum": "metal-)" + m +
                                      R"(-eta"}, "k": {"spectrum": "metal-)" + m + R"(-k"}})");
        expect_matches_named_spectra(s, m);
    }
}

// The reference itself, at points known in closed form: normal incidence gives
// ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2), and a lossless index 1.5 at 45 degrees gives
// 0.0505429... (Rs = 0.0920, Rp = 0.0085, from the real Fresnel equations).
TEST(SceneConductorSpectra, ReferenceAgreesWithClosedForms) {
    EXPECT_NEAR(fresnel_reference(1.0, 0.2, 3.0), (0.64 + 9.0) / (1.44 + 9.0), 1e-15);
    const double mu = std::sqrt(0.5), cos_t = std::sqrt(1.0 - 0.5 / 2.25);
    const double rs = std::pow((mu - 1.5 * cos_t) / (mu + 1.5 * cos_t), 2);
    const double rp = std::pow((1.5 * mu - cos_t) / (1.5 * mu + cos_t), 2);
    EXPECT_NEAR(fresnel_reference(mu, 1.5, 0.0), 0.5 * (rs + rp), 1e-15);
}

// `metal` names a measured metal: in spectral mode its spectra where pbrt-v4 has them, so it
// reflects as the conductor of those named spectra; in RGB mode the RGB table (scene_metals_test).
TEST(SceneConductorSpectra, MetalShorthandUsesTheNamedSpectra) {
    for (const char* metal : {"Au", "Ag", "Al", "Cu", "CuZn"}) {
        const Scene s = load_material(std::string(R"({"type": "conductor", "metal": ")") + metal + "\"}");
        expect_matches_named_spectra(s, metal);
    }
}

// Without pbrt-v4 spectra (Cr, Fe, Ti) spectral mode uplifts the RGB table's eta and k as the
// unbounded quantities they are.
TEST(SceneConductorSpectra, MetalWithoutSpectraUpliftsItsRgbIndex) {
    const Scene s = load_material(R"({"type": "conductor", "metal": "Fe"})");
    const auto* p = std::get_if<ConductorParams>(&s.materials.at(0).params[0]);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->eta.spectrum, kNoSpectrum);
    EXPECT_EQ(p->eta.form, SpectrumForm::kUnbounded);
    EXPECT_EQ(p->k.form, SpectrumForm::kUnbounded);
}

}  // namespace
}  // namespace candela
