#pragma once
// A table of sigmoid polynomials over the RGB cube [0, 1]^3 (Jakob & Hanika 2019, sec. 4), in
// pbrt-v4's layout (RGBToSpectrumTable): for each of the three choices of largest channel (the
// slice), res values z of that channel and res x res values x, y of the next two channels divided
// by it (x = rgb[(slice + 1) % 3] / z, y = rgb[(slice + 2) % 3] / z), all three on pbrt-v4's
// z nodes smoothstep(smoothstep(k / (res - 1))), dense near 0 and 1. A colour's coefficients are
// trilinear between the eight nodes around it.
//
// Two things differ from pbrt-v4, because the round trip (rgb -> spectrum -> sRGB under D65) must
// hold to 1e-3 over the whole gamut and pbrt-v4's scheme misses that by up to 1.5e-2 near white
// at its res 64 (tools/rgb2spec/make_rgb_to_spectrum_table.cpp has the measurements):
// - x and y use the same nodes as z (pbrt-v4 spaces them uniformly). Near a face of the cube (a
//   channel near 0) and near white the coefficients change within a few thousandths.
// - Nodes hold the coefficients times sqrt(w (1 - w)), w the mean of the node's rgb, and a lookup
//   divides by that factor of its own rgb. Towards black and white the coefficients grow as
//   1 / sqrt(distance) (the sigmoid's tails are 1 / (4 x^2)), so trilinear interpolation of them
//   is poor there; the product stays bounded and smooth. Grey v is then (0, 0, v - 1/2) exactly.
// The sRGB table (res 72; pbrt-v4 uses 64) is rgb_to_spectrum_table_data.cpp, written into the
// build tree by tools/rgb2spec/make_rgb_to_spectrum_table.
#include <cstring>

#include "candela/core/platform.h"
#include "candela/math/rgb.h"
#include "candela/spectrum/rgb_sigmoid.h"

namespace candela {

struct RgbToSpectrumTable {
    int res = 0;
    const float* nodes = nullptr;  // res increasing values from 0 to 1, on every axis
    // 3 res^3 triples (c0, c1, c2) of float in host byte order, as bytes so that the data file
    // can hold them as one string literal (which compiles in a second, where millions of float
    // literals take GCC many seconds and a GB): node (slice, k, j, i), at z = nodes[k],
    // y = nodes[j], x = nodes[i], is triple ((slice * res + k) * res + j) * res + i.
    const unsigned char* coefficient_bytes = nullptr;

    // The sigmoid of rgb in [0, 1]^3 (pbrt-v4's RGBToSpectrumTable::operator()). A grey
    // r = g = b = v is the constant v: c0 = c1 = 0, c2 = (v - 1/2) / sqrt(v (1 - v)), for which
    // s(c2) = v, infinite for v = 0 or 1 where s is exactly 0 or 1.
    CANDELA_HD RgbSigmoid operator()(const Rgb& rgb) const;

    CANDELA_HD float coefficient(int node, int i) const {
        float c;
        std::memcpy(&c, coefficient_bytes + (3 * size_t(node) + size_t(i)) * sizeof(float), sizeof(float));
        return c;
    }
};

// The factor the nodes' coefficients are stored times: sqrt(w (1 - w)), w = mean of rgb; 1 - w
// from 1 - r, 1 - g and 1 - b, so that it is not 0 for a colour just below white.
CANDELA_HD inline float rgb_table_normalization(const Rgb& rgb) {
    const float w = (rgb.r + rgb.g + rgb.b) / 3.0f;
    const float w1 = ((1.0f - rgb.r) + (1.0f - rgb.g) + (1.0f - rgb.b)) / 3.0f;
    return std::sqrt(w * w1);
}

// The sRGB table (CIE 1931, D65), built with candela.
CANDELA_HD const RgbToSpectrumTable& srgb_to_spectrum_table();

}  // namespace candela
