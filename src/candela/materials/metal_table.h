#pragma once
// Measured metals as per-RGB-channel complex indices of refraction eta + i k (relative to
// vacuum), for the conductor lobe's Fresnel term in RGB mode: the `conductor` material's `metal`
// names. The values are computed in the build (metal_table_data.cpp in the build folder) by
// tools/metals/make_metal_table from the measured spectra that spectral mode uses
// (src/candela/spectrum/: Au, Ag, Cu, Al from luxpop.com after Palik and CuZn from Querry 1985,
// as tabulated in pbrt-v4; Cr, Fe, Ti from Johnson & Christy 1974): per channel, the (eta, k)
// whose Fresnel curve over cos in (0, 1] best matches, in least squares, the metal's spectral
// Fresnel reflectance rendered to linear sRGB under D65 (CIE 1931 2-degree observer). The
// generator says how; docs/SCENE_FORMAT.md lists the values.
#include <array>

#include "candela/math/color.h"

namespace candela {

// The scene file names them by symbol ("Au", ...): scene/enum_names.cpp, in this order.
enum class Metal { kAu, kAg, kCu, kAl, kCr, kFe, kTi, kCuZn };
inline constexpr int kMetalCount = 8;

struct MetalIor {
    Rgb eta;
    Rgb k;
};

// In the order of Metal.
extern const std::array<MetalIor, kMetalCount> kMetalIors;

// The RGB complex index of a measured metal.
inline const MetalIor& metal_ior(Metal metal) { return kMetalIors[static_cast<int>(metal)]; }

}  // namespace candela
