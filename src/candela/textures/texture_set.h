#pragma once
// The scene's textures, referenced by index from material parameters (texture_param.h).
#include <vector>

#include "candela/core/platform.h"
#include "candela/textures/texture_context.h"
#include "candela/textures/texture_param.h"

namespace candela {

class TextureSet {
  public:
    CANDELA_HD bool empty() const { return count_ == 0; }

    // The parameter's value at ctx: its constant, or its texture's value there.
    CANDELA_HD float eval(const FloatParam& p, const TextureContext&) const { return p.value; }
    CANDELA_HD Color eval(const ColorParam& p, const TextureContext&) const { return p.value; }

  private:
    size_t count_ = 0;
};

}  // namespace candela
