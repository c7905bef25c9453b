#pragma once
// A material is a BSDF: a list of lobes whose values add (see bsdf.h). The scene file's material
// types are the constructors below; `mix` concatenates the lobes of others.
#include <span>

#include "candela/core/check.h"
#include "candela/materials/bsdf.h"

namespace candela {

struct Material {
    Bsdf bsdf;
};

// A material of the one lobe `lobe`.
CANDELA_HD inline Material make_material(const BsdfLobe& lobe) {
    Material m;
    m.bsdf.lobes[0] = lobe;
    m.bsdf.lobe_count = 1;
    return m;
}

// `diffuse`: Lambertian reflection of the given albedo.
CANDELA_HD inline Material make_diffuse(Rgb albedo) {
    return make_material(LambertianLobe{albedo});
}

// `mirror`: perfect specular reflection scaled by albedo.
CANDELA_HD inline Material make_mirror(Rgb albedo) {
    return make_material(SpecularReflectionLobe{albedo});
}

// `dielectric`: smooth glass of index `ior` (inside over outside) reflecting and refracting in
// Fresnel's proportions, exact or by Schlick's approximation.
CANDELA_HD inline Material make_dielectric(float ior, Rgb tint = Rgb(1.0f), bool schlick = false) {
    return make_material(FresnelSpecularLobe{tint, ior, schlick});
}

// `transmission`: the refracted part of a dielectric only (1 - F); the reflected part is lost.
CANDELA_HD inline Material make_transmission(float ior, Rgb tint = Rgb(1.0f)) {
    return make_material(SpecularTransmissionLobe{tint, ior});
}

// `mix`: the lobes of `parts`, in order, in one material (their f add up). The parts may hold at
// most Bsdf::kMaxLobes lobes together (the scene loader checks).
CANDELA_HD inline Material make_mix(std::span<const Material> parts) {
    Material m;
    for (const Material& part : parts) {
        for (uint32_t k = 0; k < part.bsdf.lobe_count; ++k) {
            CANDELA_CHECK(m.bsdf.lobe_count < Bsdf::kMaxLobes);
            m.bsdf.lobes[m.bsdf.lobe_count++] = part.bsdf.lobes[k];
        }
    }
    return m;
}

// The surface colour the `albedo` integrator shows: the sum of the lobes' albedo or tint.
CANDELA_HD inline Rgb material_albedo(const Material& m) { return m.bsdf.albedo(); }

}  // namespace candela
