// Dispersion (issue 14, point 4): a dielectric whose index is a spectrum refracts each
// wavelength by Snell's law with its own index, and a path that meets it keeps only its hero
// wavelength. The lobe is built as the path tracer builds it (build_bsdf at a TextureContext
// whose lambda holds the path's wavelengths) and checked against Snell's law with the index read
// independently from the named table; a 60-degree prism's deviation per wavelength against the
// closed form; PathVertex's termination of the secondary wavelengths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "candela/materials/material.h"
#include "candela/math/frame.h"
#include "candela/integrators/path_common.h"
#include "candela/spectrum/named_spectra.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr float kPi = std::numbers::pi_v<float>;

// The Fraunhofer lines h (Hg violet), F (H blue), d (He yellow) and C (H red), in nm.
constexpr float kLines[] = {404.7f, 486.1f, 587.6f, 656.3f};

// Wavelengths whose hero (channel 0) is `hero`; the secondaries are elsewhere, so a lobe that
// read them instead of the hero would refract differently.
Color wavelengths_with_hero(float hero) {
    Color lambda;
    lambda.set(0, hero);
    lambda.set(1, 700.0f);
    lambda.set(2, 450.0f);
    lambda.set(3, 550.0f);
    return lambda;
}

// SF11 (pbrt-v4's "glass-F11") as the scene loader makes it from {"spectrum": "glass-F11"}:
// `ior` its d-line value for RGB mode, ior_spectrum the table in the scene's TextureSet.
Material dispersive_glass(TextureSet& textures) {
    const DenseSpectrum* table = named_spectrum("glass-F11");
    DielectricParams p{(*table)(587.6f), ColorParam{Rgb(1.0f)}, false};
    p.ior_spectrum = textures.add_spectrum(*table);
    return make_material(p);
}

// The direction refracted by the material's BSDF at the hero wavelength, for light arriving
// along `d` (world) at a surface of unit normal `n` (the glass's outside is where n points).
Vec3f refract_through(const Material& m, const TextureSet& textures, float hero, Vec3f n, Vec3f d) {
    const Color lambda = wavelengths_with_hero(hero);
    const Bsdf bsdf = build_bsdf(m, textures, TextureContext{Vec2f(), Vec3f(), &lambda});
    const Frame frame = Frame::from_normal(n);
    // uc just below 1 is above any Fresnel reflectance met here: the lobe refracts.
    const std::optional<BsdfSample> s =
        bsdf.sample(frame.to_local(-d), 0.999999f, Vec2f(0.5f, 0.5f), TransportMode::kRadiance);
    EXPECT_TRUE(s && s->is_transmission);
    return s ? frame.to_world(s->wi) : Vec3f();
}

float angle_between(Vec3f a, Vec3f b) { return std::acos(std::clamp(dot(a, b), -1.0f, 1.0f)); }

TEST(Dispersion, MaterialFromSpectrumIsDispersive) {
    TextureSet textures;
    EXPECT_TRUE(dispersive_glass(textures).dispersive);
    EXPECT_FALSE(make_dielectric(1.5f).dispersive);
}

// The table is SCHOTT's SF11: its catalogue gives n_d = 1.78472 and Abbe number
// v_d = (n_d - 1) / (n_F - n_C) = 25.68 (tolerances cover the table's nearest-nm lookup).
TEST(Dispersion, TableIsSchottSf11) {
    const DenseSpectrum& n = *named_spectrum("glass-F11");
    EXPECT_NEAR(n(587.6f), 1.78472f, 2e-4f);
    EXPECT_NEAR((n(587.6f) - 1.0f) / (n(486.1f) - n(656.3f)), 25.68f, 0.4f);
    EXPECT_GT(n(404.7f), n(486.1f));
    EXPECT_GT(n(486.1f), n(587.6f));
    EXPECT_GT(n(587.6f), n(656.3f));
}

// Snell's law sin(theta_i) = n(lambda) sin(theta_t) at each line, entering and leaving the glass,
// with n(lambda) read from the named table at the hero wavelength.
TEST(Dispersion, RefractionObeysSnellAtTheHeroWavelength) {
    TextureSet textures;
    const Material glass = dispersive_glass(textures);
    const DenseSpectrum& n = *named_spectrum("glass-F11");
    const Vec3f normal(0.0f, 0.0f, 1.0f);
    for (float lambda : kLines) {
        for (float theta_i_deg : {10.0f, 35.0f, 60.0f, 80.0f}) {
            const float theta_i = theta_i_deg * kPi / 180.0f;
            // Entering: from outside (above) into the glass.
            const Vec3f d_in(std::sin(theta_i), 0.0f, -std::cos(theta_i));
            const Vec3f t_in = refract_through(glass, textures, lambda, normal, d_in);
            const float sin_t = std::sqrt(t_in.x * t_in.x + t_in.y * t_in.y);
            EXPECT_NEAR(sin_t, std::sin(theta_i) / n(lambda), 2e-6f) << lambda << " nm, " << theta_i_deg << " deg in";
            EXPECT_LT(t_in.z, 0.0f);
            EXPECT_GT(t_in.x, 0.0f);  // in the plane of incidence, on the far side of the normal
            // Leaving: from inside at the angle that comes out at theta_i (the path reversed).
            const Vec3f t_out = refract_through(glass, textures, lambda, normal, -t_in);
            EXPECT_NEAR(dot(t_out, -d_in), 1.0f, 1e-6f) << lambda << " nm, " << theta_i_deg << " deg out";
        }
    }
}

