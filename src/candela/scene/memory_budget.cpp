#include "candela/scene/memory_budget.h"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <string>
#include <type_traits>

#include "candela/core/saturating.h"
#include "candela/film/film.h"
#include "candela/geometry/accelerator.h"
#include "candela/media/medium.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

// Bytes per pixel: the film's three double sums twice (24 + 24: a pass reads the saved sums and
// writes a second film, swapped when the pass is complete, so a stop never saves half a pass), the
// resolved float image (12), and one output image being encoded (12). A resume also holds the
// checkpoint's sums while reading them (24), which the same bound covers with the output's room.
constexpr uint64_t kFilmBytesPerPixel = 24 + 24 + 12 + 12;
// With statistics: three sums of squares, the count and the rays (5 doubles) and the prefix sums
// (8 floats): 72 bytes in each of the two films.
constexpr uint64_t kFilmStatisticsBytesPerPixel = 72 + 72;
static_assert(kFilmStatisticsBytesPerPixel == 2 * (5 * sizeof(double) + sizeof(PrefixSums)));
// Per vertex: the position and Embree's copy of it; normals and uvs when the mesh has them.
constexpr uint64_t kPositionBytes = 12 + 12;
constexpr uint64_t kNormalBytes = 12;
constexpr uint64_t kUvBytes = 8;
// Per triangle: its three indices and Embree's copy (12 + 12), the BVH with its build-time
// references (96; a grid of 2M triangles peaked at about 70 B per triangle beyond the mesh, its
// copies and the file), and an emitting mesh's area table and normals (8 + 12); plus the winding
// normal hits read, in meshes small enough to keep one (geometry/accelerator.h).
constexpr uint64_t kTriangleBytes = 12 + 12 + 96 + 8 + 12;
constexpr uint64_t kNormalTableBytes = 12;
// Per instance: candela's Instance (a float matrix and its inverse, 104), Embree's instance
// geometry with its matrices, and the instance's share of the top-level BVH: 10,000 instances of
// one object added about 540 B each to the resident set (tests/geometry/instance_memory_test.cpp).
constexpr uint64_t kInstanceBytes = 640;
// While an OBJ loads: tinyobjloader's attribute arrays (up to 32 B per vertex for v, vn and vt)
// and its index triples (12 B per corner), plus our corner-to-vertex hash map (about 64 B per
// corner, an upper bound on the distinct ones).
constexpr uint64_t kObjVertexLoadBytes = 32;
constexpr uint64_t kObjCornerLoadBytes = 12 + 64;
// Per environment texel: the loaded image, the light's copy (12 + 12) and its sampling tables
// (weights and CDF, 4 + 4, and row overhead rounded up).
constexpr uint64_t kEnvironmentBytesPerTexel = 12 + 12 + 12;

// The pixels (or texels) of a width x height image, saturating; negative sizes count as 0.
uint64_t pixel_count(int width, int height) {
    return saturating_product(uint64_t(std::max(width, 0)), uint64_t(std::max(height, 0)));
}

