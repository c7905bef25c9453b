#pragma once
// A walk over an OpenEXR file's header attributes, made before OpenEXR's C++ reader sees the file
// (exr_file.cpp). That reader (3.1) allocates each attribute at the size the file declares, and
// reads some types by their content instead of that size, so a corrupt file of a few hundred
// bytes could make it allocate 2 GiB (found by fuzz/exr_fuzzer.cpp).
#include <filesystem>

namespace candela::image_formats {

// Throws SceneError naming `file` unless every attribute of every header (several when
// `multi_part`) fits in the file and holds exactly the bytes it declares, as the C++ reader
// would read them. A file cut short inside its headers is left to OpenEXR's own error.
void check_exr_attributes(const std::filesystem::path& file, bool multi_part);

}  // namespace candela::image_formats
