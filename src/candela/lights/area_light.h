#pragma once
// A diffuse area light: an emitter's geometry with the radiance it emits. Radiance `emission`
// leaves the front side (the side the normal points to), and the back too when two_sided.
#include <cstdint>

#include "candela/core/platform.h"
#include "candela/core/variant.h"
#include "candela/lights/disk_emitter.h"
#include "candela/lights/mesh_emitter.h"
#include "candela/lights/quadric_emitter.h"
#include "candela/lights/sphere_emitter.h"
#include "candela/math/constants.h"
#include "candela/math/color.h"
#include "candela/spectrum/spectral_color.h"

namespace candela {

using Emitter = Variant<MeshEmitter, SphereEmitter, DiskEmitter, QuadricEmitter>;

// visit(f, emitter) with meshes (and quads), the common emitters, tested first: one comparison
// of the index, where visit compares it with each other alternative (and the valueless state)
// before reaching the first. Each alternative is called from one place only, so that the
// compiler keeps inlining the mesh's sampling into the light set's (measured: a call otherwise).
template <class F>
CANDELA_HD decltype(auto) visit_emitter(const Emitter& emitter, F&& f) {
    static_assert(std::variant_size_v<Emitter> == 4, "visit_emitter must call every emitter type");
    if (const MeshEmitter* mesh = get_if<MeshEmitter>(&emitter)) return f(*mesh);
    if (const SphereEmitter* sphere = get_if<SphereEmitter>(&emitter)) return f(*sphere);
    if (const DiskEmitter* disk = get_if<DiskEmitter>(&emitter)) return f(*disk);
    return f(*get_if<QuadricEmitter>(&emitter));
}

struct AreaLight {
    Emitter emitter;
    Color emission;
    bool two_sided = false;
    uint32_t shape_id = 0;  // in the scene's shapes
    SpectralColor spectral_emission{};  // spectral mode's emission (LightSet::set_spectra)
};

// Radiance leaving a point with front normal n in direction w (away from the surface; need not
// be unit): emission on the front side, or on both when two-sided, else black.
CANDELA_HD inline Color area_light_radiance(const AreaLight& light, const Vec3f& n, const Vec3f& w) {
    return light.two_sided || dot(n, w) > 0.0f ? light.emission : Color();
}
// Whether the light emits towards w from a point with front normal n: spectral mode's test, whose
// value, spectral_emission at the path's wavelengths, LightSet evaluates once per path.
CANDELA_HD inline bool area_light_faces(const AreaLight& light, const Vec3f& n, const Vec3f& w) {
    return light.two_sided || dot(n, w) > 0.0f;
}

// Total emitted power as luminance: a Lambertian emitter sends pi L per unit area from each
// emitting side.
CANDELA_HD inline float area_light_power(const AreaLight& light) {
    float area = visit([](const auto& e) { return e.area(); }, light.emitter);
    return kPi * area * to_rgb(light.emission).luminance() * (light.two_sided ? 2.0f : 1.0f);
}

}  // namespace candela
