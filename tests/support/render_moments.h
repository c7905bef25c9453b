#pragma once
// Per-pixel sample statistics of a render, for the render tests' z-tests (Mitsuba 3's
// test_renders.py compares mean and variance images the same way).
//
// render_moments() replays the renderer's loop (renderer.cpp): the same accelerator, light set,
// camera and integrator, one Rng::for_sample(pixel, sample, seed) stream per sample, film
// positions from PixelFilter::sample, non-finite samples dropped and counted as zero. It sums each
// pixel's samples in sample-index order in double, as Film does, so image() is bit-identical to
// render()'s image (agreement_render_test.cpp asserts this); it also sums their squares, which
// gives each pixel mean's variance. The samples of one pixel are independent and identically
// distributed, so the unbiased sample variance over spp divided by spp estimates the variance of
// the pixel mean; pixels are independent of each other, so block variances add.
//
// That needs independent samples: with the sobol sampler a pixel's samples are dependent (a
// scrambled net), and their spread says nothing reliable about the error of their mean (Owen's
// bound allows a few times the Monte Carlo variance for rough integrands, far less for smooth
// ones). render_moments() therefore fails the test for a sobol scene unless asked only for the
// image; render_moments_replicated() measures a sobol render's error the randomized-QMC way,
// from independent re-randomizations (seeds).
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "candela/camera/camera.h"
#include "candela/film/pixel_filter.h"
#include "candela/geometry/accelerator.h"
#include "candela/image/image.h"
#include "candela/image/image_io.h"
#include "candela/lights/light_set.h"
#include "candela/integrators/integrator.h"
#include "candela/render/renderer.h"
#include "candela/sampling/sampler.h"
#include "candela/scene/scene.h"
#include "support/chi2.h"

namespace candela::test {

struct RenderMoments {
    int width = 0;
    int height = 0;
    uint32_t spp = 0;
    uint64_t dropped = 0;                      // non-finite samples (counted as zero: FrameRenderer's rule)
    std::vector<std::array<double, 3>> sum;    // per pixel and channel, in sample-index order
    std::vector<std::array<double, 3>> sum_sq;

