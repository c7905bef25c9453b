#pragma once
// Regular 3D grids of samples, interpolated trilinearly: the storage of the grid media.
//
// `Lattice<T>` holds nx * ny * nz samples, x fastest (sample (x, y, z) at (z ny + y) nx + x), and
// interpolates them at continuous lattice coordinates q, where sample (i, j, k) sits at
// q = (i, j, k) and samples outside the lattice are zero. Two placements share that lookup:
//   - pbrt-v4's SampledGrid (uniformgrid, rgbgrid): a point u in [0, 1]^3 of the grid's box is
//     q = u n - 1/2, so the samples sit at the centres of n cells tiling the box (`lookup`);
//   - NanoVDB / OpenVDB grids: a dense block of voxels read out of the tree, whose trilinear
//     sampler puts values at integer index coordinates; q = index - the block's index origin.
// `GridField` is a lattice with its placement in medium space, an affine map p -> q, so a
// medium holds any of them the same way.
#include <cmath>
#include <utility>
#include <vector>

#include "candela/core/platform.h"
#include "candela/math/bounds.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"
#include "candela/media/medium_box.h"

namespace candela {

template <class T>
struct Lattice {
    int nx = 0, ny = 0, nz = 0;
    std::vector<T> values;  // nx * ny * nz, x fastest

    CANDELA_HD bool empty() const { return values.empty(); }
    CANDELA_HD int size(int axis) const { return axis == 0 ? nx : (axis == 1 ? ny : nz); }

    // Sample (x, y, z) through `convert` (T -> a float or a Color), or zero outside the lattice.
    template <class F>
    CANDELA_HD auto sample(int x, int y, int z, F&& convert) const -> decltype(convert(values[0])) {
        using R = decltype(convert(values[0]));
        if (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz) return R{};
        return convert(values[(size_t(z) * size_t(ny) + size_t(y)) * size_t(nx) + size_t(x)]);
    }

    // The trilinear interpolation of the converted samples at lattice coordinates q (in pbrt-v4's
    // order: x, then y, then z, each lerp (1 - t) a + t b).
    template <class F>
    CANDELA_HD auto at_lattice(Vec3f q, F&& convert) const -> decltype(convert(values[0])) {
        // Beyond one sample outside, every sample read is zero: clamping there (NaN included)
        // changes no result and keeps floor() within int range.
        for (int a = 0; a < 3; ++a) {
            const float hi = float(size(a) + 1);
            q[a] = !(q[a] >= -2.0f) ? -2.0f : (q[a] > hi ? hi : q[a]);
        }
        const int x = int(std::floor(q.x)), y = int(std::floor(q.y)), z = int(std::floor(q.z));
        const float dx = q.x - float(x), dy = q.y - float(y), dz = q.z - float(z);
        const auto d00 = lerp(dx, sample(x, y, z, convert), sample(x + 1, y, z, convert));
        const auto d10 = lerp(dx, sample(x, y + 1, z, convert), sample(x + 1, y + 1, z, convert));
        const auto d01 = lerp(dx, sample(x, y, z + 1, convert), sample(x + 1, y, z + 1, convert));
        const auto d11 = lerp(dx, sample(x, y + 1, z + 1, convert), sample(x + 1, y + 1, z + 1, convert));
        return lerp(dz, lerp(dy, d00, d10), lerp(dy, d01, d11));
    }

    // pbrt-v4's SampledGrid::Lookup: u in [0, 1]^3 of the grid's box, a sample at each cell centre.
    template <class F>
    CANDELA_HD auto lookup(const Vec3f& u, F&& convert) const -> decltype(convert(values[0])) {
        return at_lattice(Vec3f(u.x * float(nx) - 0.5f, u.y * float(ny) - 0.5f, u.z * float(nz) - 0.5f), convert);
    }

    // The largest `convert(sample)` (a float) of the samples that an interpolation anywhere in the
    // lattice-coordinate box [q0, q1] reads, and 0 for those outside the lattice: a bound on
    // at_lattice over the box when convert bounds each interpolated value by its samples' (it does
    // for non-negative samples and for the maximum of a spectrum). pbrt-v4's SampledGrid::MaxValue.
    template <class F>
    float max_in_lattice_box(Vec3f q0, Vec3f q1, F&& convert) const {
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            const float top = float(size(a) + 1);
            q0[a] = !(q0[a] >= -2.0f) ? -2.0f : (q0[a] > top ? top : q0[a]);
            q1[a] = !(q1[a] >= -2.0f) ? -2.0f : (q1[a] > top ? top : q1[a]);
            const int l = int(std::floor(q0[a])), h = int(std::floor(q1[a])) + 1;
            lo[a] = l > 0 ? l : 0;
            hi[a] = h < size(a) - 1 ? h : size(a) - 1;
        }
        float m = 0.0f;
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    const float v = convert(values[(size_t(z) * size_t(ny) + size_t(y)) * size_t(nx) + size_t(x)]);
                    m = v > m ? v : m;
                }
        return m;
    }
    // The same bound over a box of u in [0, 1]^3 (SampledGrid::lookup's coordinates).
    template <class F>
    float max_value(const Bounds3f& u_box, F&& convert) const {
        const Vec3f n{float(nx), float(ny), float(nz)};
        return max_in_lattice_box(u_box.lo * n - Vec3f(0.5f), u_box.hi * n - Vec3f(0.5f), convert);
    }
};

