#pragma once
// A render identity for tests of checkpoint and part files: fixed names, hash and seed, the
// given film size.
#include "candela/render/job/checkpoint.h"

namespace candela::test {

inline RenderIdentity render_identity_of_size(int width, int height) {
    RenderIdentity id;
    id.candela_version = "0.1.0";
    id.integrator = "path";
    id.sampler = "independent";
    id.content_hash = 0x0123456789abcdefull;
    id.seed = 42;
    id.width = width;
    id.height = height;
    return id;
}

}  // namespace candela::test