    size_t index(int x, int y) const { return size_t(y) * size_t(width) + size_t(x); }
    // The pixel's sample mean (render()'s pixel value, in double).
    double mean(int x, int y, int c) const { return sum[index(x, y)][size_t(c)] / double(spp); }
    // The variance of that mean: the unbiased sample variance of the spp samples, over spp.
    double variance_of_mean(int x, int y, int c) const {
        const double n = double(spp), s = sum[index(x, y)][size_t(c)], q = sum_sq[index(x, y)][size_t(c)];
        return std::max(0.0, (q - s * s / n) / (n - 1.0)) / n;
    }
    // The image render() returns for the same scene (Film::resolve's rounding).
    Image image() const {
        Image img(width, height);
        const double inv = 1.0 / double(spp);
        for (size_t i = 0; i < sum.size(); ++i)
            img.pixels[i] = Rgb(float(sum[i][0] * inv), float(sum[i][1] * inv), float(sum[i][2] * inv));
        return img;
    }
};

// Takes the samples render() takes, one by one, keeping per-pixel sums of samples and of their squares.
// `for_variance` false: only image() will be used (any sampler).
inline RenderMoments render_moments(const Scene& scene, bool for_variance = true) {
    if (for_variance && scene.sampler.type != SamplerType::kIndependent)
        ADD_FAILURE() << "render_moments: per-pixel variances need sampler type independent; use "
                         "render_moments_replicated for sobol";
    Accelerator accel(scene.meshes, scene.spheres, scene.disks, scene.shapes, alpha_cutouts(scene),
                      Instancing{scene.objects, scene.instances, scene.instance_motions, scene.camera.shutter},
                      scene.curves, scene.quadrics);
    LightSet lights = build_light_set(scene, accel);  // as render() builds them
    const Camera camera = make_camera(scene.camera, !scene.instance_motions.empty());
    std::unique_ptr<Integrator> integrator = make_integrator(scene, accel, lights);
    const PixelFilter filter(scene.film.filter);
    if (filter.weighted() || scene.film.crop_window != FilmSettings{}.crop_window)
        ADD_FAILURE() << "render_moments: the moments are of plain means over the full image: weight-1 filters "
                         "and no crop window";

    RenderMoments m;
    m.width = scene.camera.width;
    m.height = scene.camera.height;
    m.spp = uint32_t(scene.sampler.spp);
    m.sum.assign(size_t(m.width) * size_t(m.height), {0.0, 0.0, 0.0});
    m.sum_sq = m.sum;

    const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
    std::atomic<int> next_row{0};
    std::vector<uint64_t> dropped(size_t(threads), 0);
    auto work = [&](size_t t) {
        enable_flush_denormals();  // as the renderer's worker threads, so results match bit for bit
        RayCounters counters;
        for (int y = next_row++; y < m.height; y = next_row++) {
            for (int x = 0; x < m.width; ++x) {
                const uint64_t pixel = uint64_t(y) * uint64_t(m.width) + uint64_t(x);
                std::array<double, 3>& s = m.sum[m.index(x, y)];
                std::array<double, 3>& q = m.sum_sq[m.index(x, y)];
                for (uint32_t i = 0; i < m.spp; ++i) {
                    // With Sobol sampling the samples of a pixel are not independent: their
                    // spread / n then overestimates the error of the mean, and z-tests built on it
                    // are conservative (they lose power, never gain false alarms).
                    Sampler sampler(scene.sampler.type, pixel, i, scene.sampler.seed);
                    Vec2f film = Vec2f(float(x), float(y)) + filter.sample(i, sampler.next_vec2f()).position;
                    const Ray ray = visit([&](const auto& cam) { return cam.generate_ray(film, sampler); }, camera);
                    Rgb L = integrator->radiance(ray, sampler, counters);
                    if (!L.is_finite()) {
                        ++dropped[t];
                        continue;
                    }
                    for (int c = 0; c < 3; ++c) {
                        const double v = double(L[c]);
                        s[size_t(c)] += v;
                        q[size_t(c)] += v * v;
                    }
                }
            }
        }
    };
    std::vector<std::thread> pool;
    for (size_t t = 0; t < size_t(threads); ++t) pool.emplace_back(work, t);
    for (std::thread& th : pool) th.join();
    for (uint64_t d : dropped) m.dropped += d;
    return m;
}

// The moments of `replicates` independent renders of `scene` (seeds seed, seed + 1, ...), each
// pixel mean counting as one sample: valid for any sampler (randomized quasi-Monte Carlo error
// estimation). The result's spp is the number of replicates; image() is their average.
inline RenderMoments render_moments_replicated(const Scene& scene, int replicates) {
    RenderMoments m;
    for (int r = 0; r < replicates; ++r) {
        Scene s = scene;
        s.sampler.seed = scene.sampler.seed + uint64_t(r);
        RenderMoments one = render_moments(s, /*for_variance=*/false);
        if (r == 0) {
            m.width = one.width;
            m.height = one.height;
            m.sum.assign(one.sum.size(), {0.0, 0.0, 0.0});
            m.sum_sq = m.sum;
        }
        const double inv = 1.0 / double(one.spp);
        for (size_t i = 0; i < one.sum.size(); ++i)
            for (size_t c = 0; c < 3; ++c) {
                const double mean = one.sum[i][c] * inv;
                m.sum[i][c] += mean;
                m.sum_sq[i][c] += mean * mean;
            }
        m.dropped += one.dropped;
    }
    m.spp = uint32_t(replicates);
    return m;
}

// The false-rejection rate of one statistical render TEST (one Sidak family of z-tests): 1% for
// the whole render label, split over at most kRenderStatTests such TESTs (Bonferroni), so that a
// correct renderer fails the label by chance at most once in a hundred reseedings. Raise the bound
// when adding statistical render tests.
inline constexpr int kRenderStatTests = 100;
inline constexpr double kRenderTestAlpha = 0.01 / kRenderStatTests;

// The two-sided critical |z| of one test at level `alpha_per_test` for a standard normal
// statistic: erfc(z / sqrt(2)) = alpha_per_test, solved by bisection (erfc is decreasing).
inline double normal_critical_z(double alpha_per_test) {
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > alpha_per_test ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// The critical |z| that keeps the family-wise false-rejection rate of `tests` z-tests at `alpha`.
inline double sidak_critical_z(double alpha, long tests) {
    return normal_critical_z(sidak_alpha(alpha, int(tests)));
}

// A square block of pixels: its mean value of one channel and that mean's variance.
struct BlockEstimate {
    double mean = 0.0;
    double variance = 0.0;
};

// The block of `size` x `size` pixels with top-left pixel (x0, y0), channel c, scaled by `scale`
// (a scaled image's variance scales by scale^2).
inline BlockEstimate block_estimate(const RenderMoments& m, int x0, int y0, int size, int c, double scale = 1.0) {
    BlockEstimate b;
    const double p = double(size) * double(size);
    for (int y = y0; y < y0 + size; ++y) {
        for (int x = x0; x < x0 + size; ++x) {
            b.mean += m.mean(x, y, c);
            b.variance += m.variance_of_mean(x, y, c);
        }
    }
    b.mean *= scale / p;
    b.variance *= scale * scale / (p * p);
    return b;
}

// A family of z-tests at one critical value; remembers the worst one for the failure message.
class ZTestFamily {
  public:
    explicit ZTestFamily(double z_critical) : z_critical_(z_critical) {}

    // One test of the hypothesis E[difference] = 0, given the difference's variance. A zero
    // variance with a nonzero difference rejects (both estimates are exact and disagree).
    void add(double difference, double variance, int x, int y, int c) {
        ++tests_;
        constexpr double kInf = std::numeric_limits<double>::infinity();
        double z = variance > 0.0 ? difference / std::sqrt(variance) : (difference == 0.0 ? 0.0 : kInf);
        if (!(std::abs(z) <= z_critical_)) ++rejected_;
        if (std::abs(z) <= std::abs(worst_z_)) return;  // NaN counts as worse than anything
        worst_z_ = z;
        worst_ = fmt::format("block at ({}, {}) channel {}: difference {:.6g}, sigma {:.6g}", x, y, c, difference,
                             std::sqrt(variance));
    }
    // True when some test ran and none rejected.
    bool passed() const { return tests_ > 0 && rejected_ == 0; }
    long tests() const { return tests_; }
    long rejected() const { return rejected_; }
    double z_critical() const { return z_critical_; }
    std::string summary() const {
        return fmt::format("{} of {} z-tests rejected at |z| > {:.3f} (Sidak); worst z = {:.3f}, {}", rejected_, tests_,
                           z_critical_, worst_z_, worst_);
    }

  private:
    double z_critical_;
    long tests_ = 0;
    long rejected_ = 0;
    double worst_z_ = 0.0;
    std::string worst_ = "none";
};

// Compares two renders of the same view block by block and channel by channel:
// z = (m_a - scale_b m_b) / sqrt(var_a + scale_b^2 var_b). The renders are independent (their
// samples come from different streams or different integrators).
inline void compare_renders(const RenderMoments& a, const RenderMoments& b, int block, ZTestFamily& family,
                            double scale_b = 1.0) {
    for (int y = 0; y + block <= a.height; y += block) {
        for (int x = 0; x + block <= a.width; x += block) {
            for (int c = 0; c < 3; ++c) {
                BlockEstimate ea = block_estimate(a, x, y, block, c);
                BlockEstimate eb = block_estimate(b, x, y, block, c, scale_b);
                family.add(ea.mean - eb.mean, ea.variance + eb.variance, x, y, c);
            }
        }
    }
}

// compare_renders of every block and, per channel, of the whole (square) image, in one family
// Sidak-corrected at kRenderTestAlpha for them all.
inline ZTestFamily compare_blocks_and_whole(const RenderMoments& a, const RenderMoments& b, int block,
                                            double scale_b = 1.0) {
    const long blocks = long(a.width / block) * long(a.height / block);
    ZTestFamily family(sidak_critical_z(kRenderTestAlpha, 3 * (blocks + 1)));
    compare_renders(a, b, block, family, scale_b);
    for (int c = 0; c < 3; ++c) {
        const BlockEstimate ea = block_estimate(a, 0, 0, a.width, c);
        const BlockEstimate eb = block_estimate(b, 0, 0, a.width, c, scale_b);
        family.add(ea.mean - eb.mean, ea.variance + eb.variance, -1, -1, c);
    }
    return family;
}

// z-tests of every block-channel and of the whole (square) image against the constant colour
// `expected`, in one family Sidak-corrected at kRenderTestAlpha (closed-form render tests).
inline ZTestFamily test_against(const RenderMoments& m, const std::array<double, 3>& expected, int block) {
    const long blocks = long(m.width / block) * long(m.height / block);
    ZTestFamily family(sidak_critical_z(kRenderTestAlpha, 3 * (blocks + 1)));
    for (int c = 0; c < 3; ++c) {
        for (int y = 0; y + block <= m.height; y += block)
            for (int x = 0; x + block <= m.width; x += block) {
                const BlockEstimate b = block_estimate(m, x, y, block, c);
                family.add(b.mean - expected[size_t(c)], b.variance, x, y, c);
            }
        const BlockEstimate whole = block_estimate(m, 0, 0, m.width, c);
        family.add(whole.mean - expected[size_t(c)], whole.variance, -1, -1, c);
    }
    return family;
}

// The number of block-channels of `m` with a nonzero mean (the ones a scaled copy changes).
inline long lit_blocks(const RenderMoments& m, int block) {
    long lit = 0;
    for (int y = 0; y + block <= m.height; y += block)
        for (int x = 0; x + block <= m.width; x += block)
            for (int c = 0; c < 3; ++c) lit += block_estimate(m, x, y, block, c).mean != 0.0 ? 1 : 0;
    return lit;
}

// Writes `m`'s mean image as PFM into the build tree, for looking at a failed test.
inline void write_diagnostic(const RenderMoments& m, const std::string& name) {
    std::filesystem::path file = std::filesystem::path(CANDELA_TEST_BINARY_DIR) / (name + ".pfm");
    write_image(file, m.image(), FilmSettings{});
}


}  // namespace candela::test
