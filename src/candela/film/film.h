#pragma once
// The accumulation buffer: per pixel, the sum of its samples in double. Each pixel is written by
// one thread only, in sample-index order, so the sums (and the image) do not depend on how many
// threads render or how tiles are scheduled (DESIGN.md, "Determinism"). Checkpoints save and
// restore the sums exactly, so a resumed render goes on adding to the same doubles.
//
// With a filter whose samples have weights (film/pixel_filter.h: pbrt-v4's tabulated filters) the
// film also sums each pixel's weights and resolves to sum / weight sum (pbrt-v4's RGBFilm). Films
// of weight-1 filters keep no weights: their weight sum is the sample count, exactly.
//
// With AOV layers (film/aov_layers.h) the film also sums, per pixel, each sample's AOV values
// (albedo, normal, depth, position) times the same filter weight as its radiance, so the layers
// resolve exactly like the beauty image. Films without AOVs allocate nothing for them.
//
// A film with statistics (adaptive sampling, a noise target, the variance and spp outputs) also
// keeps per pixel the sum of its sample values' squares (r, g, b), its sample count, the rays its
// samples traced, and its sums (and weight sums) at the last two powers of two of its sample count:
// what the per-pixel variance of the mean needs (film/pixel_statistics.h: from the squares, and
// from the two halves of the last power of two, which works for Sobol samples too), the count
// because adaptive sampling gives pixels different numbers of samples, and the rays as the pixel's
// work, which --target-error's allocation weighs (render/error_allocation.h). That is 5 more
// doubles and 8 floats (72 bytes) per pixel, only for such films: others keep their memory, speed
// and bits. Regions (checkpoints, parts, messages) carry all 13 as doubles.
#include <array>
#include <cstdint>
#include <vector>

#include "candela/film/aov_layers.h"
#include "candela/film/film_settings.h"
#include "candela/image/image.h"
#include "candela/math/rgb.h"
#include "candela/math/vec.h"

namespace candela {

// One pixel's running sum of sample values, r, g, b.
using PixelSum = std::array<double, 3>;

// Adds one sample's value to a running sum: the only arithmetic a sample value goes through.
inline void add_to_sum(PixelSum& sum, const Rgb& value) {
    sum[0] += double(value.r);
    sum[1] += double(value.g);
    sum[2] += double(value.b);
}

// Adds the squares of one sample's value (or of value * weight) to a running sum of squares.
inline void add_square_to_sum(PixelSum& squares, const Rgb& value) {
    for (int c = 0; c < 3; ++c) {
        const double v = double(value[c]);
        squares[size_t(c)] += v * v;
    }
}
inline void add_weighted_square_to_sum(PixelSum& squares, const Rgb& value, float weight) {
    const double w = double(weight);
    for (int c = 0; c < 3; ++c) {
        const double v = double(value[c]) * w;
        squares[size_t(c)] += v * v;
    }
}

// Adds value * weight to a running sum, the product in double.
inline void add_weighted_to_sum(PixelSum& sum, const Rgb& value, float weight) {
    const double w = double(weight);
    sum[0] += double(value.r) * w;
    sum[1] += double(value.g) * w;
    sum[2] += double(value.b) * w;
}

// A pixel's sums and weight sums (the counts, for an unweighted film) over its first 2^(m-1) and
// first 2^m samples, 2^m the largest power of two at most its count (both 0 before the first
// sample; with one sample the first is 0): the two halves of a Sobol net
// (film/pixel_statistics.h). Floats, to halve their memory: only the error estimate reads them,
// and a float's relative rounding (6e-8) is far below any error a render is stopped at.
struct PrefixSums {
    std::array<std::array<float, 3>, 2> sum{};
    std::array<float, 2> weight{};
    // Called after sample `index` (0-based) was added to `running` (and `running_weight`): when
    // index + 1 is a power of two, the sums so far become the last power of two's.
    void after_sample(uint32_t index, const PixelSum& running, double running_weight) {
        const uint32_t n = index + 1;
        if ((n & (n - 1)) != 0) return;
        sum[0] = sum[1];
        weight[0] = weight[1];
        for (size_t c = 0; c < 3; ++c) sum[1][c] = float(running[c]);
        weight[1] = float(running_weight);
    }
};

// One camera sample's AOV values (integrators/aov_tracer.h): what the film sums for the AOV layers.
struct AovSample {
    Rgb albedo;      // at the first non-specular vertex, times the specular chain's tint
    Vec3f normal;    // shading normal there, world space, facing the ray; 0 on a miss
    float depth;     // distance along the camera ray to the first hit; kAovMissDepth on a miss
    Vec3f position;  // world-space first hit; 0 on a miss
};

// The depth of a camera sample that hits nothing: a finite "far away" (Blender Cycles' value for
// its Z pass), which filtering and averaging keep finite, where infinity would make every
// silhouette pixel infinite and NaN-prone in a compositor.
inline constexpr float kAovMissDepth = 1e10f;

class Film {
  public:
    Film() = default;  // 0 x 0
    // `weighted`: the film keeps per-pixel weight sums (all 0 to start); `aovs`: the AOV layers
    // whose sums it keeps (all 0 to start); `statistics`: sums of squares and sample counts.
    Film(int width, int height, bool weighted = false, AovLayers aovs = {}, bool statistics = false);
    // A film holding these sums (row-major, width * height of them), e.g. read from a checkpoint;
    // `weights` is empty (an unweighted film) or has one weight sum per pixel.
    Film(int width, int height, std::vector<PixelSum> sums, std::vector<double> weights = {});

