#pragma once
// All-or-nothing file writes: the contents go to a temporary file in the destination's folder
// (same file system, so the final rename is atomic), which is flushed to disk and then renamed
// over the destination. A crash or a failed write never leaves a half-written file behind, and
// readers of the destination see either the old file or the complete new one.
#include <filesystem>
#include <functional>
#include <string_view>

namespace candela {

// Calls `write` with a fresh temporary path next to `destination` (a hidden name like
// `.image.png.tmp.<pid>.<n>`), then renames it over `destination`. On any failure the temporary
// file is removed and a SceneError naming `destination` is thrown; a SceneError or RenderError
// thrown by `write` passes through unchanged (after the cleanup), other std::exceptions are
// wrapped into a SceneError with their message.
void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(const std::filesystem::path& temporary)>& write);

// Writes `contents` (text or binary bytes) to `destination` atomically, as above.
void write_contents_atomically(const std::filesystem::path& destination, std::string_view contents);

}  // namespace candela
