#pragma once
// The materials of the scene file, as plain values. Their BSDFs arrive with light transport; for
// now the debug integrators read their albedo.
#include "candela/core/variant.h"
#include "candela/math/rgb.h"

namespace candela {

struct DiffuseMaterial {
    Rgb albedo{0.5f};
};
struct MirrorMaterial {
    Rgb albedo{1.0f};
};
struct DielectricMaterial {
    float ior = 1.5f;
    Rgb tint{1.0f};  // multiplies reflected and refracted light
};

using Material = Variant<DiffuseMaterial, MirrorMaterial, DielectricMaterial>;

// The surface colour the `albedo` integrator shows: albedo, or tint for glass.
CANDELA_HD inline Rgb material_albedo(const Material& m) {
    return visit(Overloaded{[](const DiffuseMaterial& d) { return d.albedo; },
                            [](const MirrorMaterial& d) { return d.albedo; },
                            [](const DielectricMaterial& d) { return d.tint; }},
                 m);
}

}  // namespace candela
