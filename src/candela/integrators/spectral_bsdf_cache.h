#pragma once
// Spectral mode: the BSDFs of one path's untextured materials at its wavelengths, built once per
// path instead of at every vertex.
#include <array>
#include <cstdint>
#include <new>
#include <type_traits>

#include "candela/materials/bsdf.h"

namespace candela {

// An untextured material's BSDF in spectral mode depends only on the material and the path's
// four wavelengths, which stay the same along the path (terminating the secondary wavelengths
// changes only their pdfs). A path revisits the same few materials (the Cornell box's walls), so
// PathIntegrator keeps one of these per path: a direct-mapped table of built BSDFs keyed by
// material index. A vertex reads its BSDF in place in the slot; the next vertex may overwrite it,
// when the previous vertex is gone. Textured materials are built at every hit as before.
class SpectralBsdfCache {
  public:
    static constexpr uint32_t kSlots = 4;

    // Nothing is built or zeroed here: a default Bsdf (its lobes are std::variants, which
    // value-initialize) and std::optional<Bsdf> both zero their bytes (GCC 12), and a path that
    // is over after one or two vertices would pay 1.7 kB of stores. A slot is constructed on its
    // first use.
    SpectralBsdfCache() {}

    // The slot for material `index`; `hit` tells whether it already holds that material's BSDF
    // (otherwise the caller builds it into the slot, which then belongs to `index`).
    Bsdf& slot(uint32_t index, bool& hit) {
        const uint32_t s = index % kSlots;
        hit = material_[s] == index;
        if (!hit) {
            if (material_[s] == kEmpty) ::new (&slots_[s].bsdf) Bsdf();
            material_[s] = index;
        }
        return slots_[s].bsdf;
    }

  private:
    static_assert(std::is_trivially_destructible_v<Bsdf>, "slots are never destroyed");
    union Slot {
        Slot() {}
        Bsdf bsdf;
    };
    static constexpr uint32_t kEmpty = UINT32_MAX;
    std::array<uint32_t, kSlots> material_{kEmpty, kEmpty, kEmpty, kEmpty};
    std::array<Slot, kSlots> slots_;
};

}  // namespace candela
