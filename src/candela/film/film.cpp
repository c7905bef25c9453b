#include "candela/film/film.h"

#include <initializer_list>
#include <string>

#include "candela/core/check.h"
#include "candela/film/pixel_statistics.h"

namespace candela {

Film::Film(int width, int height, bool weighted, AovLayers aovs, bool statistics)
    : width_(width), height_(height), sums_(size_t(width) * size_t(height), {0.0, 0.0, 0.0}),
      weights_(weighted ? sums_.size() : 0, 0.0), weighted_(weighted), aovs_(aovs), aov_values_(aovs.value_count()),
      aov_sums_(sums_.size() * size_t(aov_values_), 0.0), statistics_(statistics),
      squares_(statistics ? sums_.size() : 0, {0.0, 0.0, 0.0}), counts_(statistics ? sums_.size() : 0, 0.0),
      rays_(statistics ? sums_.size() : 0, 0.0), prefixes_(statistics ? sums_.size() : 0) {}

Film::Film(int width, int height, std::vector<PixelSum> sums, std::vector<double> weights)
    : width_(width), height_(height), sums_(std::move(sums)), weights_(std::move(weights)), weighted_(!weights_.empty()) {
    CANDELA_CHECK(sums_.size() == size_t(width) * size_t(height));
    CANDELA_CHECK(weights_.empty() || weights_.size() == sums_.size());
}

void Film::read_region(const PixelBounds& region, double* out) const {
    for (int y = region.y0; y < region.y1; ++y)
        for (int x = region.x0; x < region.x1; ++x) {
            const size_t i = index(x, y);
            for (double v : sums_[i]) *out++ = v;
            if (weighted_) *out++ = weights_[i];
            for (int k = 0; k < aov_values_; ++k) *out++ = aov_sums_[i * size_t(aov_values_) + size_t(k)];
            if (statistics_) {
                for (double v : squares_[i]) *out++ = v;
                *out++ = counts_[i];
                *out++ = rays_[i];
                for (const auto& p : prefixes_[i].sum)
                    for (float v : p) *out++ = double(v);
                for (float v : prefixes_[i].weight) *out++ = double(v);
            }
        }
}

void Film::write_region(const PixelBounds& region, const double* in) {
    for (int y = region.y0; y < region.y1; ++y)
        for (int x = region.x0; x < region.x1; ++x) {
            const size_t i = index(x, y);
            for (double& v : sums_[i]) v = *in++;
            if (weighted_) weights_[i] = *in++;
            for (int k = 0; k < aov_values_; ++k) aov_sums_[i * size_t(aov_values_) + size_t(k)] = *in++;
            if (statistics_) {
                for (double& v : squares_[i]) v = *in++;
                counts_[i] = *in++;
                rays_[i] = *in++;
                for (auto& p : prefixes_[i].sum)
                    for (float& v : p) v = float(*in++);
                for (float& v : prefixes_[i].weight) v = float(*in++);
            }
        }
}

void Film::add_aov_sample(int x, int y, const AovSample& sample, float weight) {
    double* sums = aov_sums(x, y);
    const double w = double(weight);
    auto add = [&](AovLayer layer, std::initializer_list<float> values) {
        if (!aovs_.has(layer)) return;
        double* out = sums + aovs_.offset(layer);
        for (float v : values) *out++ += double(v) * w;
    };
    add(AovLayer::kAlbedo, {sample.albedo.r, sample.albedo.g, sample.albedo.b});
    add(AovLayer::kNormal, {sample.normal.x, sample.normal.y, sample.normal.z});
    add(AovLayer::kDepth, {sample.depth});
    add(AovLayer::kPosition, {sample.position.x, sample.position.y, sample.position.z});
}

std::vector<ImageLayer> Film::resolve_aovs(uint32_t samples_per_pixel, AovNames names) const {
    std::vector<ImageLayer> layers;
    const double inv_spp = samples_per_pixel > 0 ? 1.0 / double(samples_per_pixel) : 0.0;
    for (int l = 0; l < kAovLayerCount; ++l) {
        const AovLayer layer = AovLayer(l);
        const AovLayerInfo& info = aov_layer_info(layer);
        if (!aovs_.has(layer)) continue;
        ImageLayer out{std::string(info.name), info.channels, {}, Image(width_, height_)};
        const bool pbrt = names == AovNames::kPbrt && !info.pbrt_channel[0].empty();
        for (int c = 0; c < info.channels; ++c)
            out.channel_names[size_t(c)] = std::string(pbrt ? info.pbrt_channel[size_t(c)] : info.channel[size_t(c)]);
        if (info.values == 0) {  // derived from the statistics (pixel_statistics.h)
            if (!statistics_) continue;
            out.image = layer == AovLayer::kVariance ? variance_image(*this) : spp_image(*this);
            layers.push_back(std::move(out));
            continue;
        }
        const size_t offset = size_t(aovs_.offset(layer));
        for (size_t i = 0; i < sums_.size(); ++i) {
            // Adaptive sampling gives pixels their own sample counts.
            const double inv = weighted_     ? (weights_[i] != 0.0 ? 1.0 / weights_[i] : 0.0)
                               : statistics_ ? (counts_[i] > 0.0 ? 1.0 / counts_[i] : 0.0)
                                             : inv_spp;
            const double* s = aov_sums_.data() + i * size_t(aov_values_) + offset;
            float v[3] = {0.0f, 0.0f, 0.0f};
            for (int c = 0; c < info.channels; ++c) v[c] = float(s[c] * inv);
            out.image.pixels[i] = Rgb(v[0], v[1], v[2]);
        }
        layers.push_back(std::move(out));
    }
    return layers;
}

Image Film::resolve(uint32_t samples_per_pixel) const {
    Image img(width_, height_);
    if (weighted_) {
        for (size_t i = 0; i < sums_.size(); ++i) {
            const double inv_weight = weights_[i] != 0.0 ? 1.0 / weights_[i] : 0.0;
            img.pixels[i] = Rgb(float(sums_[i][0] * inv_weight), float(sums_[i][1] * inv_weight),
                                float(sums_[i][2] * inv_weight));
        }
        return img;
    }
    if (statistics_) {
        for (size_t i = 0; i < sums_.size(); ++i) {
            const double inv = counts_[i] > 0.0 ? 1.0 / counts_[i] : 0.0;
            img.pixels[i] = Rgb(float(sums_[i][0] * inv), float(sums_[i][1] * inv), float(sums_[i][2] * inv));
        }
        return img;
    }
    double inv = samples_per_pixel > 0 ? 1.0 / double(samples_per_pixel) : 0.0;
    for (size_t i = 0; i < sums_.size(); ++i)
        img.pixels[i] = Rgb(float(sums_[i][0] * inv), float(sums_[i][1] * inv), float(sums_[i][2] * inv));
    return img;
}

}  // namespace candela
