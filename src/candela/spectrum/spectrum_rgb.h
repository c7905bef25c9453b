#pragma once
// Spectra reduced to linear sRGB, for RGB mode: every colour a scene gives as a spectrum (named,
// pairs, a file, a blackbody) becomes the RGB value that renders it most nearly, so every scene
// renders in both modes (DESIGN: "Colour: RGB and spectral transport").
#include "candela/math/rgb.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {

// A reflectance (or any value a surface multiplies light by, eta and k included, which are
// unbounded) as the linear sRGB of what it reflects of illuminant D65: XYZ of s x D65, then
// sRGB, whose white is that D65. A constant c gives (c, c, c) up to float rounding.
Rgb reflectance_rgb(const DenseSpectrum& s);

// An emission spectrum as the linear sRGB colour of its light at luminance Y = 1 (pbrt-v4 scales
// every light's spectrum to luminance 1; the light's scale or power gives its brightness):
// stdillum-D65 gives (1, 1, 1). Black (0, 0, 0) if s has no luminance.
Rgb emission_rgb(const DenseSpectrum& s);

}  // namespace candela
