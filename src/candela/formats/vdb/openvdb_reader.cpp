// OpenVDB files through libopenvdb: the grid's metadata first (type, and the active bounding box
// and memory that io::File writes as file_bbox_min/max and file_mem_bytes, to refuse a grid too
// large before its tree is read), then the tree, copied voxel by voxel into the dense block of its
// active bounding box. Same result as nanovdb_reader.h for the same grid: OpenVDB's getValue per
// voxel, the affine map of a linear transform, world bounds of the active cells.
#include "candela/formats/vdb/openvdb_reader.h"

#include <fmt/format.h>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <algorithm>
#include <climits>
#include <cmath>
#include <fstream>
#include <mutex>

#include "candela/core/error.h"
#include "candela/core/saturating.h"
#include "candela/scene/memory_budget.h"

namespace candela {
namespace {

// openvdb::initialize registers the grid and map types; once per process.
void initialize_openvdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

// Bytes of the dense block of `box`, saturating.
uint64_t dense_bytes(const openvdb::CoordBBox& box) {
    const openvdb::Coord d = box.dim();
    return saturating_product(saturating_product(saturating_product(uint64_t(d.x()), uint64_t(d.y())), uint64_t(d.z())),
                              sizeof(float));
}

std::vector<std::string> names_in(openvdb::io::File& file) {
    std::vector<std::string> names;
    for (auto it = file.beginName(); it != file.endName(); ++it) names.push_back(*it);
    return names;
}

// OpenVDB's message, fit for one line: a corrupt file can put the bytes of a string it never
// read into it (NULs, long runs of garbage). Printable ASCII kept, the rest as '?', runs of
// blanks as one, at most 200 characters.
std::string printable(std::string_view message) {
    std::string out;
    for (char c : message) {
        const char p = c >= 0x20 && c < 0x7f ? c : (c == '\0' || c == '\n' || c == '\t' ? ' ' : '?');
        if (p == ' ' && (out.empty() || out.back() == ' ')) continue;
        if (out.size() == 200) {
            out += "...";
            break;
        }
        out += p;
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

// Checks that what libopenvdb reads before a tree fits in the file, since it takes a size from a
// read that failed as if it had read it (a file cut inside its metadata made it allocate 14 GB):
// the header, the file's metadata (count; per item a name, a type name and a value, each a u32
// size and bytes), and the chain of grid descriptors (name, type, instance parent; the grid's,
// its data blocks' and its end's offsets, the next descriptor starting at that end), with each
// grid's own metadata at its offset (after a u32 of compression flags). Throws SceneError.
class VdbPrecheck {
  public:
    VdbPrecheck(const std::filesystem::path& path, const std::string& file) : in_(path, std::ios::binary), file_(file) {
        in_.seekg(0, std::ios::end);
        size_ = in_ ? uint64_t(std::max<std::streamoff>(0, in_.tellg())) : 0;
    }

    void run() {
        if (size_ < 8 || u64(0) != 0x56444220) return;  // not a VDB file: libopenvdb says so
        const uint32_t version = u32(8);
        if (version < 221) return;  // libopenvdb refuses these
        const bool has_offsets = byte(20) != 0;
        uint64_t at = 21 + (version < 222 ? 1 : 0) + 36;  // the header, with its UUID
        at = meta_map(at);
        if (!has_offsets) return;
        const uint32_t grids = u32(at);
        at += 4;
        for (uint32_t g = 0; g < grids && g < (1u << 20); ++g) {
            for (int s = 0; s < 3; ++s) at = string(at);  // name, type, instance parent
            const uint64_t grid = u64(at), blocks = u64(at + 8), end = u64(at + 16);
            if (!(grid >= at + 24 && grid <= blocks && blocks <= end && end <= size_))
                fail(fmt::format("grid {} says it lies at bytes {} to {}, but the file has {} bytes", g, grid, end,
                                 size_));
            meta_map(grid + (version >= 222 ? 4 : 0));
            at = end;
        }
    }

  private:
    [[noreturn]] void fail(const std::string& what) const {
        throw SceneError(SourceLocation{file_, 0, 0, {}}, fmt::format("truncated or corrupt OpenVDB file: {}", what));
    }
    void need(uint64_t at, uint64_t count) const {
        if (at > size_ || count > size_ - at)
            fail(fmt::format("{} bytes at byte {} lie past its end ({} bytes)", count, at, size_));
    }
    template <class T>
    T read(uint64_t at) {
        need(at, sizeof(T));
        T v{};
        in_.clear();
        in_.seekg(std::streamoff(at));
        in_.read(reinterpret_cast<char*>(&v), sizeof(T));
        if (!in_) fail(fmt::format("cannot read byte {}", at));
        return v;
    }
    uint64_t u64(uint64_t at) { return read<uint64_t>(at); }
    uint32_t u32(uint64_t at) { return read<uint32_t>(at); }
    char byte(uint64_t at) { return read<char>(at); }
    // A u32 size and that many bytes; returns where it ends.
    uint64_t string(uint64_t at) {
        const uint64_t n = u32(at);
        need(at + 4, n);
        return at + 4 + n;
    }
    uint64_t meta_map(uint64_t at) {
        const uint32_t count = u32(at);
        at += 4;
        for (uint32_t i = 0; i < count; ++i) at = string(string(string(at)));  // name, type, value
        return at;
    }

    std::ifstream in_;
    std::string file_;
    uint64_t size_ = 0;
};

// Runs `body` on the opened file, turning OpenVDB's exceptions into SceneErrors.
template <class Body>
auto with_file(const std::filesystem::path& path, Body&& body) {
    initialize_openvdb();
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail_in_file(name, "cannot open OpenVDB file: no such file");
    VdbPrecheck(path, name).run();
    try {
        openvdb::io::File file(name);
        file.open(/*delayLoad=*/false);
        return body(file);
    } catch (const SceneError&) {
        throw;
    } catch (const std::exception& e) {
        fail_in_file(name, fmt::format("cannot read OpenVDB file: {}", printable(e.what())));
    }
}

void read_map(const openvdb::FloatGrid& grid, const std::string& file, VolumeGrid& out) {
    const openvdb::math::Transform& transform = grid.transform();
    if (!transform.isLinear())
        fail_in_file(file,
                     fmt::format("grid \"{}\" has a non-linear transform ({}); candela reads grids with an affine "
                                 "index-to-world map only",
                                 out.name, transform.mapType()));
    // OpenVDB multiplies row vectors: world = (i, j, k, 1) * M, so our rows are M's columns.
    const openvdb::Mat4d m = transform.baseMap()->getAffineMap()->getMat4();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) out.index_to_world[r][c] = m(c, r);
}

// The map applied to the 8 corners of the index box [min, max + 1], as NanoVDB computes its world bbox.
void compute_world_bounds(VolumeGrid& g) {
    const Vec3d lo(g.index_min), hi = lo + Vec3d(double(g.nx), double(g.ny), double(g.nz));
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p =
            g.index_to_world_point({corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z});
        for (int a = 0; a < 3; ++a) {
            g.world_min[a] = corner == 0 ? p[a] : std::min(g.world_min[a], p[a]);
            g.world_max[a] = corner == 0 ? p[a] : std::max(g.world_max[a], p[a]);
        }
    }
}

}  // namespace

VolumeGrid read_openvdb_grid(const std::filesystem::path& path, std::string_view grid_name, MemoryBudget& budget) {
    const std::string file_name = path.string();
    return with_file(path, [&](openvdb::io::File& file) {
        const std::string name(grid_name);
        if (!file.hasGrid(name)) {
            std::string names;
            for (const std::string& n : names_in(file)) names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", n);
            if (names.empty())
                fail_in_file(file_name, fmt::format("no grid named \"{}\": the OpenVDB file has no grids", name));
            fail_in_file(file_name, fmt::format("no grid named \"{}\"; the OpenVDB file has: {}", name, names));
        }
        const openvdb::GridBase::Ptr meta = file.readGridMetadata(name);
        if (!meta->isType<openvdb::FloatGrid>())
            fail_in_file(file_name, fmt::format("grid \"{}\" holds {} values; candela reads float grids only", name,
                                                meta->valueType()));
        const std::string what = fmt::format("volume grid \"{}\"", name);
        // What the file's metadata says, checked before the tree is read.
        const auto bbox_min = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
        const auto bbox_max = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
        const auto mem_bytes = meta->getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_MEM_BYTES);
        if (bbox_min && bbox_max) {
            const openvdb::CoordBBox box(openvdb::Coord(bbox_min->value()), openvdb::Coord(bbox_max->value()));
            const uint64_t tree_bytes = mem_bytes && mem_bytes->value() > 0 ? uint64_t(mem_bytes->value()) : 0;
            if (!box.empty())
                if (auto refused = budget.charge(0, what, saturating_sum(dense_bytes(box), tree_bytes)))
                    fail_in_file(file_name, *refused);
        }

        const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
        if (!grid) fail_in_file(file_name, fmt::format("grid \"{}\" could not be read as a float grid", name));
        VolumeGrid out;
        out.name = name;
        out.background = grid->background();
        if (!std::isfinite(out.background))
            fail_in_file(file_name, fmt::format("grid \"{}\": the background is not finite", name));
        read_map(*grid, file_name, out);
        const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
        if (box.empty()) return out;
        const openvdb::Coord dim = box.dim();
        for (int a = 0; a < 3; ++a)
            if (int64_t(box.max()[a]) - box.min()[a] + 1 > INT_MAX)
                fail_in_file(file_name,
                             fmt::format("grid \"{}\" is too wide along {}; candela reads grids up to {} voxels wide",
                                         name, "xyz"[a], INT_MAX));
        if (auto refused =
                budget.charge(dense_bytes(box), fmt::format("{} ({}x{}x{} voxels)", what, dim.x(), dim.y(), dim.z()),
                              grid->memUsage()))
            fail_in_file(file_name, *refused);
        out.index_min = Vec3<int>(box.min().x(), box.min().y(), box.min().z());
        out.nx = dim.x();
        out.ny = dim.y();
        out.nz = dim.z();
        out.values.resize(out.voxel_count());
        const auto accessor = grid->getConstAccessor();
        size_t n = 0;
        for (int z = box.min().z(); z <= box.max().z(); ++z)
            for (int y = box.min().y(); y <= box.max().y(); ++y)
                for (int x = box.min().x(); x <= box.max().x(); ++x) {
                    const float v = accessor.getValue(openvdb::Coord(x, y, z));
                    if (!std::isfinite(v))
                        fail_in_file(file_name, fmt::format("grid \"{}\": voxel ({}, {}, {}) is not a finite number",
                                                            name, x, y, z));
                    out.values[n++] = v;
                }
        compute_world_bounds(out);
        return out;
    });
}

std::vector<std::string> openvdb_grid_names(const std::filesystem::path& path) {
    return with_file(path, [](openvdb::io::File& file) { return names_in(file); });
}

}  // namespace candela
