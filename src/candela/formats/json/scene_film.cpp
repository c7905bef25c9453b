// The film's pixel filter, crop window and AOV layers (docs/SCENE_FORMAT.md, "film").
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "candela/film/pixel_filter.h"
#include "candela/formats/json/scene_sections.h"
#include "candela/scene/enum_names.h"

namespace candela {

namespace {

// The object form's types: pbrt-v4's filter names, with its sinc filter called lanczos.
constexpr std::array<std::string_view, 5> kFilterObjectTypes = {"box", "triangle", "gaussian", "mitchell", "lanczos"};
constexpr std::array<FilterType, 5> kFilterObjectValues = {FilterType::kBox, FilterType::kTent,
                                                           FilterType::kOffsetGaussian, FilterType::kMitchell,
                                                           FilterType::kLanczos};
// The largest radius, in pixels: a tabulated filter keeps 32 cells per pixel of radius.
constexpr double kMaxFilterRadius = 1024.0;

// A radius: one number for both axes, or [x, y].
Vec2f read_radius(const JsonCursor& v) {
    const Bounds bounds{0.0, kMaxFilterRadius, true, false};
    if (v.is_number()) {
        const float r = v.number_f(bounds);
        return {r, r};
    }
    if (!v.is_array()) v.fail_expected("a radius in pixels: a number or an array of 2 numbers [x, y]");
    std::vector<JsonCursor> e = v.elements(2, "a radius in pixels: a number or an array of 2 numbers [x, y]");
    return {e[0].number_f(bounds), e[1].number_f(bounds)};
}

}  // namespace

FilterSettings read_filter(JsonCursor v) {
    if (v.is_string()) return *parse_filter_type(v.choice("filter", filter_type_names()));
    if (!v.is_object())
        v.fail_expected("a filter name (box, tent, gaussian, smallpt) or an object such as {\"type\": \"mitchell\"}");
    const std::string_view name = v.require("type").choice("filter type", kFilterObjectTypes);
    FilterSettings filter;
    filter.type = kFilterObjectValues[size_t(std::find(kFilterObjectTypes.begin(), kFilterObjectTypes.end(), name) -
                                             kFilterObjectTypes.begin())];
    const float r = default_filter_radius(filter.type);
    filter.radius = {r, r};
    if (auto radius = v.get("radius")) filter.radius = read_radius(*radius);
    // Each type reads only its own parameters, so another type's is an unknown key.
    if (filter.type == FilterType::kOffsetGaussian)
        if (auto sigma = v.get("sigma")) filter.sigma = sigma->number_f(Bounds::above(0));
    if (filter.type == FilterType::kMitchell) {
        if (auto b = v.get("B")) filter.b = b->number_f();
        if (auto c = v.get("C")) filter.c = c->number_f();
    }
    if (filter.type == FilterType::kLanczos)
        if (auto tau = v.get("tau")) filter.tau = tau->number_f(Bounds::above(0));
    v.reject_unknown_keys();
    // A table of zeros (or one that overflows) has nothing to sample.
    const float integral = PixelFilter(filter).table_integral();
    if (!(integral > 0.0f) || !std::isfinite(integral))
        v.fail(fmt::format("this {} filter's integral of |f| is {}: it has nothing to sample", name, integral));
    return filter;
}

std::array<float, 4> read_crop_window(const JsonCursor& crop, const CameraSettings& camera) {
    std::vector<JsonCursor> e = crop.elements(4, "an array of 4 numbers [x0, x1, y0, y1] in [0, 1]");
    std::array<float, 4> w{};
    for (size_t i = 0; i < 4; ++i) w[i] = e[i].number_f(Bounds::closed(0, 1));
    for (size_t axis = 0; axis < 2; ++axis)
        if (!(w[2 * axis] < w[2 * axis + 1]))
            e[2 * axis + 1].fail(fmt::format("expected a number > {} ({}0), got {}", w[2 * axis], axis == 0 ? "x" : "y",
                                             e[2 * axis + 1].describe()));
    const PixelBounds b = crop_pixel_bounds(camera.width, camera.height, w);
    if (b.width() < 1 || b.height() < 1)
        crop.fail(fmt::format("the crop window covers no pixel of the {}x{} image (pixels [{}, {}) x [{}, {}))",
                              camera.width, camera.height, b.x0, b.x1, b.y0, b.y1));
    return w;
}

AovLayers read_aov_layers(const JsonCursor& aovs) {
    static const std::array<std::string_view, kAovLayerCount> names = [] {
        std::array<std::string_view, kAovLayerCount> n;
        for (int i = 0; i < kAovLayerCount; ++i) n[size_t(i)] = kAovLayerInfo[size_t(i)].name;
        return n;
    }();
    if (!aovs.is_array()) aovs.fail_expected(fmt::format("an array of AOV layer names ({})", kAovLayerNames));
    AovLayers layers;
    for (const JsonCursor& e : aovs.elements()) {
        const AovLayer layer = *parse_aov_layer(e.choice("AOV layer", names));
        const std::string_view name = aov_layer_info(layer).name;
        if (layers.has(layer)) e.fail(fmt::format("AOV layer \"{}\" is listed twice", name));
        layers.add(layer);
    }
    return layers;
}

}  // namespace candela
