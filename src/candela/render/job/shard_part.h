#pragma once
// Shard part files: what `candela render SCENE --shard I/N -o part-I.ckpt` writes, `--resume`
// continues and `candela merge` puts together (shard_merge.h). A checkpoint of one part of the
// image (shard.h), format version 3 of the checkpoint files (checkpoint.h has versions 1 and 2):
// the same common header, then what merging needs without the scene, then only the part's
// pixels. Integers are unsigned little-endian, floats their IEEE 754 bits.
//
//   magic ... dropped samples   as in checkpoint.h, with format version 3; width and height are
//                               the whole film's (the crop window's), samples done and dropped
//                               samples the part's pixels'
//   shard index      u32   I, 1..N
//   shard count      u32   N, 1..kMaxShards
//   target spp       u32   the samples per pixel the render asks for (merge refuses a part
//                          with fewer done)
//   tile size        u32   kShardTileSize (16), the side of the tiles shard_tiles cuts
//   values per pixel u32   Film::values_per_pixel() of the film that rendered it
//   film flags       u32   bit 0: the film keeps weight sums (a tabulated filter); bit 1: it keeps
//                          statistics (film.h: adaptive sampling, the variance and spp layers);
//                          bits 8..: its AOV layers' mask (film/aov_layers.h); others 0
//   tonemap          u32   film.tonemap: 0 clamp, 1 exposure, 2 reinhard, 3 aces
//   exposure         f32   film.exposure
//   transfer         u32   film.transfer: 0 srgb, 1 gamma
//   gamma            f32   film.gamma
//   adaptive   u32, u32    only with statistics (bit 1): sampler.adaptive's min_spp and the
//                          threshold's binary32 bits; 0, 0 without adaptive sampling. (Parts
//                          without statistics, all that earlier candelas wrote, lack the field.)
//   pixel count      u64   the part's pixels: the sum of its tiles' pixels
//   values           f64 x values per pixel x pixel count: the part's tiles in shard_tiles
//                          order (row-major), each tile's pixels row-major, each pixel's values as
//                          Film::read_region gives them (r g b sums, the weight sum, the AOV sums,
//                          then the sums of squares and the sample count)
//   checksum         u64   Hash64 (core/hash64.h) of every byte before it
//
// Written atomically, as checkpoints are.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "candela/film/film_settings.h"
#include "candela/render/job/checkpoint.h"
#include "candela/render/render_state.h"
#include "candela/render/shard.h"

namespace candela {

struct Scene;

// What a part file says besides a checkpoint's identity and sample counts.
struct PartInfo {
    Shard shard;
    uint32_t target_spp = 0;
    // What write_image reads for tone-mapped outputs: tonemap, exposure, transfer, gamma (the rest
    // keep their defaults).
    FilmSettings output;
};

// A part file's contents.
struct ShardPart {
    RenderIdentity identity;     // with the adaptive settings (none without statistics)
    PartInfo info;
    bool weighted = false;       // the film keeps weight sums
    bool statistics = false;     // the film keeps sums of squares and sample counts
    AovLayers aovs;              // the film's AOV layers (also in identity.aov_layers)
    int values_per_pixel = 0;    // Film::values_per_pixel()
    uint32_t samples_done = 0;   // per pixel of the part
    uint64_t dropped_samples = 0;
    std::vector<double> values;  // the part's pixels' values, as the file holds them
};

// The part `shard` of rendering `scene` (after command-line overrides).
PartInfo part_info(const Scene& scene, Shard shard);

// Writes the pixels of part info.shard of `state`'s film with `identity`, atomically. Throws
// SceneError naming the file when it cannot be written.
void write_shard_part(const std::filesystem::path& file, const RenderIdentity& identity, const PartInfo& info,
                      const RenderState& state);

// Reads a part file. A missing, unreadable, foreign, newer-format, truncated or corrupt file, and a
// checkpoint of the whole image (versions 1 and 2), throw SceneError naming the file.
ShardPart read_shard_part(const std::filesystem::path& file);

// Copies the part's values into its pixels of `film`, which is identity's size and keeps
// part.values_per_pixel values per pixel.
void put_part_values(const ShardPart& part, Film& film);

// Throws SceneError naming `file` unless `part` continues the render of part `shard` with
// `identity` on `film` (make_film of the scene): the same render (check_checkpoint_matches), the
// same part, the same values per pixel.
void check_part_matches(const std::filesystem::path& file, const ShardPart& part, const RenderIdentity& identity,
                        Shard shard, const Film& film);

}  // namespace candela
