#pragma once
// How much memory a scene will need to render, estimated before anything large is allocated, so
// that a scene too big for the machine fails with a message saying what it needs and what there
// is, instead of being killed by the kernel hours later (or at once, in an allocation of a
// 100000x100000 film). The estimates are upper bounds from what candela stores per pixel, vertex
// and triangle, with Embree's BVH measured (docs/SCENE_FORMAT.md, "Limits").
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "candela/film/aov_layers.h"

namespace candela {

struct Scene;

// What the process may allocate: the smallest of the physical memory, the cgroup (container)
// memory limit and the address-space limit (ulimit -v), with where that limit comes from.
struct MemoryLimit {
    uint64_t bytes = 0;
    std::string source;  // "physical memory", "the cgroup memory limit", "the address-space limit (ulimit -v)"

    static MemoryLimit of_this_process();
};

// --- estimates, in bytes
// A film of width x height pixels: the per-pixel double sums, the resolved float image, and one
// encoded output (or checkpoint) in flight.
uint64_t film_memory_bytes(int width, int height);
// The AOV layers of such a film (film/aov_layers.h): their double sums in both films of a pass,
// and per layer the resolved float image and one encoded output in flight. 0 for none.
uint64_t aov_memory_bytes(int width, int height, AovLayers aovs);
// The statistics a film keeps for adaptive sampling or a noise target (film/film.h): sums of
// squares, counts, rays and prefix sums, in both films of a pass.
uint64_t film_statistics_memory_bytes(int width, int height);
// A triangle mesh as rendered: its arrays, Embree's copies and BVH, and the light tables it
// gets if it emits.
uint64_t mesh_memory_bytes(uint64_t vertices, uint64_t triangles, bool normals, bool uvs);
// An instance of an object (geometry/instance.h): its transform and Embree's instance record, and
// its share of the top-level BVH; the object's shapes are counted once, as any shape.
uint64_t instance_memory_bytes();
// What loading a mesh file needs besides the mesh itself (the OBJ reader's tables), freed after.
uint64_t mesh_loading_memory_bytes(uint64_t vertices, uint64_t corners);
// An environment map of width x height texels: the image, the light's copy and its sampling tables.
uint64_t environment_memory_bytes(int width, int height);
// A texture image of width x height texels, `channels` values each of `bytes_per_channel` bytes
// (1 for 8-bit files, kept as bytes; 4 for floats), with its decoding table.
uint64_t texture_memory_bytes(int width, int height, int channels, int bytes_per_channel);
// What reading such an image needs besides its texels, freed after: the file's bytes and the
// decoder's own copy of the texels (at their bit depth in the file: 1 or 2 bytes).
uint64_t texture_loading_memory_bytes(uint64_t file_bytes, int width, int height, int channels,
                                      int bytes_per_channel);
// A grid medium (media/grid_medium.h, rgb_grid_medium.h) of `voxels` samples in each of
// `float_grids` float grids (density, temperature, Le_scale) and `rgb_grids` RGB grids (a voxel's
// RGB and its spectrum), with its majorant grids (at most two, of `majorant_res`^3 cells: 16 for
// uniformgrid and rgbgrid, 16 to 64 for NanoVDB and OpenVDB media, media/majorant_grid.h) and,
// `blackbody`, its blackbody colour table.
uint64_t grid_medium_memory_bytes(uint64_t voxels, int float_grids, int rgb_grids, bool blackbody,
                                  int majorant_res = 16);
// A loaded scene at its camera resolution: film, meshes, environment, texture images and medium
// grids.
// `statistics`: the film keeps statistics whatever the scene says (--target-error asks for them);
// adaptive sampling and the variance and spp layers are charged from the scene itself.
uint64_t scene_memory_bytes(const Scene& scene, bool statistics = false);

// "512 B", "1.5 KiB", "23.4 GiB".
std::string format_bytes(uint64_t bytes);
// "4096", "512M", "8G", "1T" (K, M, G, T: powers of 1024; an "iB" or "B" after them is allowed);
// nothing when malformed, zero or beyond 64 bits.
std::optional<uint64_t> parse_byte_count(std::string_view text);

// A running total of what a scene needs, checked against a limit as the scene is loaded.
class MemoryBudget {
  public:
    explicit MemoryBudget(MemoryLimit limit) : limit_(std::move(limit)) {}

    // Adds `bytes` for `what` ("a 640x480 film"), plus `transient` bytes needed only while it
    // is made. Returns nothing when the total fits, else the message that says why it does not
    // (and adds nothing).
    std::optional<std::string> charge(uint64_t bytes, std::string_view what, uint64_t transient = 0);

    uint64_t used() const { return used_; }
    const MemoryLimit& limit() const { return limit_; }

  private:
    MemoryLimit limit_;
    uint64_t used_ = 0;
};

// The loaded scene as it will render (at its camera resolution, perhaps overridden since it was
// loaded) against `limit`: the message when it does not fit.
// `statistics` as for scene_memory_bytes.
std::optional<std::string> memory_refusal(const Scene& scene, const MemoryLimit& limit, bool statistics = false);

}  // namespace candela
