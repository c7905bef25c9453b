// A dielectric's `ior` as a spectrum (issue 14, dispersion): every spectrum form is accepted, a
// varying one makes the material dispersive with the table in the scene's TextureSet and its
// d-line (587.6 nm) value as the RGB-mode index, a number is a plain index, and a
// non-positive index anywhere is a located error.
#include <gtest/gtest.h>

#include <string>

#include "candela/spectrum/named_spectra.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_material;
using test::material_error;

template <class P>
const P& only_params(const Scene& s) {
    const P* p = std::get_if<P>(&s.materials.at(0).params[0]);
    EXPECT_NE(p, nullptr);
    static const P none{};
    return p != nullptr ? *p : none;
}

TEST(SceneDispersiveIor, ANamedGlassIsDispersive) {
    const Scene s = load_material(R"({"type": "dielectric", "ior": {"spectrum": "glass-F11"}})");
    const DenseSpectrum& table = *named_spectrum("glass-F11");
    EXPECT_TRUE(s.materials[0].dispersive);
    const DielectricParams& p = only_params<DielectricParams>(s);
    EXPECT_EQ(p.ior, table(587.6f));
    ASSERT_NE(p.ior_spectrum, kNoSpectrum);
    for (float lambda : {380.0f, 404.7f, 486.1f, 656.3f, 800.0f})
        EXPECT_EQ(s.textures.spectrum(p.ior_spectrum)(lambda), table(lambda)) << lambda;
    // RGB mode's lobe (built at load) uses the d-line index.
    EXPECT_EQ(test::only_lobe<FresnelSpecularLobe>(s).eta, table(587.6f));
}

TEST(SceneDispersiveIor, PairsAreDispersiveAndANumberIsNot) {
    const Scene s = load_material(R"({"type": "dielectric", "ior": {"spectrum": [400, 1.6, 700, 1.5]}})");
    EXPECT_TRUE(s.materials[0].dispersive);
    const DielectricParams& p = only_params<DielectricParams>(s);
    EXPECT_NEAR(p.ior, 1.6f - 0.1f * (588.0f - 400.0f) / 300.0f, 1e-5f);  // nearest nm of 587.6
    EXPECT_NEAR(s.textures.spectrum(p.ior_spectrum)(550.0f), 1.55f, 1e-5f);

    EXPECT_FALSE(load_material(R"({"type": "dielectric", "ior": 1.5})").materials[0].dispersive);
}

// Every glass-like type takes the spectrum, and so does a spectrum file.
TEST(SceneDispersiveIor, EveryDielectricTypeTakesASpectrum) {
    EXPECT_NE(only_params<TransmissionParams>(
                  load_material(R"({"type": "transmission", "ior": {"spectrum": "glass-BK7"}})"))
                  .ior_spectrum,
              kNoSpectrum);
    EXPECT_NE(only_params<ThinDielectricParams>(
                  load_material(R"({"type": "thin_dielectric", "ior": {"spectrum": "glass-BK7"}})"))
                  .ior_spectrum,
              kNoSpectrum);
    const Scene rough =
        load_material(R"({"type": "dielectric", "roughness": 0.2, "ior": {"spectrum": "glass-BAF10"}})");
    EXPECT_TRUE(rough.materials[0].dispersive);
    EXPECT_NEAR(only_params<RoughDielectricParams>(rough).ior, (*named_spectrum("glass-BAF10"))(587.6f), 0.0f);
}

TEST(SceneDispersiveIor, NonPositiveIndicesAreLocatedErrors) {
    struct Case {
        const char* material;
        const char* pointer;
        const char* message;
    };
    const Case cases[] = {
        {R"({"type": "dielectric", "ior": {"spectrum": [400, 0, 700, 1.5]}})", "/materials/m/ior",
         "an index of refraction must be > 0 at every wavelength, got 0"},
        {R"({"type": "transmission", "ior": {"spectrum": [400, 1.5, 700, -1.5]}})", "/materials/m/ior",
         "an index of refraction must be > 0 at every wavelength, got 0"},
        {R"({"type": "dielectric", "ior": 0})", "/materials/m/ior", "expected a number > 0, got 0"},
        {R"({"type": "thin_dielectric", "ior": -1.5})", "/materials/m/ior", "expected a number > 0, got -1.5"},
        {R"({"type": "dielectric", "ior": {"spectrum": "glass-XX"}})", "/materials/m/ior/spectrum",
         R"(unknown spectrum "glass-XX")"},
    };
    for (const Case& c : cases) {
        const SceneError e = material_error(c.material);
        EXPECT_EQ(e.where().json_pointer, c.pointer) << c.material;
        EXPECT_NE(e.message().find(c.message), std::string::npos) << c.material << "\n  " << e.message();
        EXPECT_EQ(e.where().line, 1) << c.material;
    }
}

}  // namespace
}  // namespace candela
