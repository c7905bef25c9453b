#include "candela/materials/tabulated_bssrdf.h"

#include <algorithm>
#include <cmath>

#include "candela/math/catmull_rom.h"
#include "candela/math/constants.h"

namespace candela {

TabulatedBssrdf::TabulatedBssrdf(const Vec3f& po, const Vec3f& ns, float eta, const Color& sigma_a,
                                 const Color& sigma_s, const BssrdfTable* table, int hero)
    : po_(po), ns_(ns), eta_(eta), sigma_t_(sigma_a + sigma_s), table_(table), hero_(hero) {
    rho_ = safe_div(sigma_s, sigma_t_);
}

namespace {

// The table's profile 2 pi r_opt (S_ss + S_ms)(r_opt), interpolated in albedo and optical radius
// by the tensor product of Catmull-Rom weights; with rho_eff (if given) interpolated in albedo
// alike. False when rho or r_opt is outside the table.
bool interpolate_profile(const BssrdfTable& t, float rho, float r_optical, float* profile,
                         float* rho_eff) {
    int rho_offset, radius_offset;
    float rho_weights[4], radius_weights[4];
    if (!catmull_rom_weights(t.rho_samples, rho, &rho_offset, rho_weights) ||
        !catmull_rom_weights(t.radius_samples, r_optical, &radius_offset, radius_weights))
        return false;
    float sum = 0.0f, eff = 0.0f;
    for (int j = 0; j < 4; ++j) {
        if (rho_weights[j] == 0.0f) continue;
        if (rho_eff != nullptr) eff += t.rho_eff[static_cast<size_t>(rho_offset + j)] * rho_weights[j];
        for (int k = 0; k < 4; ++k)
            if (radius_weights[k] != 0.0f)
                sum += t.eval_profile(rho_offset + j, radius_offset + k) * rho_weights[j] * radius_weights[k];
    }
    *profile = sum;
    if (rho_eff != nullptr) *rho_eff = eff;
    return true;
}

}  // namespace

Color TabulatedBssrdf::sr(float r) const {
    Color out(0.0f);
    for (int c = 0; c < kColorChannels; ++c) {
        const float r_optical = r * sigma_t_[c];
        float profile;
        if (!interpolate_profile(*table_, rho_[c], r_optical, &profile, nullptr)) continue;
        // The table holds the radial density 2 pi r S(r); divide that factor back out, then
        // scale from the unit-extinction medium to this one (per unit area: sigma_t^2).
        if (r_optical != 0.0f) profile /= 2.0f * kPi * r_optical;
        out.set(c, std::max(0.0f, profile * sigma_t_[c] * sigma_t_[c]));
    }
    return out;
}

std::optional<float> TabulatedBssrdf::sample_sr(float u) const {
    const float sigma_t = sigma_t_[hero_];
    if (sigma_t == 0.0f) return std::nullopt;
    return sample_catmull_rom_2d(table_->rho_samples, table_->radius_samples, table_->profile,
                                 table_->profile_cdf, rho_[hero_], u) /
           sigma_t;
}

Color TabulatedBssrdf::pdf_sr(float r) const {
    Color out(0.0f);
    for (int c = 0; c < kColorChannels; ++c) {
        const float r_optical = r * sigma_t_[c];
        float profile, rho_eff;
        if (!interpolate_profile(*table_, rho_[c], r_optical, &profile, &rho_eff)) continue;
        if (r_optical != 0.0f) profile /= 2.0f * kPi * r_optical;
        out.set(c, std::max(0.0f, profile * sigma_t_[c] * sigma_t_[c] / rho_eff));
    }
    return out;
}

std::optional<BssrdfProbeSegment> TabulatedBssrdf::sample_sp(float u1, float u2a, float u2b) const {
    // The probe axis and the two directions of the disk normal to it: the axes of
    // Frame::from_normal(ns), in pbrt-v4's order (its Frame::FromX, FromY and FromZ of ns), so a
    // sample lands where pbrt-v4's does.
    const Frame frame = Frame::from_normal(ns_);
    Vec3f axis, disk_x, disk_y;
    if (u1 < 0.25f) {
        axis = frame.t, disk_x = frame.n, disk_y = frame.s;
    } else if (u1 < 0.5f) {
        axis = frame.s, disk_x = frame.t, disk_y = frame.n;
    } else {
        axis = frame.n, disk_x = frame.s, disk_y = frame.t;
    }
    const std::optional<float> r = sample_sr(u2a);
    if (!r) return std::nullopt;
    const float phi = 2.0f * kPi * u2b;
    // The chord's half length: the probe covers the sphere of radius r_max about po, beyond
    // which the profile holds 0.1% of its energy.
    const std::optional<float> r_max = sample_sr(0.999f);
    if (!r_max || *r >= *r_max) return std::nullopt;
    const float l = 2.0f * std::sqrt(*r_max * *r_max - *r * *r);
    const Vec3f start = po_ + (disk_x * std::cos(phi) + disk_y * std::sin(phi)) * *r - axis * (0.5f * l);
    return BssrdfProbeSegment{start, start + axis * l};
}

Color TabulatedBssrdf::pdf_sp(const Vec3f& pi, const Vec3f& ni) const {
    const Frame frame = Frame::from_normal(ns_);
    const Vec3f d = frame.to_local(pi - po_), n = frame.to_local(ni);
    // The radius each axis's disk sees: the distance from po after projecting along the axis.
    const float r_proj[3] = {std::sqrt(d.y * d.y + d.z * d.z), std::sqrt(d.z * d.z + d.x * d.x),
                             std::sqrt(d.x * d.x + d.y * d.y)};
    const float n_local[3] = {n.x, n.y, n.z};
    const float axis_probability[3] = {0.25f, 0.25f, 0.5f};
    Color pdf(0.0f);
    for (int axis = 0; axis < 3; ++axis)
        pdf += pdf_sr(r_proj[axis]) * (std::abs(n_local[axis]) * axis_probability[axis]);
    return pdf;
}

}  // namespace candela
