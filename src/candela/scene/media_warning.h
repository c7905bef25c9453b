#pragma once
// The words of the scene loader's warning that the scene's integrator ignores its media
// (places_media, scene.h; pbrt-v4's cpu/render.cpp warns the same). A render job whose
// --integrator changes the integrator withdraws that warning by these words, since it no longer
// holds, and gives its own where the new integrator ignores the media too (render_overrides.cpp).
#include <string_view>

namespace candela {

inline constexpr std::string_view kMediaIgnoredWarning = "the scene has participating media but the ";
// The same for subsurface materials (has_tabulated_subsurface, scene.h).
inline constexpr std::string_view kSubsurfaceIgnoredWarning = "the scene has subsurface materials but the ";

}  // namespace candela
