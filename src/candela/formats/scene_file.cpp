#include "candela/formats/scene_file.h"

#include <cctype>
#include <string>

#include "candela/formats/pbrt/pbrt_scene_loader.h"

namespace candela {

bool is_pbrt_scene_file(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".pbrt";
}

Scene load_scene_file(const std::filesystem::path& file, const LoadOptions& options) {
    return is_pbrt_scene_file(file) ? pbrt::load_pbrt_scene(file, options) : load_scene(file, options);
}

}  // namespace candela
