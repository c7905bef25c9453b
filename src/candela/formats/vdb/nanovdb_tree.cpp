// The tree of a NanoVDB float grid, walked from the root: root tiles (4096^3 voxels each, keyed by
// their origin), upper internal nodes (32^3 slots of 128^3 voxels), lower internal nodes (16^3
// slots of 8^3 voxels) and leaves (8^3 voxels). Each slot holds a child or a tile value with an
// active bit. The walk computes every origin itself from the root key and the slot numbers
// (the nodes' own bounding boxes are not trusted), and follows a child offset only when it lands
// exactly on a node of the right level inside the buffer, a node not reached before: so a corrupt
// file cannot send it out of the buffer, round a cycle, or through one node many times.
//
// Two walks: the first finds the bounding box of the active voxels and tiles (visiting every child
// but, of the tiles, only active ones, 64 mask bits at a time); the second, only through the slots
// that meet that box, fills the dense block with what NanoVDB's getValue returns for each voxel
// (leaf values, tile values active or not, the background where the tree has nothing).
#include "candela/formats/vdb/nanovdb_tree.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <vector>

#include "candela/core/error.h"
#include "candela/core/saturating.h"
#include "candela/formats/vdb/nanovdb_layout.h"
#include "candela/scene/memory_budget.h"

namespace candela {
namespace {

namespace L = nanovdb_layout;
using Coord = std::array<int64_t, 3>;

// A box of voxels, inclusive: the active bounding box, growing as voxels and tiles are added.
struct ActiveBox {
    Coord lo = {INT64_MAX, INT64_MAX, INT64_MAX}, hi = {INT64_MIN, INT64_MIN, INT64_MIN};
    bool empty() const { return lo[0] > hi[0]; }
    void add(const Coord& origin, int64_t width) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], origin[a]);
            hi[a] = std::max(hi[a], origin[a] + width - 1);
        }
    }
};

// Floor of a / b for b > 0.
int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

class TreeWalker {
  public:
    TreeWalker(std::string_view bytes, const std::string& file, const std::string& name)
        : b_(bytes), file_(file), name_(name) {
        if (!b_.holds(0, L::kGridDataSize + L::kTreeDataSize))
            fail(fmt::format("the grid buffer has {} bytes, fewer than its headers ({})", b_.size(),
                             L::kGridDataSize + L::kTreeDataSize));
        const uint64_t sizes[3] = {L::kLeafSize, L::kLower.size, L::kUpper.size};
        for (int level = 0; level < 3; ++level) {
            count_[level] = b_.at<uint32_t>(kTree + L::kTreeNodeCount + 4 * level);
            start_[level] = node_array_start(level);
            if (count_[level] > 0 && !b_.holds(start_[level], uint64_t(count_[level]) * sizes[level]))
                fail(fmt::format("its {} {} nodes at byte {} do not fit in its {} bytes", count_[level],
                                 kLevelNames[level], start_[level], b_.size()));
        }
        root_ = node_array_start(3);
        if (!b_.holds(root_, L::kRootDataSize)) fail(fmt::format("its root at byte {} lies outside it", root_));
        table_size_ = b_.at<uint32_t>(root_ + L::kRootTableSize);
        if (!b_.holds(root_ + L::kRootDataSize, uint64_t(table_size_) * L::kRootTileSize))
            fail(fmt::format("its root table of {} tiles does not fit in its {} bytes", table_size_, b_.size()));
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw SceneError(SourceLocation{file_, 0, 0, {}}, fmt::format("corrupt NanoVDB grid \"{}\": {}", name_, what));
    }

    float background() const { return b_.at<float>(root_ + L::kRootBackground); }

