#pragma once
// The closed set of BSDF lobes a material combines (DESIGN.md: closed sets are variants). Each
// alternative satisfies BsdfLobeType (bsdf_lobe.h). tests/materials/ runs its per-lobe checks
// over every alternative and static_asserts this variant's size, so a new lobe must be added there.
#include "candela/core/variant.h"
#include "candela/materials/conductor.h"
#include "candela/materials/dielectric.h"
#include "candela/materials/diffuse_transmission.h"
#include "candela/materials/fresnel_specular.h"
#include "candela/materials/hair.h"
#include "candela/materials/lambertian.h"
#include "candela/materials/layered.h"
#include "candela/materials/specular_reflection.h"
#include "candela/materials/specular_transmission.h"
#include "candela/materials/thin_dielectric.h"

namespace candela {

using BsdfLobe = Variant<LambertianLobe, SpecularReflectionLobe, FresnelSpecularLobe,
                         SpecularTransmissionLobe, ConductorLobe, DielectricLobe, ThinDielectricLobe,
                         CoatedDiffuseLobe, CoatedConductorLobe, HairLobe, DiffuseTransmissionLobe>;

}  // namespace candela
