#include "render_stats.h"

#include <fmt/format.h>
#include <sys/resource.h>

#include <string>

#include "candela/core/atomic_file.h"

namespace candela::cli {

namespace {

// The process's peak resident memory so far (Linux reports ru_maxrss in KiB).
uint64_t peak_rss_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return uint64_t(usage.ru_maxrss) * 1024;
}

}  // namespace

void write_stats(const std::filesystem::path& file, const RenderJobResult& r) {
    const RenderStats& s = r.render.stats;
    const std::string json = fmt::format(
        "{{\"integrator\": \"{}\", \"width\": {}, \"height\": {}, \"spp\": {}, \"threads\": {}, \"ranks\": {},\n"
        " \"passes\": {}, \"mpi_bytes_to_rank0\": {}, \"mpi_bytes_from_rank0\": {},\n"
        " \"render_seconds\": {:.6f}, \"build_seconds\": {:.6f}, \"samples\": {}, \"dropped_samples\": {},\n"
        " \"load_seconds\": {:.6f}, \"startup_seconds\": {:.6f}, \"peak_rss_bytes\": {},\n"
        " \"rays\": {{\"camera\": {}, \"bounce\": {}, \"shadow\": {}, \"total\": {}}}}}\n",
        r.integrator, r.width, r.height, r.spp, s.threads, r.ranks, s.passes, r.bytes_to_rank0, r.bytes_from_rank0,
        s.render_seconds, s.build_seconds, s.samples, s.dropped_samples, r.load_seconds, r.startup_seconds,
        peak_rss_bytes(), s.rays.camera, s.rays.bounce, s.rays.shadow, s.rays.total());
    write_contents_atomically(file, json);
}

}  // namespace candela::cli