    // Calls tile(origin, width, value, active) for tile values (root, upper and lower) and
    // leaf(origin, offset) for leaves. Without `clip`: every child and every active tile of the
    // internal nodes (skipping 64 empty slots at once), each child checked; with it: the slots
    // that meet the box, children or tiles, active or not.
    template <class TileFn, class LeafFn>
    void walk(TileFn&& tile, LeafFn&& leaf, const ActiveBox* clip = nullptr) {
        for (int level = 0; level < 3; ++level) seen_[level].assign(count_[level], 0);
        std::vector<Coord> origins;
        origins.reserve(table_size_);
        for (uint32_t t = 0; t < table_size_; ++t) {
            const uint64_t at = root_ + L::kRootDataSize + uint64_t(t) * L::kRootTileSize;
            const uint64_t key = b_.at<uint64_t>(at + L::kTileKey);
            // The key packs x, y, z >> 12 in 21 bits each (x highest); an origin is a multiple of 4096.
            auto axis = [&](int shift) { return int64_t(int32_t(uint32_t(((key >> shift) & 0x1fffff) << 12))); };
            const Coord origin = {axis(42), axis(21), axis(0)};
            origins.push_back(origin);
            const int64_t child = b_.at<int64_t>(at + L::kTileChild);
            if (child != 0)
                internal(L::kUpper, child_node(2, root_, child), origin, tile, leaf, clip);
            else
                tile(origin, int64_t(4096), b_.at<float>(at + L::kTileValue), b_.at<uint32_t>(at + L::kTileState) != 0);
        }
        std::sort(origins.begin(), origins.end());
        if (std::adjacent_find(origins.begin(), origins.end()) != origins.end())
            fail("two root tiles have the same origin");
    }

  private:
    static constexpr uint64_t kTree = L::kGridDataSize;
    static constexpr const char* kLevelNames[3] = {"leaf", "lower internal", "upper internal"};

    // Where the nodes of `level` (0 leaves .. 3 root) start, from the TreeData's offsets.
    uint64_t node_array_start(int level) const {
        const int64_t offset = b_.at<int64_t>(kTree + L::kTreeNodeOffset + 8 * level);
        if (offset < 0 || uint64_t(offset) > b_.size() - kTree)
            fail(fmt::format("the offset {} of its {} nodes lies outside it", offset,
                             level == 3 ? "root" : kLevelNames[level]));
        return kTree + uint64_t(offset);
    }

    // The node of `level` that `parent` + `offset` points to; fails unless it is one, reached once.
    uint64_t child_node(int level, uint64_t parent, int64_t offset) {
        static constexpr uint64_t sizes[3] = {L::kLeafSize, L::kLower.size, L::kUpper.size};
        const int64_t target =
            int64_t(parent) + std::clamp<int64_t>(offset, -int64_t(b_.size()) - 1, int64_t(b_.size()) + 1);
        const bool in_array = target >= int64_t(start_[level]) &&
                              (uint64_t(target) - start_[level]) % sizes[level] == 0 &&
                              (uint64_t(target) - start_[level]) / sizes[level] < count_[level];
        if (!in_array)
            fail(fmt::format(
                "a child offset of the node at byte {} points to byte {}, which is not one of its {} {} nodes", parent,
                target, count_[level], kLevelNames[level]));
        uint8_t& seen = seen_[level][(uint64_t(target) - start_[level]) / sizes[level]];
        if (seen) fail(fmt::format("the {} node at byte {} is the child of two slots", kLevelNames[level], target));
        seen = 1;
        return uint64_t(target);
    }

    bool bit(uint64_t mask, uint32_t n) const { return (b_.at<uint64_t>(mask + 8 * (n >> 6)) >> (n & 63)) & 1; }

