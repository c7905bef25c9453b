#pragma once
// RGB values as spectra, as pbrt-v4 makes them (Jakob & Hanika 2019): a colour in [0, 1]^3 is
// looked up in a table of sigmoid polynomials over the sRGB gamut (rgb_to_spectrum_table.h,
// computed by tools/rgb2spec/), and one small value type covers pbrt-v4's three uses: albedo
// (RGBAlbedoSpectrum), unbounded (RGBUnboundedSpectrum: a scale times a bounded spectrum) and
// illuminant (RGBIlluminantSpectrum: that times the colour space's white, D65).
//
// The table is read only when an RgbSpectrum is made (once per constant at load time, once per
// texture lookup); evaluating one at a path's wavelengths is a polynomial, a square root and a
// division per wavelength (and one D65 load for an illuminant).
#include "candela/core/platform.h"
#include "candela/math/color.h"
#include "candela/math/rgb.h"
#include "candela/spectrum/dense_spectrum.h"
#include "candela/spectrum/rgb_sigmoid.h"

namespace candela {

// The sigmoid whose reflectance under D65 has the sRGB colour c in [0, 1]^3, from the sRGB table
// (rgb_to_spectrum_table.h); a grey is exactly constant.
CANDELA_HD RgbSigmoid rgb_to_sigmoid(const Rgb& c);

// A spectrum made from an RGB value: scale times a sigmoid polynomial, times D65 for an
// illuminant.
struct RgbSpectrum {
    RgbSigmoid s;
    float scale = 1;
    bool illuminant = false;

    CANDELA_HD float operator()(float lambda_nm) const {
        const float v = scale * s(lambda_nm);
        return illuminant ? v * d65_illuminant()(lambda_nm) : v;
    }
    // The values at a path's four wavelengths.
    CANDELA_HD Color eval(const Color& lambda) const {
        Color v = s.eval(lambda) * scale;
        if (illuminant) v *= d65_illuminant().eval(lambda);
        return v;
    }
    // The largest value over 360-830 nm (pbrt-v4's MaxValue: for an illuminant, a bound, the
    // product of the two factors' maxima).
    CANDELA_HD float max_value() const {
        const float m = scale * s.max_value();
        return illuminant ? m * d65_illuminant().max_value() : m;
    }
};

// A reflectance (pbrt-v4's RGBAlbedoSpectrum): rgb clamped to [0, 1], values in [0, 1]. A grey v
// is the constant v exactly (scale 2v times s = 1/2, since s of (v - 1/2) / sqrt(v (1 - v)) in
// float may miss v by an ulp).
CANDELA_HD RgbSpectrum rgb_albedo_spectrum(const Rgb& rgb);
// Any non-negative colour, values above 1 too (pbrt-v4's RGBUnboundedSpectrum: eta, k, scaled
// albedos): m = the largest channel, scale 2m, the sigmoid of rgb / 2m, so that the table is
// read where its largest channel is 1/2, at the spectra furthest from its saturated corners.
CANDELA_HD RgbSpectrum rgb_unbounded_spectrum(const Rgb& rgb);
// An emitter's colour (pbrt-v4's RGBIlluminantSpectrum): the unbounded spectrum times D65
// (luminance 1), so that its XYZ is rgb's in sRGB, whose white is D65: RGB (1, 1, 1) is D65.
CANDELA_HD RgbSpectrum rgb_illuminant_spectrum(const Rgb& rgb);

}  // namespace candela
