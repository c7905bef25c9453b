#include "candela/render/renderer.h"

#include <utility>

#include "candela/render/frame_renderer.h"
#include "candela/render/pass_engine.h"
#include "candela/render/thread_executor.h"

namespace candela {

RenderResult render(const Scene& scene, const RenderOptions& options) {
    return render(scene, options, RenderState{make_film(scene, needs_statistics(scene, options))});
}

RenderResult render(const Scene& scene, const RenderOptions& options, RenderState start) {
    const FrameRenderer frame(scene);
    PassEngine engine(frame, scene, options, std::move(start));
    ThreadExecutor threads(frame, options.threads);
    return engine.run(threads);
}

}  // namespace candela