    template <class TileFn, class LeafFn>
    void internal(const L::InternalLayout& node, uint64_t at, const Coord& origin, TileFn& tile, LeafFn& leaf,
                  const ActiveBox* clip) {
        const int dim = node.log2dim;
        const int64_t width = int64_t(1) << node.child_log2, side = int64_t(1) << dim;
        auto visit = [&](uint32_t n) {
            const Coord o = {origin[0] + int64_t(n >> (2 * dim)) * width,
                             origin[1] + int64_t((n >> dim) & (side - 1)) * width,
                             origin[2] + int64_t(n & (side - 1)) * width};
            const uint64_t slot = at + node.table + 8 * uint64_t(n);
            if (bit(at + node.child_mask, n)) {
                const int64_t child = b_.at<int64_t>(slot);
                if (node.log2dim == L::kUpper.log2dim)
                    internal(L::kLower, child_node(1, at, child), o, tile, leaf, clip);
                else
                    leaf(o, child_node(0, at, child));
            } else {
                tile(o, width, b_.at<float>(slot), bit(at + node.value_mask, n));
            }
        };
        if (!clip) {
            const uint32_t words = (1u << (3 * dim)) / 64;
            for (uint32_t w = 0; w < words; ++w) {
                uint64_t bits =
                    b_.at<uint64_t>(at + node.child_mask + 8 * w) | b_.at<uint64_t>(at + node.value_mask + 8 * w);
                for (; bits != 0; bits &= bits - 1) visit(w * 64 + uint32_t(std::countr_zero(bits)));
            }
            return;
        }
        int64_t lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::max<int64_t>(0, floor_div(clip->lo[a] - origin[a], width));
            hi[a] = std::min<int64_t>(side - 1, floor_div(clip->hi[a] - origin[a], width));
            if (lo[a] > hi[a]) return;
        }
        for (int64_t x = lo[0]; x <= hi[0]; ++x)
            for (int64_t y = lo[1]; y <= hi[1]; ++y)
                for (int64_t z = lo[2]; z <= hi[2]; ++z) visit(uint32_t((x << (2 * dim)) | (y << dim) | z));
    }

  public:
    // Leaf helpers: whether voxel n (x * 64 + y * 8 + z) is active, and its value.
    bool leaf_active(uint64_t leaf, uint32_t n) const { return bit(leaf + L::kLeafValueMask, n); }
    float leaf_value(uint64_t leaf, uint32_t n) const { return b_.at<float>(leaf + L::kLeafValues + 4 * uint64_t(n)); }
    const L::Bytes& bytes() const { return b_; }

  private:
    L::Bytes b_;
    const std::string& file_;
    const std::string& name_;
    uint32_t count_[3] = {};
    uint64_t start_[3] = {};
    uint64_t root_ = 0;
    uint32_t table_size_ = 0;
    std::vector<uint8_t> seen_[3];
};

void read_map(const L::Bytes& b, VolumeGrid& grid, const TreeWalker& walker) {
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) grid.index_to_world[r][c] = b.at<double>(L::kGridMapMatD + 8 * (3 * r + c));
        grid.index_to_world[r][3] = b.at<double>(L::kGridMapVecD + 8 * r);
    }
    const auto& m = grid.index_to_world;
    for (const auto& row : m)
        for (double v : row)
            if (!std::isfinite(v)) walker.fail("its index-to-world map is not finite");
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (!(std::abs(det) > 0) || !std::isfinite(det)) walker.fail("its index-to-world map is singular");
}

// The world box of the active cells: the file's when it is a box, else the map applied to the
// index box [min, max + 1] (as NanoVDB computes it).
void read_world_bounds(const L::Bytes& b, VolumeGrid& grid) {
    if (grid.voxel_count() == 0) return;
    bool valid = true;
    for (int a = 0; a < 3; ++a) {
        grid.world_min[a] = b.at<double>(L::kGridWorldBBox + 8 * a);
        grid.world_max[a] = b.at<double>(L::kGridWorldBBox + 24 + 8 * a);
        valid = valid && std::isfinite(grid.world_min[a]) && std::isfinite(grid.world_max[a]) &&
                grid.world_min[a] <= grid.world_max[a];
    }
    if (valid) return;
    const Vec3d lo(grid.index_min), hi = lo + Vec3d(double(grid.nx), double(grid.ny), double(grid.nz));
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p =
            grid.index_to_world_point({corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z});
        for (int a = 0; a < 3; ++a) {
            grid.world_min[a] = corner == 0 ? p[a] : std::min(grid.world_min[a], p[a]);
            grid.world_max[a] = corner == 0 ? p[a] : std::max(grid.world_max[a], p[a]);
        }
    }
}

}  // namespace

