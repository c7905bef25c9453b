#include "candela/render/job/job_files.h"

#include <bit>
#include <utility>

#include "candela/core/error.h"
#include "candela/render/frame_setup.h"
#include "candela/render/job/checkpoint_codec.h"
#include "candela/render/pass_engine.h"
#include "candela/scene/scene.h"

#if CANDELA_HAVE_MPI
#include "candela/distributed/mpi_session.h"
#endif

namespace candela {

namespace fs = std::filesystem;

ResumedFile read_resumed_file(const fs::path& file, bool shard) {
    ResumedFile r;
    if (shard) {
        r.part = read_shard_part(file);
        r.identity = r.part->identity;
        r.target_spp = r.part->info.target_spp;
    } else {
        r.checkpoint = read_checkpoint(file);
        r.identity = r.checkpoint->identity;
    }
    return r;
}

#if CANDELA_HAVE_MPI
void share_resumed_settings(const MpiSession& session, std::optional<ResumedFile>& resumed) {
    using namespace checkpoint_codec;
    Writer w;
    if (session.rank() == 0) {
        const RenderIdentity& id = resumed->identity;
        write_identity_start(w, id);
        for (uint32_t v : {uint32_t(id.width), uint32_t(id.height), id.aov_layers, uint32_t(id.adaptive.has_value()),
                           id.adaptive ? std::bit_cast<uint32_t>(id.adaptive->threshold) : 0u,
                           id.adaptive ? uint32_t(id.adaptive->min_spp) : 0u, resumed->target_spp})
            w.u32(v);
    }
    const std::string bytes = session.broadcast(std::move(w.out));
    if (session.rank() == 0) return;
    Reader r(bytes);
    ResumedFile settings;
    RenderIdentity& id = settings.identity;
    read_identity_start(r, id);
    id.width = int(r.u32());
    id.height = int(r.u32());
    id.aov_layers = r.u32();
    const bool adaptive = r.u32() != 0;
    const uint32_t threshold = r.u32(), min_spp = r.u32();
    if (adaptive) id.adaptive = AdaptiveSettings{std::bit_cast<float>(threshold), int(min_spp)};
    settings.target_spp = r.u32();
    resumed = std::move(settings);
}
#endif

RenderState resumed_state(const fs::path& file, ResumedFile resumed, const RenderIdentity& identity,
                          const std::optional<Shard>& shard, const Scene& scene, const RenderOptions& options) {
    if (resumed.part) {
        RenderState start{make_film(scene, needs_statistics(scene, options))};
        check_part_matches(file, *resumed.part, identity, *shard, start.film);
        put_part_values(*resumed.part, start.film);
        start.samples_done = resumed.part->samples_done;
        start.dropped_samples = resumed.part->dropped_samples;
        return start;
    }
    Checkpoint& c = *resumed.checkpoint;
    check_checkpoint_matches(file, c.identity, identity);
    if (needs_statistics(scene, options) && !c.state.film.has_statistics())
        throw SceneError(SourceLocation{file.string(), 0, 0, ""},
                         "cannot resume: the checkpoint keeps no per-pixel statistics (it was written without "
                         "adaptive sampling or --target-error), which --target-error needs; render again");
    return std::move(c.state);
}

JobSaver::JobSaver(fs::path file, RenderIdentity identity, const Scene& scene, const std::optional<Shard>& shard)
    : file_(std::move(file)), identity_(std::move(identity)) {
    if (shard) part_ = part_info(scene, *shard);
}

void JobSaver::operator()(const RenderState& state) const {
    if (part_)
        write_shard_part(file_, identity_, *part_, state);
    else
        write_checkpoint(file_, identity_, state);
}

}  // namespace candela
