#include "candela/spectrum/rgb_to_spectrum_table.h"

#include <cmath>
#include <limits>

namespace candela {

namespace {

CANDELA_HD float lerp(float t, float a, float b) { return (1.0f - t) * a + t * b; }

// The cell [nodes[i], nodes[i + 1]] that holds v, i in [0, n - 2]: the last node below v, by
// bisection (pbrt-v4's FindInterval).
CANDELA_HD int cell_of(const float* nodes, int n, float v) {
    int lo = 0, hi = n - 2;
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (nodes[mid] < v)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

// The constant v in [0, 1]: s(c2) = v for c2 = (v - 1/2) / sqrt(v (1 - v)), since then
// 1 + c2^2 = 1 / (4 v (1 - v)).
CANDELA_HD RgbSigmoid constant_sigmoid(float v) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    if (v <= 0.0f) return RgbSigmoid{0.0f, 0.0f, -kInf};
    if (v >= 1.0f) return RgbSigmoid{0.0f, 0.0f, kInf};
    return RgbSigmoid{0.0f, 0.0f, (v - 0.5f) / std::sqrt(v * (1.0f - v))};
}

}  // namespace

CANDELA_HD RgbSigmoid RgbToSpectrumTable::operator()(const Rgb& rgb) const {
    if (rgb.r == rgb.g && rgb.g == rgb.b) return constant_sigmoid(rgb.r);

    // The slice of the largest channel (z > 0, since the channels differ), the other two
    // channels relative to it, and the cell and position in it along each axis.
    const int slice = rgb.r > rgb.g ? (rgb.r > rgb.b ? 0 : 2) : (rgb.g > rgb.b ? 1 : 2);
    const float p[3] = {rgb[(slice + 1) % 3] / rgb[slice], rgb[(slice + 2) % 3] / rgb[slice], rgb[slice]};
    int cell[3];
    float t[3];
    for (int a = 0; a < 3; ++a) {
        cell[a] = cell_of(nodes, res, p[a]);
        t[a] = (p[a] - nodes[cell[a]]) / (nodes[cell[a] + 1] - nodes[cell[a]]);
    }

    const int base = ((slice * res + cell[2]) * res + cell[1]) * res + cell[0];
    const int dx = 1, dy = res, dz = res * res;
    const float n = rgb_table_normalization(rgb);
    float c[3];
    for (int i = 0; i < 3; ++i) {
        auto at = [&](int offset) { return coefficient(base + offset, i); };
        const float near_z = lerp(t[1], lerp(t[0], at(0), at(dx)), lerp(t[0], at(dy), at(dy + dx)));
        const float far_z = lerp(t[1], lerp(t[0], at(dz), at(dz + dx)), lerp(t[0], at(dz + dy), at(dz + dy + dx)));
        c[i] = lerp(t[2], near_z, far_z) / n;
    }
    return RgbSigmoid{c[0], c[1], c[2]};
}

}  // namespace candela
