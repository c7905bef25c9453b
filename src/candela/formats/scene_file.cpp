#include "candela/formats/scene_file.h"

#include <cctype>
#include <string>

#include "candela/core/file_extension.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"

namespace candela {

bool is_pbrt_scene_file(const std::filesystem::path& file) {
    // "scene.pbrt", or "scene.pbrt.gz" (gzip-compressed, as pbrt-v4 reads it).
    const std::string ext = lower_extension(file);
    return ext == ".pbrt" || (ext == ".gz" && lower_extension(file.stem()) == ".pbrt");
}

Scene load_scene_file(const std::filesystem::path& file, const LoadOptions& options) {
    return is_pbrt_scene_file(file) ? pbrt::load_pbrt_scene(file, options) : load_scene(file, options);
}

}  // namespace candela
