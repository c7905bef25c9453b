#pragma once
// Ken Perlin's gradient noise as pbrt-v4 computes it (src/pbrt/util/noise.cpp: Noise, DNoise), so
// that what pbrt-v4 builds from it (the cloud medium, media/cloud_medium.h) is the same function
// here: the same permutation table, gradient choice (Perlin 2002, "Improving noise"), quintic
// fade 6t^5 - 15t^4 + 10t^3 and interpolation order, float arithmetic step for step.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

// Perlin's permutation of 0..255, the table of his reference implementation, as pbrt-v4's
// NoisePerm holds it (src/pbrt/util/noise.cpp, which stores it twice over 512 entries; indexing
// this one modulo 256 reads the same values).
inline constexpr int kPerlinPermutation[256] = {
    151, 160, 137,  91,  90,  15, 131,  13, 201,  95,  96,  53, 194, 233,   7, 225,
    140,  36, 103,  30,  69, 142,   8,  99,  37, 240,  21,  10,  23, 190,   6, 148,
    247, 120, 234,  75,   0,  26, 197,  62,  94, 252, 219, 203, 117,  35,  11,  32,
     57, 177,  33,  88, 237, 149,  56,  87, 174,  20, 125, 136, 171, 168,  68, 175,
     74, 165,  71, 134, 139,  48,  27, 166,  77, 146, 158, 231,  83, 111, 229, 122,
     60, 211, 133, 230, 220, 105,  92,  41,  55,  46, 245,  40, 244, 102, 143,  54,
     65,  25,  63, 161,   1, 216,  80,  73, 209,  76, 132, 187, 208,  89,  18, 169,
    200, 196, 135, 130, 116, 188, 159,  86, 164, 100, 109, 198, 173, 186,   3,  64,
     52, 217, 226, 250, 124, 123,   5, 202,  38, 147, 118, 126, 255,  82,  85, 212,
    207, 206,  59, 227,  47,  16,  58,  17, 182, 189,  28,  42, 223, 183, 170, 213,
    119, 248, 152,   2,  44, 154, 163,  70, 221, 153, 101, 155, 167,  43, 172,   9,
    129,  22,  39, 253,  19,  98, 108, 110,  79, 113, 224, 232, 178, 185, 112, 104,
    218, 246,  97, 228, 251,  34, 242, 193, 238, 210, 144,  12, 191, 179, 162, 241,
     81,  51, 145, 235, 249,  14, 239, 107,  49, 192, 214,  31, 181, 199, 106, 157,
    184,  84, 204, 176, 115, 121,  50,  45, 127,   4, 150, 254, 138, 236, 205,  93,
    222, 114,  67,  29,  24,  72, 243, 141, 128, 195,  78,  66, 215,  61, 156, 180,
};

namespace perlin_detail {

CANDELA_HD inline int perm(int i) { return kPerlinPermutation[i & 255]; }

// The gradient of lattice point (x, y, z) dotted with the offset (dx, dy, dz): one of Perlin's 12
// edge directions (16 with 4 repeated), picked by the hashed lattice point.
CANDELA_HD inline float grad(int x, int y, int z, float dx, float dy, float dz) {
    const int h = perm(perm(perm(x) + y) + z) & 15;
    const float u = h < 8 || h == 12 || h == 13 ? dx : dy;
    const float v = h < 4 || h == 12 || h == 13 ? dy : dz;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

// 6t^5 - 15t^4 + 10t^3, its powers grouped as pbrt-v4's Pow<n> groups them.
CANDELA_HD inline float fade(float t) {
    const float t2 = t * t;
    const float t4 = t2 * t2;
    return 6 * (t4 * t) - 15 * t4 + 10 * (t2 * t);
}

}  // namespace perlin_detail

// Gradient noise at p: 0 at every integer lattice point, values in about [-1, 1], period 256 in
// each axis.
CANDELA_HD inline float perlin_noise(const Vec3f& p) {
    using namespace perlin_detail;
    // fmod keeps huge coordinates within int range (pbrt-v4 does the same).
    const float x = std::fmod(p.x, float(1 << 30));
    const float y = std::fmod(p.y, float(1 << 30));
    const float z = std::fmod(p.z, float(1 << 30));
    int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
    const float dx = x - float(ix), dy = y - float(iy), dz = z - float(iz);
    ix &= 255;
    iy &= 255;
    iz &= 255;
    const float w000 = grad(ix, iy, iz, dx, dy, dz);
    const float w100 = grad(ix + 1, iy, iz, dx - 1, dy, dz);
    const float w010 = grad(ix, iy + 1, iz, dx, dy - 1, dz);
    const float w110 = grad(ix + 1, iy + 1, iz, dx - 1, dy - 1, dz);
    const float w001 = grad(ix, iy, iz + 1, dx, dy, dz - 1);
    const float w101 = grad(ix + 1, iy, iz + 1, dx - 1, dy, dz - 1);
    const float w011 = grad(ix, iy + 1, iz + 1, dx, dy - 1, dz - 1);
    const float w111 = grad(ix + 1, iy + 1, iz + 1, dx - 1, dy - 1, dz - 1);
    const float wx = fade(dx), wy = fade(dy), wz = fade(dz);
    const float x00 = lerp(wx, w000, w100);
    const float x10 = lerp(wx, w010, w110);
    const float x01 = lerp(wx, w001, w101);
    const float x11 = lerp(wx, w011, w111);
    const float y0 = lerp(wy, x00, x10);
    const float y1 = lerp(wy, x01, x11);
    return lerp(wz, y0, y1);
}

// The gradient of perlin_noise by forward differences of step 0.01 (pbrt-v4's DNoise).
CANDELA_HD inline Vec3f perlin_noise_gradient(const Vec3f& p) {
    constexpr float delta = 0.01f;
    const float n = perlin_noise(p);
    const Vec3f nd(perlin_noise(p + Vec3f(delta, 0, 0)), perlin_noise(p + Vec3f(0, delta, 0)),
                   perlin_noise(p + Vec3f(0, 0, delta)));
    return (nd - Vec3f(n)) / delta;
}

}  // namespace candela
