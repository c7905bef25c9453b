#pragma once
// The pass executor of one process (pass_engine.h): a pass's tiles in parallel on a oneTBB task
// arena of a fixed number of threads.
#include <memory>

#include "candela/render/pass_engine.h"

namespace candela {

class ThreadExecutor final : public PassExecutor {
  public:
    // `threads` render threads (0: all cores).
    ThreadExecutor(const FrameRenderer& frame, int threads);
    ~ThreadExecutor() override;

    int threads() const override { return threads_; }
    uint64_t run_pass(const PassWork& pass, PassEngine& engine) override;
    RayCounters finish(RenderEnd end, const RenderState& state) override;

  private:
    struct Pool;
    const FrameRenderer& frame_;
    int threads_;
    std::unique_ptr<Pool> pool_;
};

}  // namespace candela
