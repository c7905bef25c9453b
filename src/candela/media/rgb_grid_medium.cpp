#include "candela/media/rgb_grid_medium.h"

#include <utility>

namespace candela {

RgbLattice make_rgb_lattice(int nx, int ny, int nz, std::vector<Rgb> values, bool illuminant) {
    RgbLattice l;
    l.rgb.nx = l.spectra.nx = nx;
    l.rgb.ny = l.spectra.ny = ny;
    l.rgb.nz = l.spectra.nz = nz;
    l.spectra.values.reserve(values.size());
    for (const Rgb& v : values)
        l.spectra.values.push_back(illuminant ? rgb_illuminant_spectrum(v) : rgb_unbounded_spectrum(v));
    l.rgb.values = std::move(values);
    return l;
}

void finish_rgb_grid_medium(RgbGridMedium& m) {
    // pbrt-v4's bound per cell: the largest voxel maximum of sigma_a plus that of sigma_s (1 for
    // a grid not given), times scale. The cells are boxes of [0, 1]^3, the lookups' coordinates.
    auto bound = [&](auto max_of, auto lattice_of) {
        return make_majorant_grid(m.box.bounds, [&](const Bounds3f&, const Bounds3f& u) {
            const float a = m.sigma_a.empty() ? 1.0f : lattice_of(m.sigma_a).max_value(u, max_of);
            const float s = m.sigma_s.empty() ? 1.0f : lattice_of(m.sigma_s).max_value(u, max_of);
            return m.scale * (a + s);
        });
    };
    m.majorant_spectral = bound([](const RgbSpectrum& s) { return s.max_value(); },
                                [](const RgbLattice& l) -> const Lattice<RgbSpectrum>& { return l.spectra; });
    m.majorant_rgb = bound([](const Rgb& v) { return v.max_component(); },
                           [](const RgbLattice& l) -> const Lattice<Rgb>& { return l.rgb; });
    m.emissive = !m.Le.empty() && m.Le_scale > 0.0f;
}

}  // namespace candela
