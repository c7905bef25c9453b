#pragma once
// A scene's content hash: 64 bits that change with everything deciding its image except the
// sample count. Checkpoints carry it, so that a render only continues from a checkpoint of the
// same scene (a resumed render may ask for more samples than the interrupted one).
//
// Hashed, in this order:
//  - the scene file's JSON, parsed and written back canonically (keys sorted, no whitespace), so
//    formatting and key order do not count, with /sampler/spp removed;
//  - the bytes of every file the scene names (each string under a "file" key: meshes,
//    environment images), resolved against the scene's folder as the loader resolves them;
//  - the settings the command line can override, as `scene` holds them after the overrides:
//    resolution, integrator, sampler type and seed, the film's iso, exposure_time and
//    white_balance. (A new override that changes the image must be added here.)
#include <cstdint>
#include <string_view>

#include "candela/scene/scene.h"

namespace candela {

// The content hash of `scene`, loaded from `json_text`; files are resolved against the folder of
// scene.file. Throws SceneError naming a referenced file that cannot be read.
uint64_t scene_content_hash(std::string_view json_text, const Scene& scene);

// The same, reading the JSON text from scene.file, or for a translated scene (a pbrt-v4 file)
// from scene.translated_json, with scene.inline_file_hashes standing for the files it names that
// were held in memory.
uint64_t scene_content_hash(const Scene& scene);

}  // namespace candela
