#pragma once
// The scene settings a render job may override (the command line's flags, later Python's
// keywords), as one typed value, and the checkpoint's settings a resumed job takes in their place.
// The job applies them to the loaded scene once, before the memory check and the content hash
// (job.h). Messages name each override by its command-line flag (--spp, --resolution, ...).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "candela/film/aov_layers.h"
#include "candela/scene/render_settings.h"

namespace candela {

struct Scene;
struct RenderIdentity;

struct Resolution {
    int width = 0;
    int height = 0;
    bool operator==(const Resolution&) const = default;
};

// Every member is optional: nothing given keeps the scene file's setting.
struct RenderOverrides {
    std::optional<int> spp = {};  // --spp: >= 1; with adaptive sampling the most a pixel takes
    std::optional<uint64_t> seed = {};              // --seed
    std::optional<Resolution> resolution = {};      // --resolution: each side 1..32768
    std::optional<IntegratorType> integrator = {};  // --integrator
    std::optional<SamplerType> sampler = {};        // --sampler
    std::optional<bool> spectral = {};              // --spectral (true), --rgb (false)
    std::optional<double> iso = {};                 // --iso: > 0
    std::optional<double> exposure_time = {};       // --exposure-time: seconds > 0
    std::optional<double> white_balance = {};       // --white-balance: 0 or kelvin >= 1000
    std::optional<AovLayers> aovs = {};             // --aov
    std::optional<double> noise_threshold = {};     // --noise-threshold: [0, 1); 0 turns it off
    std::optional<int> min_spp = {};                // --min-spp: [2, 2^24], with adaptive sampling
    // --target-error: stop at this estimated relMSE (> 0). A render option, not a scene setting:
    // it does not enter the content hash (it changes when a render stops, not its samples).
    std::optional<double> target_error = {};
};

// Checks each given value as the scene file's key is checked and applies it to `scene`. Throws
// SceneError naming the flag (e.g. "--spp: expected an integer >= 1, got 0").
void apply_overrides(const RenderOverrides& overrides, Scene& scene);

// A flag's value the caller got wrong: thrown as a SceneError without a file, so that the command
// line (and Python) report it as they report the scene file's errors.
[[noreturn]] void bad_flag(const std::string& message);

// The integrator, the sampler and the AOV layers that a flag or keyword `flag` names (`--sampler`
// on the command line, `sampler` in Python): bad_flag naming `flag` for an unknown name (listing
// the known ones) or, for the layers, a repeated one.
IntegratorType integrator_override(std::string_view flag, const std::string& name);
SamplerType sampler_override(std::string_view flag, const std::string& name);
AovLayers aov_layers_override(std::string_view flag, const std::vector<std::string>& names);

// Resuming: the settings a checkpoint's identity records (resolution, seed, sampler, integrator,
// AOV layers, adaptive sampling) and, for a shard's part file, its target spp (`target_spp` > 0),
// put into `overrides` where the caller gave none, so that the resumed render is the one that
// was stopped. A given override that contradicts the checkpoint throws SceneError naming the
// checkpoint `file` and the flag. `scene` is the loaded scene before any override (its crop
// window turns the checkpoint's film size back into a camera resolution).
void take_checkpoint_settings(const std::filesystem::path& file, const RenderIdentity& checkpoint,
                              uint32_t target_spp, const Scene& scene, RenderOverrides& overrides);

}  // namespace candela