    // Adds one sample's radiance to pixel (x, y). Not thread-safe for the same pixel.
    void add_sample(int x, int y, const Rgb& value) { add_to_sum(sums_[index(x, y)], value); }

    PixelSum& sum(int x, int y) { return sums_[index(x, y)]; }
    const PixelSum& sum(int x, int y) const { return sums_[index(x, y)]; }
    // All sums, row-major.
    const std::vector<PixelSum>& sums() const { return sums_; }

    bool weighted() const { return weighted_; }
    // The weight sum of pixel (x, y); weighted films only.
    double& weight(int x, int y) { return weights_[index(x, y)]; }
    double weight(int x, int y) const { return weights_[index(x, y)]; }
    // All weight sums, row-major; empty for an unweighted film.
    const std::vector<double>& weights() const { return weights_; }

    // The AOV layers the film sums, and pixel (x, y)'s AOV sums: aovs().value_count() doubles,
    // each layer's at aovs().offset(layer).
    AovLayers aovs() const { return aovs_; }
    double* aov_sums(int x, int y) { return aov_sums_.data() + index(x, y) * size_t(aov_values_); }
    const double* aov_sums(int x, int y) const { return aov_sums_.data() + index(x, y) * size_t(aov_values_); }
    // Adds one sample's AOV values times `weight` to pixel (x, y)'s AOV sums.
    void add_aov_sample(int x, int y, const AovSample& sample, float weight);

    bool has_statistics() const { return statistics_; }
    // The sum of squared sample values and the sample count of pixel (x, y); films with
    // statistics only.
    PixelSum& squares(int x, int y) { return squares_[index(x, y)]; }
    const PixelSum& squares(int x, int y) const { return squares_[index(x, y)]; }
    double& count(int x, int y) { return counts_[index(x, y)]; }
    double count(int x, int y) const { return counts_[index(x, y)]; }
    // The rays (camera, bounce, shadow) that pixel (x, y)'s samples traced; films with statistics
    // only. A count of work, not of time, so that decisions made from it are deterministic.
    double& rays(int x, int y) { return rays_[index(x, y)]; }
    double rays(int x, int y) const { return rays_[index(x, y)]; }
    // The sums at the last two powers of two of the sample count; films with statistics only.
    PrefixSums& prefix_sums(int x, int y) { return prefixes_[index(x, y)]; }
    const PrefixSums& prefix_sums(int x, int y) const { return prefixes_[index(x, y)]; }

    // The doubles the film keeps per pixel: the three sums, the weight sum for a weighted film,
    // the AOV sums, then for a film with statistics the three sums of squares, the sample count,
    // the rays and the prefix sums (sums then weight sums). What checkpoints, shard parts and MPI
    // messages carry for each pixel.
    int values_per_pixel() const { return (weighted_ ? 4 : 3) + aov_values_ + (statistics_ ? kStatisticsValues : 0); }
    static constexpr int kStatisticsValues = 13;
    // Copies the values of the pixels in `region` (row-major, values_per_pixel() each) to `out`,
    // which has room for region.width() * region.height() * values_per_pixel() doubles; and back.
    void read_region(const PixelBounds& region, double* out) const;
    void write_region(const PixelBounds& region, const double* in);

    // Unweighted: the mean over `samples_per_pixel` samples (over the pixel's own sample count for
    // a film with statistics); weighted: each sum divided by its weight sum (0 where that is 0).
    // As floats.
    Image resolve(uint32_t samples_per_pixel) const;
    // The summed AOV layers, resolved like resolve(), in AovLayer order, named and with their
    // channels' names (film/aov_layers.h; pbrt-v4's where `names` asks for them and it has them).
    std::vector<ImageLayer> resolve_aovs(uint32_t samples_per_pixel, AovNames names = AovNames::kCandela) const;

    int width() const { return width_; }
    int height() const { return height_; }

  private:
    size_t index(int x, int y) const { return size_t(y) * size_t(width_) + size_t(x); }
    int width_ = 0, height_ = 0;
    std::vector<PixelSum> sums_;
    std::vector<double> weights_;
    bool weighted_ = false;
    AovLayers aovs_;
    int aov_values_ = 0;  // aovs_.value_count()
    std::vector<double> aov_sums_;  // aov_values_ per pixel, row-major; empty without AOVs
    bool statistics_ = false;
    std::vector<PixelSum> squares_;  // with statistics only
    std::vector<double> counts_;     // with statistics only
    std::vector<double> rays_;       // with statistics only
    std::vector<PrefixSums> prefixes_;  // with statistics only
};

}  // namespace candela
