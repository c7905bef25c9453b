#pragma once
// `candela render --stats FILE`: the render's statistics as JSON, for scripts (bench/run.sh) that
// should not parse the summary line.
#include <filesystem>

#include "candela/render/job/job.h"

namespace candela::cli {

// Writes `result`'s statistics, with this process's peak resident memory, to `file` (atomically).
void write_stats(const std::filesystem::path& file, const RenderJobResult& result);

}  // namespace candela::cli
