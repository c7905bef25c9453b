// How the `metal` shorthand's RGB eta and k (materials/metal_table.h, fitted by
// tools/metals/make_metal_table) relate to the named spectra: the table is not the RGB
// reduction of the eta and k spectra (reflectance_rgb of "metal-Au-eta" is a poorer stand-in,
// because Fresnel reflectance is far from linear in eta and k), but the per-channel (eta, k)
// whose Fresnel curve best matches the metal's spectral Fresnel reflectance reduced to RGB.
// Checked here from the named spectra, independently of the generator, against the
// errors tools/metals/README.md documents.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "candela/materials/fresnel.h"
#include "candela/materials/metal_table.h"
#include "candela/spectrum/named_spectra.h"
#include "candela/spectrum/spectrum_rgb.h"

namespace candela {
namespace CANDELA_UNITY_ID {

struct PbrtMetal {
    Metal metal;
    const char* symbol;
    // tools/metals/README.md: below 0.004, gold 0.0075 (its --check prints 7.50e-3; the float
    // Fresnel here rounds differently by ~1e-5, so gold is bounded by 0.0076).
    float documented_error;
};

// The metals whose spectra are pbrt-v4's named spectra (Cr, Fe and Ti come from Johnson and
// Christy, which pbrt-v4 does not name).
constexpr PbrtMetal kPbrtMetals[] = {{Metal::kAu, "Au", 0.0076f},
                                     {Metal::kAg, "Ag", 0.004f},
                                     {Metal::kCu, "Cu", 0.004f},
                                     {Metal::kAl, "Al", 0.004f},
                                     {Metal::kCuZn, "CuZn", 0.004f}};

TEST(MetalSpectra, TableFresnelMatchesTheNamedSpectraReducedToRgb) {
    for (const PbrtMetal& m : kPbrtMetals) {
        const DenseSpectrum& eta = *named_spectrum(std::string("metal-") + m.symbol + "-eta");
        const DenseSpectrum& k = *named_spectrum(std::string("metal-") + m.symbol + "-k");
        const MetalIor& ior = metal_ior(m.metal);
        float worst = 0.0f;
        // The generator's 64 cosines: midpoints of equal steps of (0, 1].
        for (int j = 0; j < 64; ++j) {
            const float mu = (float(j) + 0.5f) / 64.0f;
            DenseSpectrum f;
            for (int i = 0; i < kDenseSamples; ++i)
                f.v[size_t(i)] = fresnel_complex(mu, eta.v[size_t(i)], k.v[size_t(i)]);
            const Rgb target = reflectance_rgb(f);
            for (int c = 0; c < 3; ++c) {
                // Gold's red is beyond the sRGB gamut near normal incidence; the table fits it
                // clipped to 1.
                const float clipped = std::clamp(target[c], 0.0f, 1.0f);
                const float table = fresnel_complex(mu, ior.eta[c], ior.k[c]);
                worst = std::max(worst, std::abs(table - clipped));
            }
        }
        EXPECT_LT(worst, m.documented_error) << m.symbol;
    }
}

}  // namespace
}  // namespace candela
