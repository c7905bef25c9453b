#pragma once
// The pbrt-v4 scene-file parser: tokenizes a file as it streams it (bounded memory however large
// the file), reads directives and their parameter lists, follows Include and Import (paths
// relative to the including file's folder, else to the main file's as pbrt-v4; a cycle is an error), and calls the Target for each
// directive. Syntax errors throw SceneError located as `file:line:col: message`, with the chain
// of includes named (pbrt_location.h).
#include <cstddef>
#include <filesystem>
#include <string_view>

#include "candela/formats/pbrt/pbrt_target.h"

namespace candela::pbrt {

struct ParseOptions {
    size_t chunk_size = size_t(1) << 20;  // bytes read at a time from each open file
    int max_include_depth = 64;           // files open at once: the main file and its includes
    size_t max_token_bytes = size_t(64) << 20;  // a longer word or string is an error (memory bound)
};

// Parses `file` (as the user named it; messages show it so) and everything it includes.
void parse_file(const std::filesystem::path& file, Target& target, const ParseOptions& options = {});

// Parses text held in memory, as if it were the file `name` (its folder resolves Includes).
void parse_string(std::string_view text, const std::filesystem::path& name, Target& target,
                  const ParseOptions& options = {});

}  // namespace candela::pbrt
