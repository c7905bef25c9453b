#pragma once
// The directives of pbrt-v4's scene format (pbrt-v4's src/pbrt/parser.cpp, parse()), plus
// pbrt-v3's WorldEnd, which the parser ignores with a warning.
#include <algorithm>
#include <array>
#include <optional>
#include <string_view>
#include <utility>

namespace candela::pbrt {

enum class Directive {
    Accelerator, ActiveTransform, AreaLightSource, Attribute, AttributeBegin, AttributeEnd, Camera,
    ColorSpace, ConcatTransform, CoordSysTransform, CoordinateSystem, Film, Identity, Import, Include,
    Integrator, LightSource, LookAt, MakeNamedMaterial, MakeNamedMedium, Material, MediumInterface,
    NamedMaterial, ObjectBegin, ObjectEnd, ObjectInstance, Option, PixelFilter, ReverseOrientation,
    Rotate, Sampler, Scale, Shape, Texture, Transform, TransformBegin, TransformEnd, TransformTimes,
    Translate, WorldBegin, WorldEnd,
};

inline constexpr std::array<std::pair<std::string_view, Directive>, 41> kDirectives{{
    {"Accelerator", Directive::Accelerator},
    {"ActiveTransform", Directive::ActiveTransform},
    {"AreaLightSource", Directive::AreaLightSource},
    {"Attribute", Directive::Attribute},
    {"AttributeBegin", Directive::AttributeBegin},
    {"AttributeEnd", Directive::AttributeEnd},
    {"Camera", Directive::Camera},
    {"ColorSpace", Directive::ColorSpace},
    {"ConcatTransform", Directive::ConcatTransform},
    {"CoordSysTransform", Directive::CoordSysTransform},
    {"CoordinateSystem", Directive::CoordinateSystem},
    {"Film", Directive::Film},
    {"Identity", Directive::Identity},
    {"Import", Directive::Import},
    {"Include", Directive::Include},
    {"Integrator", Directive::Integrator},
    {"LightSource", Directive::LightSource},
    {"LookAt", Directive::LookAt},
    {"MakeNamedMaterial", Directive::MakeNamedMaterial},
    {"MakeNamedMedium", Directive::MakeNamedMedium},
    {"Material", Directive::Material},
    {"MediumInterface", Directive::MediumInterface},
    {"NamedMaterial", Directive::NamedMaterial},
    {"ObjectBegin", Directive::ObjectBegin},
    {"ObjectEnd", Directive::ObjectEnd},
    {"ObjectInstance", Directive::ObjectInstance},
    {"Option", Directive::Option},
    {"PixelFilter", Directive::PixelFilter},
    {"ReverseOrientation", Directive::ReverseOrientation},
    {"Rotate", Directive::Rotate},
    {"Sampler", Directive::Sampler},
    {"Scale", Directive::Scale},
    {"Shape", Directive::Shape},
    {"Texture", Directive::Texture},
    {"Transform", Directive::Transform},
    {"TransformBegin", Directive::TransformBegin},
    {"TransformEnd", Directive::TransformEnd},
    {"TransformTimes", Directive::TransformTimes},
    {"Translate", Directive::Translate},
    {"WorldBegin", Directive::WorldBegin},
    {"WorldEnd", Directive::WorldEnd},
}};

// The directive named `word` (case-sensitive, as in pbrt-v4), if any. The table is sorted.
inline std::optional<Directive> find_directive(std::string_view word) {
    const auto it = std::lower_bound(kDirectives.begin(), kDirectives.end(), word,
                                     [](const auto& entry, std::string_view w) { return entry.first < w; });
    if (it == kDirectives.end() || it->first != word) return std::nullopt;
    return it->second;
}

}  // namespace candela::pbrt
