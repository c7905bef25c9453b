#include "candela/spectrum/camera_sensors.h"

#include <array>
#include <cstddef>

#include "candela/spectrum/camera_sensor_data.h"

namespace candela {

namespace {

struct CameraTable {
    std::string_view name;
    std::span<const float> r, g, b;  // (nm, value) pairs
};

// pbrt-v4's names (its camera curves are the named spectra NAME_r, NAME_g, NAME_b).
constexpr std::array kCameras = {
    CameraTable{"canon_eos_100d", kCanonEos100dR, kCanonEos100dG, kCanonEos100dB},
    CameraTable{"canon_eos_1dx_mkii", kCanonEos1dxMkiiR, kCanonEos1dxMkiiG, kCanonEos1dxMkiiB},
    CameraTable{"canon_eos_200d", kCanonEos200dR, kCanonEos200dG, kCanonEos200dB},
    CameraTable{"canon_eos_200d_mkii", kCanonEos200dMkiiR, kCanonEos200dMkiiG, kCanonEos200dMkiiB},
    CameraTable{"canon_eos_5d", kCanonEos5dR, kCanonEos5dG, kCanonEos5dB},
    CameraTable{"canon_eos_5d_mkii", kCanonEos5dMkiiR, kCanonEos5dMkiiG, kCanonEos5dMkiiB},
    CameraTable{"canon_eos_5d_mkiii", kCanonEos5dMkiiiR, kCanonEos5dMkiiiG, kCanonEos5dMkiiiB},
    CameraTable{"canon_eos_5d_mkiv", kCanonEos5dMkivR, kCanonEos5dMkivG, kCanonEos5dMkivB},
    CameraTable{"canon_eos_5ds", kCanonEos5dsR, kCanonEos5dsG, kCanonEos5dsB},
    CameraTable{"canon_eos_m", kCanonEosMR, kCanonEosMG, kCanonEosMB},
    CameraTable{"hasselblad_l1d_20c", kHasselbladL1d20cR, kHasselbladL1d20cG, kHasselbladL1d20cB},
    CameraTable{"nikon_d810", kNikonD810R, kNikonD810G, kNikonD810B},
    CameraTable{"nikon_d850", kNikonD850R, kNikonD850G, kNikonD850B},
    CameraTable{"sony_ilce_6400", kSonyIlce6400R, kSonyIlce6400G, kSonyIlce6400B},
    CameraTable{"sony_ilce_7m3", kSonyIlce7m3R, kSonyIlce7m3G, kSonyIlce7m3B},
    CameraTable{"sony_ilce_7rm3", kSonyIlce7rm3R, kSonyIlce7rm3G, kSonyIlce7rm3B},
    CameraTable{"sony_ilce_9", kSonyIlce9R, kSonyIlce9G, kSonyIlce9B},
};

}  // namespace

std::span<const CameraResponse> camera_responses() {
    static const std::array<CameraResponse, kCameras.size()> all = [] {
        std::array<CameraResponse, kCameras.size()> a;
        for (size_t i = 0; i < kCameras.size(); ++i)
            a[i] = {kCameras[i].name, dense_from_pairs(kCameras[i].r), dense_from_pairs(kCameras[i].g),
                    dense_from_pairs(kCameras[i].b)};
        return a;
    }();
    return all;
}

int camera_response_index(std::string_view name) {
    for (size_t i = 0; i < kCameras.size(); ++i)
        if (kCameras[i].name == name) return int(i);
    return -1;
}

std::span<const DenseSpectrum> color_checker_swatches() {
    static const std::array<DenseSpectrum, kColorCheckerSwatches> all = [] {
        const std::array<std::span<const float>, kColorCheckerSwatches> pairs = {
            std::span<const float>(kColorCheckerSwatch1),  std::span<const float>(kColorCheckerSwatch2),
            std::span<const float>(kColorCheckerSwatch3),  std::span<const float>(kColorCheckerSwatch4),
            std::span<const float>(kColorCheckerSwatch5),  std::span<const float>(kColorCheckerSwatch6),
            std::span<const float>(kColorCheckerSwatch7),  std::span<const float>(kColorCheckerSwatch8),
            std::span<const float>(kColorCheckerSwatch9),  std::span<const float>(kColorCheckerSwatch10),
            std::span<const float>(kColorCheckerSwatch11), std::span<const float>(kColorCheckerSwatch12),
            std::span<const float>(kColorCheckerSwatch13), std::span<const float>(kColorCheckerSwatch14),
            std::span<const float>(kColorCheckerSwatch15), std::span<const float>(kColorCheckerSwatch16),
            std::span<const float>(kColorCheckerSwatch17), std::span<const float>(kColorCheckerSwatch18),
            std::span<const float>(kColorCheckerSwatch19), std::span<const float>(kColorCheckerSwatch20),
            std::span<const float>(kColorCheckerSwatch21), std::span<const float>(kColorCheckerSwatch22),
            std::span<const float>(kColorCheckerSwatch23), std::span<const float>(kColorCheckerSwatch24)};
        std::array<DenseSpectrum, kColorCheckerSwatches> a;
        for (size_t i = 0; i < a.size(); ++i) a[i] = dense_from_pairs(pairs[i]);
        return a;
    }();
    return all;
}

}  // namespace candela
