#include "candela/scene/content_hash.h"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "candela/core/error.h"
#include "candela/core/hash64.h"
#include "candela/scene/enum_names.h"

namespace candela {

namespace {

namespace fs = std::filesystem;
// Sorted keys (std::map), unlike the loader's ordered_json: the canonical form ignores key order.
using Json = nlohmann::json;

[[noreturn]] void fail(const fs::path& file, const std::string& message) {
    throw SceneError(SourceLocation{file.string(), 0, 0, ""}, message);
}

// Adds the bytes of `file`, read in blocks (meshes may be large).
void add_file_bytes(Hash64& hash, const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) fail(file, fmt::format("cannot read for the scene's content hash: {}", std::strerror(errno)));
    std::array<char, 1 << 16> block;
    while (in) {
        in.read(block.data(), std::streamsize(block.size()));
        hash.add(block.data(), size_t(in.gcount()));
    }
    if (in.bad()) fail(file, "cannot read for the scene's content hash");
}

// Every string under a "file" key (meshes, images) or a "spectrum_file" key (.spd spectra),
// depth first in the canonical key order.
void add_referenced_files(Hash64& hash, const Json& value, const fs::path& folder,
                          const std::map<std::string, uint64_t>& inline_files) {
    if (value.is_object()) {
        for (const auto& [key, member] : value.items()) {
            if ((key == "file" || key == "spectrum_file") && member.is_string()) {
                const std::string name = member.get<std::string>();
                hash.add_field(name);
                if (auto it = inline_files.find(name); it != inline_files.end())
                    hash.add_u64(it->second);
                else
                    add_file_bytes(hash, folder / fs::path(name));  // an absolute name stays as it is
            } else {
                add_referenced_files(hash, member, folder, inline_files);
            }
        }
    } else if (value.is_array()) {
        for (const Json& element : value) add_referenced_files(hash, element, folder, inline_files);
    }
}

std::string read_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) fail(file, fmt::format("cannot read for the scene's content hash: {}", std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    return std::move(text).str();
}

}  // namespace

uint64_t scene_content_hash(std::string_view json_text, const Scene& scene) {
    Json json;
    try {
        json = Json::parse(json_text);
    } catch (const Json::exception& e) {
        // load_scene accepted this text, so only a file changed since loading gets here.
        fail(scene.file, fmt::format("cannot parse for the scene's content hash: {}", e.what()));
    }
    if (json.is_object() && json.contains("sampler") && json["sampler"].is_object()) json["sampler"].erase("spp");

    Hash64 hash;
    hash.add_field("candela scene content v1");
    hash.add_field(json.dump(-1, ' ', false, Json::error_handler_t::replace));
    add_referenced_files(hash, json, scene.file.parent_path(), scene.inline_file_hashes);
    hash.add_u64(uint64_t(scene.camera.width));
    hash.add_u64(uint64_t(scene.camera.height));
    hash.add_field(integrator_type_name(scene.integrator.type));
    // Only when set, so that RGB renders keep the hashes of their checkpoints from before the
    // spectral mode (the flag may come from --spectral, which the JSON text does not show).
    if (scene.integrator.spectral) hash.add_field("spectral");
    hash.add_field(sampler_type_name(scene.sampler.type));
    hash.add_u64(scene.sampler.seed);
    // Adaptive sampling (the scene key or --noise-threshold, --min-spp): only when on, so that
    // other renders keep their checkpoints' hashes.
    if (const auto& a = scene.sampler.adaptive) {
        hash.add_field("adaptive");
        hash.add_u64(std::bit_cast<uint32_t>(a->threshold));
        hash.add_u64(uint64_t(a->min_spp));
    }
    // The sensor (--iso, --exposure-time, --white-balance), applied to every sample: only when
    // not pbrt-v4's defaults, so that checkpoints from before these keys keep their hashes.
    const FilmSettings defaults;
    if (scene.film.iso != defaults.iso || scene.film.exposure_time != defaults.exposure_time ||
        scene.film.white_balance != defaults.white_balance) {
        hash.add_field("sensor");
        for (float v : {scene.film.iso, scene.film.exposure_time, scene.film.white_balance})
            hash.add_u64(std::bit_cast<uint32_t>(v));
    }
    // The AOV layers (film.aovs or --aov) change what the film sums per pixel: only when some are
    // asked for, so that renders without AOVs keep their hashes.
    if (!scene.film.aovs.empty()) {
        hash.add_field("aovs");
        hash.add_u64(scene.film.aovs.mask());
    }
    return hash.value();
}

uint64_t scene_content_hash(const Scene& scene) {
    return scene_content_hash(scene.translated_json.empty() ? read_text(scene.file) : scene.translated_json, scene);
}

}  // namespace candela