// A prism of apex angle A in the xy plane, apex up, light entering its left face at theta_1 from
// the normal. Closed form (Born & Wolf, 4.7): theta_2 = asin(sin theta_1 / n),
// theta_3 = A - theta_2, theta_4 = asin(n sin theta_3), deviation theta_1 + theta_4 - A.
float prism_deviation(float apex, float theta_1, float n) {
    const float theta_2 = std::asin(std::sin(theta_1) / n);
    const float theta_4 = std::asin(n * std::sin(apex - theta_2));
    return theta_1 + theta_4 - apex;
}

// SF11's index is high: at 60 degrees of apex, light entering below about 60 degrees of incidence
// is totally reflected inside at the second face, so the incidences tested are above that.
TEST(Dispersion, PrismDeviatesEachWavelengthAsSnellPredicts) {
    TextureSet textures;
    const Material glass = dispersive_glass(textures);
    const DenseSpectrum& n = *named_spectrum("glass-F11");
    const float apex = 60.0f * kPi / 180.0f;
    // Outward normals of the left and right faces.
    const Vec3f n_left(-std::cos(apex / 2), std::sin(apex / 2), 0.0f);
    const Vec3f n_right(std::cos(apex / 2), std::sin(apex / 2), 0.0f);
    float previous = 0.0f;
    for (float theta_1_deg : {65.0f, 72.0f, 80.0f}) {
        const float theta_1 = theta_1_deg * kPi / 180.0f;
        // -n_left turned by theta_1 towards the apex: the ray climbs to the face and bends to
        // the base.
        const float a = theta_1 - apex / 2;
        const Vec3f d(std::cos(a), std::sin(a), 0.0f);
        previous = 0.0f;
        // Red to violet: the deviation grows with the index.
        for (int i = 3; i >= 0; --i) {
            const float lambda = kLines[i];
            const Vec3f inside = refract_through(glass, textures, lambda, n_left, d);
            const Vec3f out = refract_through(glass, textures, lambda, n_right, inside);
            const float deviation = angle_between(d, out);
            const float expected = prism_deviation(apex, theta_1, n(lambda));
            EXPECT_NEAR(deviation, expected, 2e-4f) << lambda << " nm at " << theta_1_deg << " deg";
            EXPECT_GT(deviation, previous) << lambda << " nm is not deviated more than the line before it";
            EXPECT_LT(out.y, d.y);  // bent towards the base
            previous = deviation;
        }
    }
}

// Glass that does not disperse: its `ior` is used whatever the wavelengths.
TEST(Dispersion, ConstantIndexIgnoresTheWavelength) {
    TextureSet textures;
    const Material glass = make_dielectric(1.5f);
    const Vec3f normal(0.0f, 0.0f, 1.0f);
    const float theta_i = 0.6f;
    const Vec3f d(std::sin(theta_i), 0.0f, -std::cos(theta_i));
    for (float lambda : kLines) {
        const Vec3f t = refract_through(glass, textures, lambda, normal, d);
        EXPECT_NEAR(t.x, std::sin(theta_i) / 1.5f, 2e-6f);
    }
}

// PathVertex in spectral mode: a dispersive material keeps the hero only (secondary pdfs 0, the
// hero's divided by 4, once however many dispersive surfaces follow), plain glass keeps all four,
// and the BSDF refracts with the hero's index.
TEST(Dispersion, PathVertexTerminatesSecondaryWavelengthsOnlyAtDispersiveGlass) {
    Scene s;
    s.materials = {make_dielectric(1.5f)};
    s.materials.push_back(dispersive_glass(s.textures));
    s.material_names = {"plain", "dispersive"};
    test::add_quad(s, {-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 0);  // z = 0, plain
    test::add_quad(s, {-1, -1, 2}, {2, 0, 0}, {0, 2, 0}, 1);  // z = 2, dispersive
    Accelerator accel(s.meshes, s.spheres, s.disks, s.shapes);

    auto vertex_at = [&](float z, SampledWavelengths& w) {
        const Ray ray{Vec3f(0.1f, 0.2f, z - 1.0f), Vec3f(0.0f, 0.0f, 1.0f)};
        const std::optional<SurfaceHit> hit = accel.intersect(ray);
        EXPECT_TRUE(hit.has_value());
        const PathVertex v(s, accel, *hit, ray, w);
        return v.bsdf.lobes[0];
    };

    const SampledWavelengths start = SampledWavelengths::sample_visible(0.3f);
    SampledWavelengths w = start;
    const BsdfLobe plain = vertex_at(0.0f, w);
    for (int i = 0; i < kColorChannels; ++i) {
        EXPECT_EQ(w.pdf[i], start.pdf[i]);
        EXPECT_EQ(w.lambda[i], start.lambda[i]);
    }
    EXPECT_EQ(std::get<FresnelSpecularLobe>(plain).eta, 1.5f);

    const BsdfLobe dispersive = vertex_at(2.0f, w);
    EXPECT_EQ(w.pdf[0], start.pdf[0] / 4.0f);
    for (int i = 1; i < kColorChannels; ++i) EXPECT_EQ(w.pdf[i], 0.0f);
    EXPECT_EQ(w.lambda[0], start.lambda[0]);
    EXPECT_EQ(std::get<FresnelSpecularLobe>(dispersive).eta, (*named_spectrum("glass-F11"))(start.lambda[0]));

    // A second dispersive hit changes nothing more.
    vertex_at(2.0f, w);
    EXPECT_EQ(w.pdf[0], start.pdf[0] / 4.0f);
}

}  // namespace
}  // namespace candela
