#pragma once
// Arbitrary output variables (AOVs): the layers a render writes beside its beauty image for a
// denoiser (Open Image Denoise's albedo and normal) or a compositor (depth, position). The film
// sums each accumulated layer's per-sample values exactly as it sums radiance (film/film.h), so a
// layer is filtered and averaged like the beauty image, deterministic and resumable.
//
// The set is closed and small: a bit mask in a fixed order, which is also the order of the
// values in a pixel and of the layers in the output. `variance` and `spp` are derived from the
// film's per-pixel statistics (film.h, film/pixel_statistics.h: the variance of each pixel's mean
// and its sample count), not from per-sample values: they have no sums here (value_count 0), and
// a film with either layer keeps statistics (render/renderer.h, make_film).
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace candela {

enum class AovLayer : uint8_t { kAlbedo, kNormal, kDepth, kPosition, kVariance, kSpp };
inline constexpr int kAovLayerCount = 6;

struct AovLayerInfo {
    std::string_view name;                     // in --aov and film.aovs
    int channels;                              // in the output
    int values;                                // doubles summed per pixel in the film (0: derived)
    std::array<std::string_view, 3> channel;   // OpenEXR channel names, the conventional ones
    // The names pbrt-v4's GBufferFilm gives the same quantity (film.aov_names "pbrt"); empty where
    // it has none of the same meaning (it has no depth or sample count, and its Variance is the
    // variance of one sample's sensor RGB, not of the pixel's mean): the conventional ones stay.
    std::array<std::string_view, 3> pbrt_channel;
};

// Indexed by AovLayer.
inline constexpr std::array<AovLayerInfo, kAovLayerCount> kAovLayerInfo{{
    {"albedo", 3, 3, {"albedo.R", "albedo.G", "albedo.B"}, {"Albedo.R", "Albedo.G", "Albedo.B"}},
    // The shading normal: pbrt-v4's Ns (its N is the geometric normal).
    {"normal", 3, 3, {"N.X", "N.Y", "N.Z"}, {"Ns.X", "Ns.Y", "Ns.Z"}},
    {"depth", 1, 1, {"Z", "", ""}, {}},
    {"position", 3, 3, {"P.X", "P.Y", "P.Z"}, {"P.X", "P.Y", "P.Z"}},
    {"variance", 3, 0, {"variance.R", "variance.G", "variance.B"}, {}},
    {"spp", 1, 0, {"spp", "", ""}, {}},
}};

inline const AovLayerInfo& aov_layer_info(AovLayer layer) { return kAovLayerInfo[size_t(layer)]; }

// The OpenEXR channel names the layers are written under (film.aov_names): the conventional
// ones above, or pbrt-v4's GBufferFilm's where it has the quantity.
enum class AovNames : uint8_t { kCandela, kPbrt };
// The space of the position and normal layers (film.aov_space; pbrt-v4's GBufferFilm
// "coordinatesystem"): world, or the camera's (x right, y up, z the view direction, origin at
// the camera's position).
enum class AovSpace : uint8_t { kWorld, kCamera };

// The layer a name names, or nullopt.
inline std::optional<AovLayer> parse_aov_layer(std::string_view name) {
    for (int i = 0; i < kAovLayerCount; ++i)
        if (kAovLayerInfo[size_t(i)].name == name) return AovLayer(i);
    return std::nullopt;
}

// "albedo, normal, depth, position, variance, spp": the names, for messages.
inline constexpr std::string_view kAovLayerNames = "albedo, normal, depth, position, variance, spp";

// A set of layers. Empty by default: a render without AOVs keeps no AOV sums.
class AovLayers {
  public:
    bool empty() const { return mask_ == 0; }
    bool has(AovLayer layer) const { return (mask_ >> unsigned(layer)) & 1u; }
    void add(AovLayer layer) { mask_ |= 1u << unsigned(layer); }
    uint32_t mask() const { return mask_; }
    bool operator==(const AovLayers&) const = default;

    // Doubles the film sums per pixel for these layers.
    int value_count() const {
        int n = 0;
        for (int i = 0; i < kAovLayerCount; ++i)
            if (has(AovLayer(i))) n += kAovLayerInfo[size_t(i)].values;
        return n;
    }
    // Where a summed layer's values start among a pixel's AOV values (layers in enum order).
    int offset(AovLayer layer) const {
        int n = 0;
        for (int i = 0; i < int(layer); ++i)
            if (has(AovLayer(i))) n += kAovLayerInfo[size_t(i)].values;
        return n;
    }

  private:
    uint32_t mask_ = 0;
};

// Whether a film with these layers needs statistics (film.h): the variance and spp layers.
inline bool film_needs_statistics(AovLayers layers) {
    return layers.has(AovLayer::kVariance) || layers.has(AovLayer::kSpp);
}

}  // namespace candela
