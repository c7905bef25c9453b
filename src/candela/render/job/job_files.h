#pragma once
// The files a render job reads and writes besides the scene and the images: the checkpoint or
// shard part it resumes (checkpoint.h, shard_part.h), and the checkpoints it saves. Internal to
// the job (job.h).
#include <cstdint>
#include <filesystem>
#include <optional>

#include "candela/render/job/checkpoint.h"
#include "candela/render/job/shard_part.h"
#include "candela/render/render_options.h"

namespace candela {

class MpiSession;
struct Scene;

// What a job resumes from: a checkpoint, or with --shard a part file. On the other ranks of an
// MPI job only the settings (identity and target_spp), which rank 0 shares.
struct ResumedFile {
    RenderIdentity identity;
    uint32_t target_spp = 0;  // a part file's target spp; 0 for a checkpoint (it records none)
    std::optional<Checkpoint> checkpoint;
    std::optional<ShardPart> part;
};

// Reads `file` as a part file when `shard`, else as a checkpoint (SceneError naming it).
ResumedFile read_resumed_file(const std::filesystem::path& file, bool shard);

#if CANDELA_HAVE_MPI
// Rank 0's `resumed` settings to every rank (collective), so that every rank renders the scene
// with the settings taken from the file only rank 0 reads.
void share_resumed_settings(const MpiSession& session, std::optional<ResumedFile>& resumed);
#endif

// The state to continue: the resumed file's, once it is known to continue this render (`identity`,
// part `shard` of it), and has the statistics the render needs. Throws SceneError naming `file`.
RenderState resumed_state(const std::filesystem::path& file, ResumedFile resumed, const RenderIdentity& identity,
                          const std::optional<Shard>& shard, const Scene& scene, const RenderOptions& options);

// Saves a render's state where its checkpoints go: a checkpoint, or a shard's part file.
class JobSaver {
  public:
    JobSaver(std::filesystem::path file, RenderIdentity identity, const Scene& scene, const std::optional<Shard>& shard);
    // Throws SceneError naming the file when it cannot be written.
    void operator()(const RenderState& state) const;

  private:
    std::filesystem::path file_;
    RenderIdentity identity_;
    std::optional<PartInfo> part_;
};

}  // namespace candela
