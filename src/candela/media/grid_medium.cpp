#include "candela/media/grid_medium.h"

#include "candela/core/check.h"

namespace candela {

GridField make_le_scale_field(float value, const Bounds3f& bounds) {
    LatticeGrid one;
    one.nx = one.ny = one.nz = 1;
    one.values = {value};
    return cell_centred_field(std::move(one), bounds);
}

void finish_grid_medium(GridMedium& m, int majorant_res) {
    m.majorant = make_majorant_grid(
        m.box.bounds, [&](const Bounds3f& cell, const Bounds3f&) { return m.density.max_over(cell); }, majorant_res);
    const bool hot = !m.temperature.empty();
    if (hot && m.blackbody_rgb.empty()) m.blackbody_rgb = make_blackbody_rgb_table();
    m.emissive = hot || !m.Le.is_black();
    CANDELA_CHECK(!m.emissive || !m.Le_scale.empty());
}

}  // namespace candela