// A float lattice (density, temperature, emission scale) and its lookups without conversion.
struct LatticeGrid : Lattice<float> {
    CANDELA_HD static float identity(float v) { return v; }
    CANDELA_HD float at_lattice(const Vec3f& q) const { return Lattice::at_lattice(q, identity); }
    CANDELA_HD float lookup(const Vec3f& u) const { return Lattice::lookup(u, identity); }
    float max_in_lattice_box(const Vec3f& q0, const Vec3f& q1) const {
        return Lattice::max_in_lattice_box(q0, q1, identity);
    }
    float max_value(const Bounds3f& u_box) const { return Lattice::max_value(u_box, identity); }
};

// The placement of pbrt-v4's SampledGrid of n samples per axis over `bounds` (medium space): the
// map p -> q = (p - p0) / (p1 - p0) n - 1/2 (an axis where the box is flat is not divided, as
// Bounds3::Offset does not).
inline AffineMap3f cell_centred_placement(const Bounds3f& bounds, int nx, int ny, int nz) {
    const Vec3f n{float(nx), float(ny), float(nz)};
    Vec3f scale, offset;
    for (int a = 0; a < 3; ++a) {
        const float extent = bounds.hi[a] - bounds.lo[a];
        scale[a] = extent > 0.0f ? n[a] / extent : n[a];
        offset[a] = -bounds.lo[a] * scale[a] - 0.5f;
    }
    return AffineMap3f::scale_offset(scale, offset);
}

// A float lattice placed in medium space, with the value it takes outside the lattice: 0 for
// pbrt-v4's SampledGrid, a VDB grid's background for a block read out of its tree. The lattice
// holds each value minus `outside` (whose trilinear interpolation, zero outside, plus `outside`
// is the interpolation of the values with `outside` beyond them: the weights sum to 1).
struct GridField {
    LatticeGrid lattice;
    AffineMap3f lattice_from_medium;  // medium-space point -> lattice coordinates
    float outside = 0.0f;

    CANDELA_HD bool empty() const { return lattice.empty(); }
    CANDELA_HD float at(const Vec3f& p_medium) const {
        return lattice.at_lattice(lattice_from_medium.apply_point(p_medium)) + outside;
    }
    // A bound on at() over a medium-space box: the lattice box around its eight corners' images,
    // widened by 1e-4 lattice units so that points the rounding of a lookup moves just across a
    // cell face stay covered.
    float max_over(const Bounds3f& medium_box) const {
        Bounds3f q;
        for (int c = 0; c < 8; ++c) {
            const Vec3f corner((c & 1) ? medium_box.hi.x : medium_box.lo.x, (c & 2) ? medium_box.hi.y : medium_box.lo.y,
                               (c & 4) ? medium_box.hi.z : medium_box.lo.z);
            q.extend(lattice_from_medium.apply_point(corner));
        }
        constexpr float kWiden = 1e-4f;
        return lattice.max_in_lattice_box(q.lo - Vec3f(kWiden), q.hi + Vec3f(kWiden)) + outside;
    }
};

// The field of `values` (x fastest, nx * ny * nz) placed by `lattice_from_medium`, `outside`
// beyond them: how a VDB grid's dense block becomes a GridField (its index-to-medium map
// inverted, minus the block's index origin; outside = its background).
inline GridField placed_field(int nx, int ny, int nz, std::vector<float> values, const AffineMap3f& lattice_from_medium,
                              float outside) {
    GridField f;
    f.lattice.nx = nx;
    f.lattice.ny = ny;
    f.lattice.nz = nz;
    for (float& v : values) v -= outside;
    f.lattice.values = std::move(values);
    f.lattice_from_medium = lattice_from_medium;
    f.outside = outside;
    return f;
}

// pbrt-v4's SampledGrid of `lattice` over `bounds`.
inline GridField cell_centred_field(LatticeGrid lattice, const Bounds3f& bounds) {
    GridField f;
    f.lattice_from_medium = cell_centred_placement(bounds, lattice.nx, lattice.ny, lattice.nz);
    f.lattice = std::move(lattice);
    return f;
}

}  // namespace candela
