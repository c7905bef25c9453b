#pragma once
// A material parameter that may be a texture: a constant value, or the index of a texture in the
// scene's TextureSet (textures/texture_set.h) that gives the value at each shading point.
//
// A texture's values are not known when the scene loads (an image may hold anything), so a
// textured parameter carries its range and the texture's value is clamped into it where it is
// looked up (pbrt-v4 clamps an albedo texture's RGB to [0, 1] the same way). A constant is checked
// against the range when it is read and returned as it is.
#include <cstdint>
#include <limits>

#include "candela/math/color.h"
#include "candela/spectrum/rgb_to_spectrum.h"

namespace candela {

inline constexpr uint32_t kNoTexture = 0xffffffffu;
inline constexpr uint32_t kNoSpectrum = 0xffffffffu;

// How an RGB colour parameter becomes a spectrum in spectral mode (pbrt-v4's SpectrumType):
// a reflectance-like value in [0, 1] by the albedo form, anything that may exceed 1 (eta, k) by
// the unbounded form (spectrum/rgb_to_spectrum.h).
enum class SpectrumForm : uint8_t { kAlbedo, kUnbounded };
inline constexpr float kUnbounded = std::numeric_limits<float>::infinity();

struct FloatParam {
    float value = 0.0f;             // the value where `texture` is kNoTexture
    uint32_t texture = kNoTexture;  // index into TextureSet
    float lo = -kUnbounded;         // a texture's value is clamped to [lo, hi]
    float hi = kUnbounded;

    CANDELA_HD bool is_textured() const { return texture != kNoTexture; }
};

struct ColorParam {
    Rgb value;  // the constant, in linear RGB (both modes' textures work in RGB)
    uint32_t texture = kNoTexture;
    float lo = -kUnbounded;  // each channel of a texture's value is clamped to [lo, hi]
    float hi = kUnbounded;
    // Spectral mode. A tabulated spectrum (an index into the TextureSet's spectra) replaces
    // `value` when given (value is then its RGB reduction, for RGB mode); otherwise a constant
    // is `value`'s uplift in `form`, made once by prepare_spectral, and a texture's RGB is
    // uplifted in `form` where it is looked up.
    SpectrumForm form = SpectrumForm::kAlbedo;
    uint32_t spectrum = kNoSpectrum;
    RgbSpectrum spectral{};

    CANDELA_HD bool is_textured() const { return texture != kNoTexture; }
};

// The uplift of an RGB constant in its form.
inline RgbSpectrum uplift(const Rgb& c, SpectrumForm form) {
    return form == SpectrumForm::kAlbedo ? rgb_albedo_spectrum(c) : rgb_unbounded_spectrum(c);
}
// Makes p's spectral-mode constant from its RGB value (make_material calls it for every colour
// parameter, so the path tracer never uplifts a constant).
inline void prepare_spectral(ColorParam& p) {
    if (!p.is_textured() && p.spectrum == kNoSpectrum) p.spectral = uplift(p.value, p.form);
}

}  // namespace candela
