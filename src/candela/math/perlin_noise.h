#pragma once
// Ken Perlin's gradient noise as pbrt-v4 computes it (src/pbrt/util/noise.cpp: Noise, DNoise), so
// that what pbrt-v4 builds from it (the cloud medium, media/cloud_medium.h) is the same function
// here: the same permutation table, gradient choice (Perlin 2002, "Improving noise"), quintic
// fade 6t^5 - 15t^4 + 10t^3 and interpolation order, float arithmetic step for step.
#include <bit>
#include <cmath>
#include <cstdint>

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

// Always inlined: the cloud medium evaluates noise 13 times per density lookup (cloud_medium.h),
// and GCC otherwise calls grad for each of a lookup's 104 corners (a quarter of a cloud render).
#define CANDELA_PERLIN_INLINE inline __attribute__((always_inline))

CANDELA_HD CANDELA_PERLIN_INLINE int perm(int i) { return kPerlinPermutation[i & 255]; }

// The gradient of a lattice point, by its hash h (Perlin's 12 edge directions, 16 with 4 repeated),
// dotted with the offset (dx, dy, dz): u + v, each a signed offset component picked by h. Picked
// and negated by bit masks rather than branches: the hashes are random, so branches on them were
// mispredicted about half the time (most of the noise's cost). Negating a float flips its sign bit,
// so the result is the branching form's, bit for bit.
CANDELA_HD CANDELA_PERLIN_INLINE float grad(int h, float dx, float dy, float dz) {
    const uint32_t bx = std::bit_cast<uint32_t>(dx), by = std::bit_cast<uint32_t>(dy), bz = std::bit_cast<uint32_t>(dz);
    // u is dx for h < 8, 12 and 13, else dy; v is dy for h < 4, 12 and 13, else dz: bit h of
    // 0x30ff and of 0x300f.
    const uint32_t u_is_x = 0u - ((0x30ffu >> h) & 1u);
    const uint32_t v_is_y = 0u - ((0x300fu >> h) & 1u);
    const uint32_t u = ((bx & u_is_x) | (by & ~u_is_x)) ^ (uint32_t(h & 1) << 31);
    const uint32_t v = ((by & v_is_y) | (bz & ~v_is_y)) ^ (uint32_t(h & 2) << 30);
    return std::bit_cast<float>(u) + std::bit_cast<float>(v);
}

// 6t^5 - 15t^4 + 10t^3, its powers grouped as pbrt-v4's Pow<n> groups them.
CANDELA_HD CANDELA_PERLIN_INLINE float fade(float t) {
    const float t2 = t * t;
    const float t4 = t2 * t2;
    return 6 * (t4 * t) - 15 * t4 + 10 * (t2 * t);
}

// The lattice cell of a point (its corner, each coordinate taken modulo 256) and the offset from it.
struct LatticePoint {
    int ix, iy, iz;
    float dx, dy, dz;
    bool same_cell(const LatticePoint& o) const { return ix == o.ix && iy == o.iy && iz == o.iz; }
};

CANDELA_HD CANDELA_PERLIN_INLINE LatticePoint locate(const Vec3f& p) {
    // fmod keeps huge coordinates within int range (pbrt-v4 does the same); below 2^30 it returns
    // its argument exactly, so it is skipped there (it was a twentieth of a cloud render).
    constexpr float kWrap = float(1 << 30);
    const float x = std::fabs(p.x) < kWrap ? p.x : std::fmod(p.x, kWrap);
    const float y = std::fabs(p.y) < kWrap ? p.y : std::fmod(p.y, kWrap);
    const float z = std::fabs(p.z) < kWrap ? p.z : std::fmod(p.z, kWrap);
    const int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
    return {ix & 255, iy & 255, iz & 255, x - float(ix), y - float(iy), z - float(iz)};
}

