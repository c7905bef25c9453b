#include "candela/scene/enum_names.h"

#include <algorithm>
#include <array>
#include <vector>

#include "candela/spectrum/camera_sensors.h"

namespace candela {

namespace {

// Each table lists the names in the enum's declaration order, so a value's name is
// table[underlying value]. Adding an enumerator means adding its name here.
constexpr std::array<std::string_view, 8> kIntegratorTypeNames = {"path",  "bsdf",   "whitted", "normals",
                                                                  "depth", "albedo", "ao",      "volpath"};
constexpr std::array<std::string_view, 2> kLightSelectionNames = {"power", "uniform"};
constexpr std::array<std::string_view, 2> kSamplerTypeNames = {"independent", "sobol"};
constexpr std::array<std::string_view, 4> kFilterTypeNames = {"box", "tent", "gaussian", "smallpt"};
constexpr std::array<std::string_view, 4> kTonemapNames = {"clamp", "exposure", "reinhard", "aces"};
constexpr std::array<std::string_view, 2> kTransferNames = {"srgb", "gamma"};
// In the order of materials/metal_table.h's enum Metal.
constexpr std::array<std::string_view, kMetalCount> kMetalNames = {"Au", "Ag", "Cu", "Al",
                                                                   "Cr", "Fe", "Ti", "CuZn"};

template <class E, size_t N>
std::string_view name_of(const std::array<std::string_view, N>& table, E value) {
    auto i = static_cast<size_t>(value);
    return i < N ? table[i] : std::string_view("unknown");
}

template <class E, size_t N>
std::optional<E> value_of(const std::array<std::string_view, N>& table, std::string_view name) {
    for (size_t i = 0; i < N; ++i)
        if (table[i] == name) return static_cast<E>(i);
    return std::nullopt;
}

}  // namespace

std::string_view integrator_type_name(IntegratorType type) {
    return name_of(kIntegratorTypeNames, type);
}
std::string_view filter_type_name(FilterType type) { return name_of(kFilterTypeNames, type); }
std::string_view light_selection_name(LightSelection s) { return name_of(kLightSelectionNames, s); }
std::string_view sampler_type_name(SamplerType t) { return name_of(kSamplerTypeNames, t); }
std::string_view tonemap_name(Tonemap tonemap) { return name_of(kTonemapNames, tonemap); }
std::string_view transfer_name(Transfer transfer) { return name_of(kTransferNames, transfer); }
std::string_view metal_name(Metal metal) { return name_of(kMetalNames, metal); }

std::optional<IntegratorType> parse_integrator_type(std::string_view name) {
    return value_of<IntegratorType>(kIntegratorTypeNames, name);
}
std::optional<FilterType> parse_filter_type(std::string_view name) {
    return value_of<FilterType>(kFilterTypeNames, name);
}
std::optional<LightSelection> parse_light_selection(std::string_view name) {
    return value_of<LightSelection>(kLightSelectionNames, name);
}
std::optional<SamplerType> parse_sampler_type(std::string_view name) {
    return value_of<SamplerType>(kSamplerTypeNames, name);
}
std::optional<Tonemap> parse_tonemap(std::string_view name) {
    return value_of<Tonemap>(kTonemapNames, name);
}
std::optional<Transfer> parse_transfer(std::string_view name) {
    return value_of<Transfer>(kTransferNames, name);
}
std::optional<Metal> parse_metal(std::string_view name) { return value_of<Metal>(kMetalNames, name); }

std::span<const std::string_view> integrator_type_names() { return kIntegratorTypeNames; }
std::span<const std::string_view> filter_type_names() { return kFilterTypeNames; }
std::span<const std::string_view> light_selection_names() { return kLightSelectionNames; }
std::span<const std::string_view> sampler_type_names() { return kSamplerTypeNames; }
std::span<const std::string_view> tonemap_names() { return kTonemapNames; }
std::span<const std::string_view> transfer_names() { return kTransferNames; }
std::span<const std::string_view> metal_names() { return kMetalNames; }

std::string names_list(std::span<const std::string_view> names) {
    std::vector<std::string_view> sorted(names.begin(), names.end());
    std::sort(sorted.begin(), sorted.end());
    std::string out;
    for (std::string_view n : sorted) {
        if (!out.empty()) out += ", ";
        out += n;
    }
    return out;
}

// The optimal-string-alignment variant of Damerau-Levenshtein (Wagner-Fischer with an extra
// transposition case), over three rolling rows: names are short, so O(|a| |b|) is nothing.
size_t edit_distance(std::string_view a, std::string_view b) {
    const size_t n = b.size();
    std::vector<size_t> before(n + 1), prev(n + 1), cur(n + 1);
    for (size_t j = 0; j <= n; ++j) prev[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (size_t j = 1; j <= n; ++j) {
            size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                cur[j] = std::min(cur[j], before[j - 2] + 1);
        }
        std::swap(before, prev);
        std::swap(prev, cur);
    }
    return prev[n];
}

std::string_view sensor_name(int camera_sensor) {
    return camera_sensor == kCie1931Sensor ? sensor_names()[0] : camera_responses()[size_t(camera_sensor)].name;
}

std::optional<int> parse_sensor(std::string_view name) {
    if (name == sensor_names()[0]) return kCie1931Sensor;
    const int i = camera_response_index(name);
    if (i < 0) return std::nullopt;
    return i;
}

std::span<const std::string_view> sensor_names() {
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> n{"cie1931"};
        for (const CameraResponse& c : camera_responses()) n.push_back(c.name);
        return n;
    }();
    return names;
}

std::optional<std::string> closest_name(std::string_view typo,
                                        std::span<const std::string_view> candidates) {
    constexpr size_t kMaxEdits = 2;
    std::optional<std::string> best;
    size_t best_distance = kMaxEdits + 1;
    for (std::string_view c : candidates) {
        size_t d = edit_distance(typo, c);
        // Two edits turn any two-letter word into any other: demand that most of it survives.
        bool plausible = 2 * d <= std::max(typo.size(), c.size());
        if (plausible && d < best_distance) {
            best_distance = d;
            best = std::string(c);
        }
    }
    return best;
}

}  // namespace candela
