// Delta tracking and ratio tracking (majorant_tracking.h, pbrt-v4's SampleT_maj) through a grid
// medium are unbiased for transmittance. The medium is a uniformgrid whose density varies along
// x only (ny = nz = 1), placed by a rotation and a non-uniform scale; a ray along its x axis at the
// samples' height sees a piecewise-linear density (linear between cell centres, falling to half
// the edge samples on the box's faces), whose optical depth is a sum of trapezoids.
//
// Each estimate must lie within 4.5 standard errors (from the sample variance, fixed seeds) of
// exp(-tau); each check has a control that must fail: a wrong tau, and a majorant grid scaled
// below the density.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/math/transform.h"
#include "candela/media/grid_medium.h"
#include "candela/media/majorant_tracking.h"
#include "candela/sampling/rng.h"
#include "candela/spectrum/dense_spectrum.h"
#include "grid_media_fixtures.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kWalks = 100000;
constexpr double kSigmas = 4.5;
constexpr float kStretchX = 2.5f;  // the CTM's scale along the medium's x

struct RampScene {
    GridMedium medium;
    Ray ray;                  // unit direction, world
    std::vector<float> d;     // density samples along x
    Color lambda;             // spectral mode's wavelengths
    MediumChannels ch;

    // Integral of the density along the ray, in world units.
    double density_integral() const {
        const int n = int(d.size());
        const double h = 1.0 / n, first = double(d.front()), last = double(d.back());
        double s = 0.5 * (0.5 * h) * (0.5 * first + first);  // the face to the first centre
        for (int i = 0; i + 1 < n; ++i) s += 0.5 * h * (double(d[size_t(i)]) + double(d[size_t(i + 1)]));
        s += 0.5 * (0.5 * h) * (last + 0.5 * last);  // the last centre to the face
        return s * double(kStretchX);
    }
};

RampScene ramp_scene(bool spectral) {
    RampScene s;
    Rng rng(31, 32);
    for (int i = 0; i < 9; ++i) s.d.push_back(0.1f + 0.9f * rng.next_float());
    const Transform ctm = Transform::translate(Vec3d(1, -2, 0.5)) * Transform::rotate(Vec3d(1, 2, 3), 0.8) *
                          Transform::scale(Vec3d(kStretchX, 0.7, 1.3));
    GridMedium& m = s.medium;
    m.box.medium_from_world = affine_map_3f(ctm.inverse());
    LatticeGrid g;
    g.nx = int(s.d.size());
    g.ny = g.nz = 1;
    g.values = s.d;
    m.density = cell_centred_field(std::move(g), m.box.bounds);
    // Coefficients that differ per channel, so every channel's estimate is checked.
    const std::vector<float> ramp_a = {360.0f, 0.2f, 830.0f, 0.9f}, ramp_s = {360.0f, 0.6f, 830.0f, 0.1f};
    m.sigma_a = {Rgb(0.3f, 0.5f, 0.9f), dense_from_pairs(ramp_a)};
    m.sigma_s = {Rgb(0.5f, 0.2f, 0.1f), dense_from_pairs(ramp_s)};
    finish_grid_medium(m);
    s.ray.o = Vec3f(ctm.apply_point(Vec3d(-0.4, 0.5, 0.5)));
    s.ray.d = normalize(Vec3f(ctm.apply_vector(Vec3d(1, 0, 0))));
    s.lambda = Color::from_channels(420.0f, 510.0f, 605.0f, 700.0f);
    s.ch = spectral ? MediumChannels{&s.lambda} : MediumChannels{};
    return s;
}

Color expected_transmittance(const RampScene& s, float tau_factor) {
    const MediumChannels& ch = s.ch;
    const Color sigma_t = s.medium.sigma_a.at(ch) + s.medium.sigma_s.at(ch);
    return exp_channels(sigma_t * float(-s.density_integral() * double(tau_factor)));
}

struct Estimate {
    double mean[kColorChannels] = {}, std_error[kColorChannels] = {};
};

template <class F>
Estimate estimate(F&& one_walk, uint64_t seed) {
    double sum[kColorChannels] = {}, sum2[kColorChannels] = {};
    for (int i = 0; i < kWalks; ++i) {
        Rng rng(seed, uint64_t(i));
        const Color v = one_walk(rng);
        for (int c = 0; c < kColorChannels; ++c) {
            sum[c] += double(v[c]);
            sum2[c] += double(v[c]) * double(v[c]);
        }
    }
    Estimate e;
    for (int c = 0; c < kColorChannels; ++c) {
        e.mean[c] = sum[c] / kWalks;
        const double var = (sum2[c] / kWalks - e.mean[c] * e.mean[c]) * kWalks / (kWalks - 1);
        e.std_error[c] = std::sqrt(std::max(var, 0.0) / kWalks);
    }
    return e;
}

