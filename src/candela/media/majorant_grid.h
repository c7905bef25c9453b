#pragma once
// pbrt-v4's MajorantGrid and DDAMajorantIterator: a coarse grid (16^3, or 64^3 for the VDB grids,
// as pbrt-v4 has them for its uniformgrid/rgbgrid and nanovdb media) over a medium's box whose
// every cell holds a bound on the medium's density scale in that cell, and the walk of a ray
// through its cells (Amanatides & Woo 1987), which yields one MajorantSegment per cell crossed.
// Delta and ratio tracking then draw distances against a majorant close to the medium where it
// is thin, instead of against the densest voxel everywhere.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "candela/core/platform.h"
#include "candela/math/bounds.h"
#include "candela/math/color.h"
#include "candela/math/constants.h"
#include "candela/math/ray.h"
#include "candela/math/vec.h"
#include "candela/media/medium_point.h"

namespace candela {

struct MajorantGrid {
    static constexpr int kRes = 16;     // cells per axis of the uniformgrid and rgbgrid media, as pbrt-v4
    static constexpr int kVdbRes = 64;  // of the nanovdb and openvdb media, as pbrt-v4's NanoVDBMedium
    int res = kRes;                     // cells per axis
    Bounds3f bounds;                    // the medium's box, medium space
    std::vector<float> cells;           // res^3, x fastest

    CANDELA_HD float at(int x, int y, int z) const { return cells[size_t((z * res + y) * res + x)]; }
    // Cell (x, y, z) as a box of [0, 1]^3, the unit cube of `bounds` (pbrt-v4's VoxelBounds).
    CANDELA_HD Bounds3f unit_cell(int x, int y, int z) const {
        const float n = float(res);
        return {Vec3f(float(x) / n, float(y) / n, float(z) / n),
                Vec3f(float(x + 1) / n, float(y + 1) / n, float(z + 1) / n)};
    }
    // The same cell in medium space.
    CANDELA_HD Bounds3f medium_cell(int x, int y, int z) const {
        const Bounds3f u = unit_cell(x, y, z);
        const Vec3f d = bounds.diagonal();
        return {bounds.lo + u.lo * d, bounds.lo + u.hi * d};
    }
};

// The grid of `res`^3 cells over `bounds` whose cell (x, y, z) is bound(its medium-space box, its
// box in [0, 1]^3).
template <class F>
MajorantGrid make_majorant_grid(const Bounds3f& bounds, F&& bound, int res = MajorantGrid::kRes) {
    MajorantGrid g;
    g.res = res;
    g.bounds = bounds;
    const int n = res;
    g.cells.resize(size_t(n * n * n));
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) g.cells[size_t((z * n + y) * n + x)] = bound(g.medium_cell(x, y, z), g.unit_cell(x, y, z));
    return g;
}

// The majorant grid's cells per axis for a VDB density of nx x ny x nz voxels: pbrt-v4's
// NanoVDBMedium walks 64^3 cells, but a cell narrower than two voxels bounds hardly tighter than
// one of two voxels (the trilinear interpolation anywhere in it reads the 2x2x2 voxels around it,
// Lattice::max_in_lattice_box), while every ray through it pays a DDA step: half the largest voxel
// count, between 16 (the uniformgrid's resolution) and 64. A grid of 128 or more voxels per axis
// keeps pbrt-v4's 64; the small smoke of tests/data/pbrt-media/ gets 16 (bench/RESULTS.md,
// 2026-11-29: its time to pbrt-v4's error fell from 0.57x to under 0.5x).
inline int vdb_majorant_resolution(int nx, int ny, int nz) {
    const int half = std::max({nx, ny, nz}) / 2;
    return std::clamp(half, MajorantGrid::kRes, MajorantGrid::kVdbRes);
}

// The cells a medium-space ray crosses over [t_min, t_max] (the ray clipped to the grid's box), in
// order, each as the segment of t it spends there with sigma_maj = sigma_t * the cell's bound. t is
// the ray's parameter, whatever the length of its direction. The segments tile [t_min, t_max]: each
// starts where the last ended, and the last ends at t_max (pbrt-v4 ends it at the grid's exit
// crossing, which rounding can put a hair before t_max).
class DdaMajorantIterator {
  public:
    // An iterator that yields nothing (a ray that misses the medium).
    DdaMajorantIterator() = default;

    CANDELA_HD DdaMajorantIterator(const Ray& ray, float t_min, float t_max, const MajorantGrid* grid,
                                   const Color& sigma_t)
        : sigma_t_(sigma_t), t_min_(t_min), t_max_(t_max), grid_(grid) {
        const int n = grid->res;
        const Vec3f diag = grid->bounds.diagonal();
        // The ray in the grid's unit cube, where cell faces lie at multiples of 1/n.
        const Vec3f o = (ray.o - grid->bounds.lo);
        for (int a = 0; a < 3; ++a) {
            const float o_u = o[a] / diag[a];
            float d_u = ray.d[a] / diag[a];
            if (d_u == 0.0f) d_u = 0.0f;  // -0 steps as +0
            const float p = o_u + d_u * t_min;
            const float c = p * float(n);
            voxel_[a] = !(c >= 0.0f) ? 0 : (c >= float(n - 1) ? n - 1 : int(c));
            if (d_u == 0.0f) {
                // Never crosses a face of this axis (pbrt-v4 gets an infinity, or NaN on a face).
                next_crossing_[a] = kInfinity;
                delta_t_[a] = kInfinity;
                step_[a] = 1;
                limit_[a] = n;
                continue;
            }
            delta_t_[a] = 1.0f / (std::abs(d_u) * float(n));
            if (d_u > 0.0f) {
                next_crossing_[a] = t_min + (float(voxel_[a] + 1) / float(n) - p) / d_u;
                step_[a] = 1;
                limit_[a] = n;
            } else {
                next_crossing_[a] = t_min + (float(voxel_[a]) / float(n) - p) / d_u;
                step_[a] = -1;
                limit_[a] = -1;
            }
        }
    }

    CANDELA_HD std::optional<MajorantSegment> next() {
        if (!(t_min_ < t_max_)) return std::nullopt;
        // The axis whose next face comes first (pbrt-v4's comparison table).
        const int bits = ((next_crossing_[0] < next_crossing_[1]) << 2) +
                         ((next_crossing_[0] < next_crossing_[2]) << 1) + (next_crossing_[1] < next_crossing_[2]);
        constexpr int kAxis[8] = {2, 1, 2, 1, 2, 2, 0, 0};
        const int axis = kAxis[bits];
        const Color sigma_maj = sigma_t_ * grid_->at(voxel_[0], voxel_[1], voxel_[2]);
        voxel_[axis] += step_[axis];
        // The walk ends at t_max, or where it leaves the grid.
        const bool last = next_crossing_[axis] >= t_max_ || voxel_[axis] == limit_[axis];
        float t_exit = last ? t_max_ : next_crossing_[axis];
        if (t_exit < t_min_) t_exit = t_min_;  // a crossing rounding put behind the last one
        MajorantSegment seg{t_min_, t_exit, sigma_maj};
        t_min_ = t_exit;
        next_crossing_[axis] += delta_t_[axis];
        return seg;
    }

  private:
    Color sigma_t_;
    float t_min_ = kInfinity, t_max_ = -kInfinity;
    const MajorantGrid* grid_ = nullptr;
    float next_crossing_[3] = {}, delta_t_[3] = {};
    int step_[3] = {}, limit_[3] = {}, voxel_[3] = {};
};

}  // namespace candela