// The hashes of a cell's 8 corners, h[x + 2y + 4z] = perm(perm(perm(ix + x) + iy + y) + iz + z) & 15
// (pbrt-v4's hash), with the partial sums shared as in Perlin's reference code: 14 table reads
// instead of 24. (perm masks its index, as pbrt-v4's doubled 512-entry table does.)
struct CornerHashes {
    int h[8];
};

CANDELA_HD CANDELA_PERLIN_INLINE CornerHashes corner_hashes(const LatticePoint& c) {
    const int a = perm(c.ix) + c.iy, b = perm(c.ix + 1) + c.iy;
    const int aa = perm(a) + c.iz, ab = perm(a + 1) + c.iz, ba = perm(b) + c.iz, bb = perm(b + 1) + c.iz;
    return {{perm(aa) & 15, perm(ba) & 15, perm(ab) & 15, perm(bb) & 15, perm(aa + 1) & 15, perm(ba + 1) & 15,
             perm(ab + 1) & 15, perm(bb + 1) & 15}};
}

// The noise at offset (dx, dy, dz) in the cell whose corner hashes are h: pbrt-v4's Noise from its
// gradients on, in its order of operations.
CANDELA_HD CANDELA_PERLIN_INLINE float noise_in_cell(const CornerHashes& c, float dx, float dy, float dz) {
    const float w000 = grad(c.h[0], dx, dy, dz);
    const float w100 = grad(c.h[1], dx - 1, dy, dz);
    const float w010 = grad(c.h[2], dx, dy - 1, dz);
    const float w110 = grad(c.h[3], dx - 1, dy - 1, dz);
    const float w001 = grad(c.h[4], dx, dy, dz - 1);
    const float w101 = grad(c.h[5], dx - 1, dy, dz - 1);
    const float w011 = grad(c.h[6], dx, dy - 1, dz - 1);
    const float w111 = grad(c.h[7], dx - 1, dy - 1, dz - 1);
    const float wx = fade(dx), wy = fade(dy), wz = fade(dz);
    const float x00 = lerp(wx, w000, w100);
    const float x10 = lerp(wx, w010, w110);
    const float x01 = lerp(wx, w001, w101);
    const float x11 = lerp(wx, w011, w111);
    const float y0 = lerp(wy, x00, x10);
    const float y1 = lerp(wy, x01, x11);
    return lerp(wz, y0, y1);
}

CANDELA_HD CANDELA_PERLIN_INLINE float noise_at(const LatticePoint& c) {
    return noise_in_cell(corner_hashes(c), c.dx, c.dy, c.dz);
}

#undef CANDELA_PERLIN_INLINE

}  // namespace perlin_detail

// Gradient noise at p: 0 at every integer lattice point, values in about [-1, 1], period 256 in
// each axis.
CANDELA_HD inline float perlin_noise(const Vec3f& p) { return perlin_detail::noise_at(perlin_detail::locate(p)); }

// The gradient of perlin_noise by forward differences of step 0.01 (pbrt-v4's DNoise). The four
// lookups mostly fall in one lattice cell, whose corner hashes they then share; each value is
// perlin_noise's at its point, bit for bit.
CANDELA_HD inline Vec3f perlin_noise_gradient(const Vec3f& p) {
    using namespace perlin_detail;
    constexpr float delta = 0.01f;
    const LatticePoint c = locate(p);
    const CornerHashes h = corner_hashes(c);
    auto at = [&](const Vec3f& q) {
        const LatticePoint cq = locate(q);
        return cq.same_cell(c) ? noise_in_cell(h, cq.dx, cq.dy, cq.dz) : noise_at(cq);
    };
    const float n = noise_in_cell(h, c.dx, c.dy, c.dz);
    const Vec3f nd(at(p + Vec3f(delta, 0, 0)), at(p + Vec3f(0, delta, 0)), at(p + Vec3f(0, 0, delta)));
    return (nd - Vec3f(n)) / delta;
}

}  // namespace candela
