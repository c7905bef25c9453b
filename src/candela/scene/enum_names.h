#pragma once
// The names the scene file and the command line use for closed sets (integrators, filters, tone
// maps, transfer curves, measured metals): one explicit table per kind, no self-registration (STYLE.md). Also the
// "did you mean" helper that unknown keys and names share.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "candela/film/film_settings.h"
#include "candela/materials/metal_table.h"
#include "candela/scene/render_settings.h"

namespace candela {

// The scene-file name of each value ("ao", "gaussian", "aces", "srgb" ...).
std::string_view integrator_type_name(IntegratorType type);
std::string_view filter_type_name(FilterType type);
std::string_view light_selection_name(LightSelection selection);
std::string_view sampler_type_name(SamplerType type);
std::string_view tonemap_name(Tonemap tonemap);
std::string_view transfer_name(Transfer transfer);
std::string_view metal_name(Metal metal);  // the chemical symbol: "Au", "CuZn" ...

// The value a scene-file name stands for; nullopt for an unknown name (names are case-sensitive).
std::optional<IntegratorType> parse_integrator_type(std::string_view name);
std::optional<FilterType> parse_filter_type(std::string_view name);
std::optional<LightSelection> parse_light_selection(std::string_view name);
std::optional<SamplerType> parse_sampler_type(std::string_view name);
std::optional<Tonemap> parse_tonemap(std::string_view name);
std::optional<Transfer> parse_transfer(std::string_view name);
std::optional<Metal> parse_metal(std::string_view name);

// The film's sensors (FilmSettings::camera_sensor): "cie1931" for kCie1931Sensor, else the
// camera's name (spectrum/camera_sensors.h, pbrt-v4's names). sensor_names() lists "cie1931"
// first, then the cameras in camera_responses()'s order.
std::string_view sensor_name(int camera_sensor);
std::optional<int> parse_sensor(std::string_view name);
std::span<const std::string_view> sensor_names();

// Every valid name of a kind, in the enum's order.
std::span<const std::string_view> integrator_type_names();
std::span<const std::string_view> filter_type_names();
std::span<const std::string_view> light_selection_names();
std::span<const std::string_view> sampler_type_names();
std::span<const std::string_view> tonemap_names();
std::span<const std::string_view> transfer_names();
std::span<const std::string_view> metal_names();

// The names sorted alphabetically and joined as "a, b, c", for "expected one of: ..." messages.
std::string names_list(std::span<const std::string_view> names);

// Optimal-string-alignment edit distance: insertions, deletions, substitutions and swaps of two
// adjacent characters each cost 1 ("shpere" is 1 from "sphere").
size_t edit_distance(std::string_view a, std::string_view b);

// The candidate a typo most likely meant: the nearest by edit_distance, if at most 2 edits away and
// the edits change at most half of the longer word (so "up" never suggests "ao"). Ties go to the
// earlier candidate. nullopt when nothing is that close.
std::optional<std::string> closest_name(std::string_view typo,
                                        std::span<const std::string_view> candidates);

}  // namespace candela
