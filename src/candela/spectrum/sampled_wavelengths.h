#pragma once
// The four wavelengths a spectral path carries (hero-wavelength sampling, Wilkie et al. 2014, as
// pbrt-v4's SampledWavelengths): one number u gives the hero wavelength from a density that
// follows the eye's sensitivity, and the other three are u shifted by 1/4, 2/4, 3/4 (mod 1), so
// the four cover the visible range evenly. A path's Color holds its values at these wavelengths.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/color.h"

namespace candela {

// The visible range the sensor integrates over, in nm (pbrt-v4's Lambda_min, Lambda_max).
inline constexpr float kLambdaMin = 360.0f;
inline constexpr float kLambdaMax = 830.0f;

// pbrt-v4's visible-wavelength density: p(lambda) = A / cosh^2(B (lambda - 538)) on
// [360, 830], a fit to the sum of the CIE matching functions that is invertible in closed form.
CANDELA_HD inline float visible_wavelength_pdf(float lambda) {
    if (lambda < kLambdaMin || lambda > kLambdaMax) return 0.0f;
    const float c = std::cosh(0.0072f * (lambda - 538.0f));
    return 0.0039398042f / (c * c);
}
// The wavelength at u in [0, 1) by inverting that density's CDF.
// atanh(t) = log((1 + t) / (1 - t)) / 2: one logf (atanhf is slower; see sample_visible).
CANDELA_HD inline float sample_visible_wavelength(float u) {
    const float t = 0.85691062f - 1.82750197f * u;
    return 538.0f - 138.888889f * 0.5f * std::log((1.0f + t) / (1.0f - t));
}

struct SampledWavelengths {
    Color lambda;  // nm
    Color pdf;     // per nm; 0 for a terminated secondary wavelength

    // Four wavelengths from u in [0, 1): the hero at u, the others at u + i/4 mod 1. Each is
    // sample_visible_wavelength's inversion, written as lambda = 538 - c atanh(t) with
    // t = a - b u, and atanh(t) = log((1 + t) / (1 - t)) / 2: one logf per wavelength, where
    // atanhf and coshf cost 9% of a spectral Cornell box render. Its density is exactly
    // |du / dlambda| = (1 - t^2) / (b c), which is visible_wavelength_pdf(lambda) (A = 1 / (b c),
    // B c = 1 to 1e-9) without the cosh.
    CANDELA_HD static SampledWavelengths sample_visible(float u) {
        constexpr float kA = 0.85691062f, kB = 1.82750197f, kC = 138.888889f;
        SampledWavelengths w;
        for (int i = 0; i < kColorChannels; ++i) {
            float up = u + float(i) / float(kColorChannels);
            if (up > 1.0f) up -= 1.0f;
            const float t = kA - kB * up;
            w.lambda.set(i, sample_visible_wavelength(up));
            w.pdf.set(i, (1.0f - t * t) * (1.0f / (kB * kC)));
        }
        return w;
    }

    // Keeps only the hero wavelength (after a refraction that depends on the wavelength, the
    // others would need directions of their own): their pdfs become 0, and the hero's pdf is
    // divided by 4 because it now stands for all four samples (pbrt-v4's TerminateSecondary).
    CANDELA_HD void terminate_secondary() {
        if (secondary_terminated()) return;
        for (int i = 1; i < kColorChannels; ++i) pdf.set(i, 0.0f);
        pdf.set(0, pdf[0] / float(kColorChannels));
    }
    CANDELA_HD bool secondary_terminated() const {
        for (int i = 1; i < kColorChannels; ++i)
            if (pdf[i] != 0.0f) return false;
        return true;
    }
};

}  // namespace candela
