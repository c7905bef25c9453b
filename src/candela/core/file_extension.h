#pragma once
// A file's extension in lower case (".EXR" -> ".exr"): the image, texture and scene readers and
// writers choose their format by it.
#include <cctype>
#include <filesystem>
#include <string>

namespace candela {

inline std::string lower_extension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace candela