VolumeGrid decode_nanovdb_float_grid(std::string_view bytes, const std::string& file, const std::string& name,
                                     MemoryBudget& budget) {
    TreeWalker walker(bytes, file, name);
    const L::Bytes& b = walker.bytes();
    const uint64_t magic = b.at<uint64_t>(L::kGridMagic);
    if (magic != L::kMagicGrid && magic != L::kMagicFileOld)
        walker.fail("it does not start with NanoVDB's grid magic number");
    if (const uint32_t type = b.at<uint32_t>(L::kGridType); type != L::kGridTypeFloat)
        walker.fail(fmt::format("the file's table says float, but the grid's header says type {}", type));

    VolumeGrid grid;
    grid.name = name;
    read_map(b, grid, walker);
    grid.background = walker.background();
    if (!std::isfinite(grid.background)) walker.fail("its background value is not finite");

    // First walk: the active bounding box.
    ActiveBox box;
    walker.walk(
        [&](const Coord& origin, int64_t width, float, bool active) {
            if (active) box.add(origin, width);
        },
        [&](const Coord& origin, uint64_t leaf) {
            for (uint32_t n = 0; n < 512; ++n)
                if (walker.leaf_active(leaf, n))
                    box.add({origin[0] + (n >> 6), origin[1] + ((n >> 3) & 7), origin[2] + (n & 7)}, 1);
        });
    if (box.empty()) return grid;

    int64_t dims[3];
    for (int a = 0; a < 3; ++a) {
        dims[a] = box.hi[a] - box.lo[a] + 1;
        if (dims[a] > INT_MAX)
            throw SceneError(SourceLocation{file, 0, 0, {}},
                             fmt::format("NanoVDB grid \"{}\" is {} voxels wide along {}; candela reads grids up to {}",
                                         name, dims[a], "xyz"[a], INT_MAX));
    }
    const uint64_t voxels =
        saturating_product(saturating_product(uint64_t(dims[0]), uint64_t(dims[1])), uint64_t(dims[2]));
    if (auto refused = budget.charge(
            saturating_product(voxels, sizeof(float)),
            fmt::format("volume grid \"{}\" ({}x{}x{} voxels)", name, dims[0], dims[1], dims[2]), bytes.size()))
        throw SceneError(SourceLocation{file, 0, 0, {}}, *refused);
    grid.index_min = Vec3<int>(int(box.lo[0]), int(box.lo[1]), int(box.lo[2]));
    grid.nx = int(dims[0]);
    grid.ny = int(dims[1]);
    grid.nz = int(dims[2]);
    grid.values.assign(voxels, grid.background);

    // Second walk: every value inside the block.
    auto put = [&](int64_t x, int64_t y, int64_t z, float v) {
        if (!std::isfinite(v)) walker.fail(fmt::format("voxel ({}, {}, {}) is not a finite number", x, y, z));
        grid.values[size_t(((z - box.lo[2]) * dims[1] + (y - box.lo[1])) * dims[0] + (x - box.lo[0]))] = v;
    };
    walker.walk(
        [&](const Coord& origin, int64_t width, float value, bool) {
            Coord lo, hi;
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::max(origin[a], box.lo[a]);
                hi[a] = std::min(origin[a] + width - 1, box.hi[a]);
                if (lo[a] > hi[a]) return;
            }
            if (value == grid.background) return;
            for (int64_t z = lo[2]; z <= hi[2]; ++z)
                for (int64_t y = lo[1]; y <= hi[1]; ++y)
                    for (int64_t x = lo[0]; x <= hi[0]; ++x) put(x, y, z, value);
        },
        [&](const Coord& origin, uint64_t leaf) {
            for (uint32_t n = 0; n < 512; ++n) {
                const Coord p = {origin[0] + (n >> 6), origin[1] + ((n >> 3) & 7), origin[2] + (n & 7)};
                if (p[0] >= box.lo[0] && p[0] <= box.hi[0] && p[1] >= box.lo[1] && p[1] <= box.hi[1] &&
                    p[2] >= box.lo[2] && p[2] <= box.hi[2])
                    put(p[0], p[1], p[2], walker.leaf_value(leaf, n));
            }
        },
        &box);
    read_world_bounds(b, grid);
    return grid;
}

}  // namespace candela
