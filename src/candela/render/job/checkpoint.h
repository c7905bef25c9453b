#pragma once
// Checkpoint files: a render's accumulated state, to continue it later (candela render SCENE
// --resume FILE) with a bit-identical result.
//
// Format versions 1 to 4: version 2 is written for films with weight sums (film/film.h: the
// tabulated pixel filters) and differs only in the sums, which then have a fourth value per pixel,
// its weight sum. Version 3 is a shard's part file (shard_part.h, docs/CLUSTER.md): this header,
// then the shard, target spp, tile size, values per pixel, film flags and output settings, then
// only the part's pixels; read_checkpoint refuses it (resume it with --shard, merge it with
// candela merge), read_shard_part reads it. Version 4 is written for films with AOV layers
// (film/aov_layers.h) or statistics (film.h: adaptive sampling, --target-error, the variance and
// spp outputs) and for renders with adaptive sampling: its header describes the film's values and
// the adaptive settings, and each pixel has the film's values_per_pixel() values in
// Film::read_region's order (r g b, the weight sum if weighted, the AOV sums, then the sums of
// squares and the sample count). Other films are written as versions 1 and 2, byte for byte as
// before.
// Integers are unsigned little-endian; a string is a u32 byte count (at most 64) and its bytes;
// sums are IEEE 754 binary64, little-endian.
//
//   magic            8 bytes  "CNDLCKPT"
//   format version   u32      1, or 2 for a film with weight sums (3: a part file), 4 (below)
//   candela version  string   CANDELA_VERSION of the program that wrote it
//   integrator       string   its name (path, bsdf, ...)
//   sampler          string   its name (independent, sobol)
//   content hash     u64      scene_content_hash (scene/content_hash.h)
//   seed             u64
//   width, height    u32, u32 1..32768 each
//   samples done     u32      per pixel
//   dropped samples  u64      NaN/Inf samples among them, counted as zero
//   version 4 only:
//     film values    u32      bit 0: weight sums; bit 1: statistics (film.h: sums of squares,
//                             counts, rays, prefix sums); bit 2: set with bit 1 by builds whose
//                             statistics have 13 values (earlier ones had 4: refused);
//                             bits 8..13: the AOV layers, bit 8 + i for AovLayer(i) (albedo,
//                             normal, depth, position, variance, spp)
//     adaptive       u32, u32 sampler.adaptive's min_spp and the threshold's binary32 bits; 0, 0
//                             without adaptive sampling
//   sums             f64 x 3 x width x height: per pixel, row-major from the top left, r g b,
//                             exactly the Film's sums; version 2: f64 x 4, r g b and the
//                             pixel's weight sum; version 4: f64 x values_per_pixel()
//   checksum         u64      Hash64 (core/hash64.h) of every byte before it
//
// Files are written atomically (a temporary file, then a rename), so a crash or a second
// Ctrl-C never leaves a half-written checkpoint in place of a good one.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "candela/scene/render_settings.h"

#include "candela/render/render_state.h"

namespace candela {

struct Scene;

// What must be the same for a checkpoint to continue a render.
struct RenderIdentity {
    std::string candela_version;
    std::string integrator;
    std::string sampler;
    uint64_t content_hash = 0;
    uint64_t seed = 0;
    int width = 0;
    int height = 0;
    uint32_t aov_layers = 0;  // AovLayers::mask() of the film's AOV layers (0: none)
    std::optional<AdaptiveSettings> adaptive;  // sampler.adaptive; none in versions 1 to 3
};

struct Checkpoint {
    RenderIdentity identity;
    RenderState state;
};

// The identity of rendering `scene` (after command-line overrides) with this candela;
// `content_hash` is scene_content_hash(scene). The resolution is the film's: the crop window's.
RenderIdentity render_identity(const Scene& scene, uint64_t content_hash);

// Writes `state` with `identity` to `file`, atomically. Throws SceneError naming the file when
// it cannot be written.
void write_checkpoint(const std::filesystem::path& file, const RenderIdentity& identity, const RenderState& state);

// Reads a checkpoint (version 1 or 2). A missing, unreadable, foreign (bad magic), newer-format,
// truncated or corrupt (checksum, sizes, non-finite sums) file, or a shard's part file (version
// 3), throws SceneError naming the file and what is wrong.
Checkpoint read_checkpoint(const std::filesystem::path& file);

// Throws SceneError naming `file` and the first thing in which the checkpoint's identity differs
// from the render's: candela version, resolution, seed, sampler, integrator, AOV layers, adaptive
// sampling, then the scene content (the scene file or a file it names).
void check_checkpoint_matches(const std::filesystem::path& file, const RenderIdentity& checkpoint,
                              const RenderIdentity& render);

}  // namespace candela