// Ratio tracking (pbrt-v4's TraceTransmittance without its Russian roulette): the product over the
// drawn points of T_maj sigma_n / (T_maj sigma_maj)[hero], times T_maj / T_maj[hero] at the end.
Color ratio_tracking(const RampScene& s, int hero, Rng& rng) {
    Color T(1.0f);
    const Color T_end = sample_majorant_transmittance(
        s.medium, s.ray, kInfinity, rng.next_float(), rng, s.ch, hero,
        [&](const Vec3f&, const MediumPoint& mp, const Color& sigma_maj, const Color& T_maj) {
            const Color sigma_n = map_channels(sigma_maj - mp.sigma_a - mp.sigma_s, [](float v) { return v > 0 ? v : 0.0f; });
            T *= T_maj * sigma_n / (T_maj[hero] * sigma_maj[hero]);
            return true;
        });
    return T * T_end / T_end[hero];
}

// Delta tracking: a drawn point is a real collision with probability sigma_t / sigma_maj (hero
// channel), ending the walk; the estimate is 1 for a walk that passes the end of the ray.
Color delta_tracking(const RampScene& s, int hero, Rng& rng) {
    bool collided = false;
    sample_majorant_transmittance(s.medium, s.ray, kInfinity, rng.next_float(), rng, s.ch, hero,
                                  [&](const Vec3f&, const MediumPoint& mp, const Color& sigma_maj, const Color&) {
                                      const float sigma_t = (mp.sigma_a + mp.sigma_s)[hero];
                                      if (rng.next_float() < sigma_t / sigma_maj[hero]) {
                                          collided = true;
                                          return false;
                                      }
                                      return true;
                                  });
    return Color(collided ? 0.0f : 1.0f);
}

// The largest |mean - expected| / standard error over the channels checked.
double worst_z(const Estimate& e, const Color& expected, int first, int last) {
    double z = 0.0;
    for (int c = first; c <= last; ++c) z = std::max(z, std::abs(e.mean[c] - double(expected[c])) / e.std_error[c]);
    return z;
}

TEST(MajorantTracking, RatioTrackingIsUnbiasedInEveryChannel) {
    for (bool spectral : {false, true}) {
        const RampScene s = ramp_scene(spectral);
        const int hero = spectral ? 0 : 1;
        const Estimate e = estimate([&](Rng& rng) { return ratio_tracking(s, hero, rng); }, 41);
        const Color T = expected_transmittance(s, 1.0f);
        EXPECT_LT(worst_z(e, T, 0, spectral ? 3 : 2), kSigmas) << (spectral ? "spectral" : "rgb");
        // Control: a 5% larger optical depth is rejected.
        EXPECT_GT(worst_z(e, expected_transmittance(s, 1.05f), 0, spectral ? 3 : 2), kSigmas);
    }
}

TEST(MajorantTracking, DeltaTrackingPassesWithProbabilityExpMinusTau) {
    for (bool spectral : {false, true}) {
        const RampScene s = ramp_scene(spectral);
        for (int hero : {0, 2}) {
            const Estimate e = estimate([&](Rng& rng) { return delta_tracking(s, hero, rng); }, 43);
            const Color T = expected_transmittance(s, 1.0f);
            EXPECT_LT(worst_z(e, T, hero, hero), kSigmas) << (spectral ? "spectral" : "rgb") << " hero " << hero;
            EXPECT_GT(worst_z(e, expected_transmittance(s, 1.05f), hero, hero), kSigmas);
        }
    }
}

TEST(MajorantTracking, ControlATooSmallMajorantBiasesBoth) {
    RampScene s = ramp_scene(false);
    for (float& c : s.medium.majorant.cells) c *= 0.6f;
    const Color T = expected_transmittance(s, 1.0f);
    const Estimate ratio = estimate([&](Rng& rng) { return ratio_tracking(s, 0, rng); }, 41);
    EXPECT_GT(worst_z(ratio, T, 0, 2), kSigmas);
    const Estimate delta = estimate([&](Rng& rng) { return delta_tracking(s, 0, rng); }, 43);
    EXPECT_GT(worst_z(delta, T, 0, 0), kSigmas);
}

}  // namespace
}  // namespace candela
