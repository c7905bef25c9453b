#pragma once
// Merging shard parts (shard_part.h) into the render of the whole image: each part's pixels go
// into one film, which then holds exactly the sums one render of the whole image would (each
// pixel's samples were summed in index order by the part that has it), so its image is bit for
// bit that render's. `candela merge` is this plus write_image.
//
// Refused, with a SceneError naming the file(s): a file that is not a part (damaged, foreign, a
// checkpoint of the whole image: read_shard_part); a part of another render than the first
// file's (candela version, shard count, resolution, seed, sampler, integrator, target spp, adaptive
// settings, scene content, film layout, output settings); the same part twice; an incomplete part
// (fewer samples done than its target spp, and with adaptive sampling some of its pixels still
// sampling); parts without adaptive sampling with different sample counts; a missing part.
//
// Adaptive parts: each block's decisions read only its own pixels (adaptive_sampling.h), so a part
// stops where its own blocks have all stopped, and the merged film is the whole render's; its
// samples done are the largest part's, where the whole render would have stopped.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "candela/film/film_settings.h"
#include "candela/render/job/checkpoint.h"
#include "candela/render/render_state.h"
#include "candela/render/shard.h"

namespace candela {

struct MergedRender {
    RenderIdentity identity;
    int parts = 0;            // the shard count N: parts 1..N were merged
    uint32_t target_spp = 0;
    FilmSettings output;      // the parts' tonemap, exposure, transfer, gamma, for write_image
    RenderState state;        // the whole film; dropped samples summed over the parts
};

// Reads the part files (one at a time: memory for the film and one part) and merges them.
MergedRender merge_shard_parts(const std::vector<std::filesystem::path>& files);

}  // namespace candela