// A number from a one-line file such as /sys/fs/cgroup/memory.max ("max" means none).
std::optional<uint64_t> read_limit_file(const char* path) {
    std::ifstream in(path);
    std::string word;
    if (!(in >> word) || word == "max") return std::nullopt;
    try {
        return std::stoull(word);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

// The address space the process already uses (VmSize), which an RLIMIT_AS leaves less room to.
uint64_t virtual_size_bytes() {
    std::ifstream in("/proc/self/statm");
    uint64_t pages = 0;
    in >> pages;
    return pages * uint64_t(sysconf(_SC_PAGESIZE));
}

}  // namespace

MemoryLimit MemoryLimit::of_this_process() {
    MemoryLimit limit{saturating_product(uint64_t(sysconf(_SC_PHYS_PAGES)), uint64_t(sysconf(_SC_PAGESIZE))),
                      "this machine has"};
    auto lower = [&](std::optional<uint64_t> candidate, const char* why) {
        if (candidate && *candidate < limit.bytes) limit = {*candidate, why};
    };
    // cgroup v2, then v1 (which states "no limit" as a huge number, so it never wins).
    lower(read_limit_file("/sys/fs/cgroup/memory.max"), "the container's memory limit is");
    lower(read_limit_file("/sys/fs/cgroup/memory/memory.limit_in_bytes"), "the container's memory limit is");
    rlimit r{};
    if (getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
        lower(uint64_t(r.rlim_cur) - std::min<uint64_t>(uint64_t(r.rlim_cur), virtual_size_bytes()),
              "the address-space limit (ulimit -v) leaves");
    if (getrlimit(RLIMIT_DATA, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
        lower(uint64_t(r.rlim_cur), "the data-size limit (ulimit -d) is");
    return limit;
}

uint64_t film_memory_bytes(int width, int height) {
    return saturating_product(pixel_count(width, height), kFilmBytesPerPixel);
}

uint64_t aov_memory_bytes(int width, int height, AovLayers aovs) {
    int layers = 0;
    for (int l = 0; l < kAovLayerCount; ++l) layers += aovs.has(AovLayer(l)) ? 1 : 0;
    const uint64_t per_pixel = uint64_t(aovs.value_count()) * (8 + 8) + uint64_t(layers) * (12 + 12);
    return saturating_product(pixel_count(width, height), per_pixel);
}

uint64_t film_statistics_memory_bytes(int width, int height) {
    return saturating_product(pixel_count(width, height), kFilmStatisticsBytesPerPixel);
}

uint64_t mesh_memory_bytes(uint64_t vertices, uint64_t triangles, bool normals, bool uvs) {
    const uint64_t per_vertex = kPositionBytes + (normals ? kNormalBytes : 0) + (uvs ? kUvBytes : 0);
    const uint64_t per_triangle = kTriangleBytes + (triangles <= kMaxTrianglesWithNormalTable ? kNormalTableBytes : 0);
    return saturating_sum(saturating_product(vertices, per_vertex), saturating_product(triangles, per_triangle));
}

uint64_t instance_memory_bytes() { return kInstanceBytes; }

uint64_t mesh_loading_memory_bytes(uint64_t vertices, uint64_t corners) {
    return saturating_sum(saturating_product(vertices, kObjVertexLoadBytes),
                          saturating_product(corners, kObjCornerLoadBytes));
}

uint64_t environment_memory_bytes(int width, int height) {
    return saturating_product(pixel_count(width, height), kEnvironmentBytesPerTexel);
}

uint64_t texture_memory_bytes(int width, int height, int channels, int bytes_per_channel) {
    const uint64_t texels = pixel_count(width, height);
    const uint64_t per_texel = uint64_t(std::max(channels, 0)) * uint64_t(std::max(bytes_per_channel, 0));
    return saturating_sum(saturating_product(texels, per_texel), sizeof(TextureImage::byte_values));
}

uint64_t texture_loading_memory_bytes(uint64_t file_bytes, int width, int height, int channels,
                                      int bytes_per_channel) {
    // stb decodes 16-bit files to 2 bytes per value, which are then decoded to floats.
    const int decoded_bytes = bytes_per_channel == 1 ? 1 : 2;
    return saturating_sum(file_bytes, saturating_product(pixel_count(width, height),
                                                         uint64_t(std::max(channels, 0)) * uint64_t(decoded_bytes)));
}

uint64_t grid_medium_memory_bytes(uint64_t voxels, int float_grids, int rgb_grids, bool blackbody, int majorant_res) {
    // Two majorant grids at most (rgbgrid keeps one per colour mode); the blackbody table is
    // 4096 x 3 floats.
    const uint64_t cells = uint64_t(std::max(majorant_res, 0));
    const uint64_t majorants = 2 * cells * cells * cells * sizeof(float);
    constexpr uint64_t kBlackbody = uint64_t(BlackbodyRgbTable::kSize) * 3 * sizeof(float);
    const uint64_t per_voxel = uint64_t(float_grids) * sizeof(float) + uint64_t(rgb_grids) * (sizeof(Rgb) + sizeof(RgbSpectrum));
    return saturating_sum(saturating_product(voxels, per_voxel), majorants + (blackbody ? kBlackbody : 0));
}

namespace {

uint64_t medium_memory_bytes(const Medium& medium) {
    auto voxels = [](const auto& lattice) { return uint64_t(lattice.values.size()); };
    return visit(
        [&](const auto& m) -> uint64_t {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, GridMedium>) {
                const uint64_t n = voxels(m.density.lattice) + voxels(m.temperature.lattice) + voxels(m.Le_scale.lattice);
                return grid_medium_memory_bytes(n, 1, 0, !m.temperature.empty(), m.majorant.res);
            } else if constexpr (std::is_same_v<M, RgbGridMedium>) {
                const uint64_t n = voxels(m.sigma_a.rgb) + voxels(m.sigma_s.rgb) + voxels(m.Le.rgb);
                return grid_medium_memory_bytes(n, 0, 1, false, m.majorant_rgb.res);
            } else {
                return uint64_t(sizeof(M));
            }
        },
        medium);
}

}  // namespace

uint64_t scene_memory_bytes(const Scene& scene, bool statistics) {
    uint64_t bytes = film_memory_bytes(scene.camera.width, scene.camera.height);
    bytes = saturating_sum(bytes, aov_memory_bytes(scene.camera.width, scene.camera.height, scene.film.aovs));
    if (statistics || scene.sampler.adaptive || film_needs_statistics(scene.film.aovs))
        bytes = saturating_sum(bytes, film_statistics_memory_bytes(scene.camera.width, scene.camera.height));
    for (const TriangleMesh& m : scene.meshes)
        bytes = saturating_sum(
            bytes, mesh_memory_bytes(m.positions.size(), m.triangle_count(), !m.normals.empty(), !m.uvs.empty()));
    bytes = saturating_sum(bytes, saturating_product(scene.instances.size(), instance_memory_bytes()));
    if (scene.environment)
        bytes = saturating_sum(
            bytes, environment_memory_bytes(scene.environment->radiance.width, scene.environment->radiance.height));
    for (const Medium& m : scene.media) bytes = saturating_sum(bytes, medium_memory_bytes(m));
    return saturating_sum(bytes, scene.textures.image_memory_bytes());
}

std::string format_bytes(uint64_t bytes) {
    constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    if (bytes < 1024) return fmt::format("{} B", bytes);
    double value = double(bytes) / 1024.0;
    size_t unit = 0;
    while (value >= 1024.0 && unit + 1 < std::size(kUnits)) {
        value /= 1024.0;
        ++unit;
    }
    return fmt::format("{:.1f} {}", value, kUnits[unit]);
}

std::optional<uint64_t> parse_byte_count(std::string_view text) {
    uint64_t count = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), count);
    if (ec != std::errc() || end == text.data()) return std::nullopt;
    std::string_view unit = text.substr(size_t(end - text.data()));
    if (unit.ends_with("iB")) {
        unit.remove_suffix(2);
    } else if (unit.ends_with('B')) {
        unit.remove_suffix(1);
    }
    constexpr std::string_view kUnits = "KMGT";
    int shift = 0;
    if (!unit.empty()) {
        const size_t k = kUnits.find(char(std::toupper(static_cast<unsigned char>(unit[0]))));
        if (unit.size() != 1 || k == std::string_view::npos) return std::nullopt;
        shift = 10 * int(k + 1);
    }
    if (count == 0 || count > (UINT64_MAX >> shift)) return std::nullopt;
    return count << shift;
}

std::optional<std::string> memory_refusal(const Scene& scene, const MemoryLimit& limit, bool statistics) {
    uint64_t triangles = 0;
    for (const TriangleMesh& m : scene.meshes) triangles += m.triangle_count();
    MemoryBudget budget(limit);
    return budget.charge(scene_memory_bytes(scene, statistics),
                         fmt::format("the scene at {}x{} pixels ({} triangles{}{})", scene.camera.width,
                                     scene.camera.height, triangles,
                                     scene.environment ? ", an environment map" : "",
                                     scene.texture_files.empty()
                                         ? std::string()
                                         : fmt::format(", {} texture images", scene.texture_files.size())));
}

std::optional<std::string> MemoryBudget::charge(uint64_t bytes, std::string_view what, uint64_t transient) {
    const uint64_t needed = saturating_sum(bytes, transient);
    const uint64_t total = saturating_sum(used_, needed);
    if (total <= limit_.bytes) {
        used_ = saturating_sum(used_, bytes);
        return std::nullopt;
    }
    // The total only when it says more than the part.
    const std::string rest = format_bytes(total) == format_bytes(needed)
                                 ? std::string()
                                 : fmt::format(" ({} with what the scene holds already)", format_bytes(total));
    return fmt::format("{} needs about {} of memory{}, but {} {}", what, format_bytes(needed), rest,
                       limit_.source, format_bytes(limit_.bytes));
}

}  // namespace candela
