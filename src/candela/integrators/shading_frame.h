#pragma once
// The shading frame at a hit whose material needs the surface's parametrization
// (Material::needs_shading_geometry): the normal perturbed by a normal map or a bump map, and for
// anisotropic lobes a tangent that follows dpdu. Other materials keep Frame::from_normal(ns).
//
// Shading normals and light leaks: as pbrt-v4 (SurfaceInteraction::SetShadingGeometry), the
// perturbed normal is flipped to the geometric normal's side, and the BSDF is then evaluated and
// sampled in the shading frame alone; the integrators offset rays by the geometric normal on the
// side the direction leaves (ray_offset.h), and light is counted with |cos| to the shading
// normal, as they already do for interpolated vertex normals. We chose this over Schüssler et
// al. 2017 (microfacet-based normal mapping) so that pbrt-v4 scenes render as pbrt-v4 renders
// them, with exact pdfs for MIS and the chi-square tests; Schüssler's energy-conserving model
// would wrap every BSDF in a stochastic evaluation. Our lobes reflect on whichever side of the
// shading normal wo lies (lambertian.h), so a view below the perturbed normal gives no black
// spot; the price, as in pbrt-v4, is that such a reflection may leave below the geometric
// surface (a leak, at grazing views of strongly tilted maps only).
#include "candela/geometry/shading_geometry.h"
#include "candela/geometry/surface_hit.h"
#include "candela/materials/material.h"
#include "candela/math/frame.h"
#include "candela/textures/texture_set.h"

namespace candela {

// pbrt-v4's step for bump-map differences when the ray carries no differentials.
inline constexpr float kBumpDelta = 0.0005f;

// The tangent-space normal a normal map's colour c encodes: 2 c - 1, its y negated for the
// DirectX convention; not normalized.
CANDELA_HD inline Vec3f decode_normal_map(const Vec3f& c, NormalMapConvention convention) {
    Vec3f t = c * 2.0f - Vec3f(1.0f);
    if (convention == NormalMapConvention::kDirectX) t.y = -t.y;
    return t;
}

// ns turned to the tangent-space normal t (pbrt-v4's NormalMap): x along dpdu made perpendicular
// to ns, y = +-cross(ns, x) on the side of +v (the sign of the uv map's handedness, so mirrored
// uvs read their maps the right way up, as MikkTSpace's bitangent sign), z = ns. A flat t
// (0, 0, 1) gives ns back, bit for bit; a t of zero length gives ns.
CANDELA_HD inline Vec3f apply_normal_map(const Vec3f& ns, const ShadingGeometry& g, const Vec3f& t) {
    const float len2 = length_squared(t);
    if (!(len2 > 0.0f) || !is_finite(t)) return ns;
    const Vec3f tn = t * (1.0f / std::sqrt(len2));
    const Frame tangent = Frame::from_normal_and_tangent(ns, g.dpdu);
    const float handedness = dot(cross(g.dpdu, g.dpdv), ns) < 0.0f ? -1.0f : 1.0f;
    return tangent.s * tn.x + tangent.t * (handedness * tn.y) + ns * tn.z;
}

// ns tilted by a height field h(uv, p) along it (pbrt-v4's BumpMap, Blinn 1978): the displaced
// surface p + h ns has derivatives dpdu + (dh/du) ns + h dndu (and likewise in v), dh/du taken
// by forward differences of kBumpDelta in uv; its normal is their cross product, on ns's side
// (cross(dpdu, dpdv) faces away from ns for mirrored uvs). dpdu and dpdv are first made
// perpendicular to ns, as pbrt's shading dpdu is. ns where the result is degenerate.
template <class Height>
CANDELA_HD Vec3f apply_bump_map(const Vec3f& ns, const ShadingGeometry& g, const Vec3f& p, Height&& height) {
    const Vec3f dpdu = g.dpdu - ns * dot(g.dpdu, ns), dpdv = g.dpdv - ns * dot(g.dpdv, ns);
    const float h = height(g.uv, p);
    const float hu = height(g.uv + Vec2f(kBumpDelta, 0.0f), p + dpdu * kBumpDelta);
    const float hv = height(g.uv + Vec2f(0.0f, kBumpDelta), p + dpdv * kBumpDelta);
    const Vec3f bu = dpdu + ns * ((hu - h) / kBumpDelta) + g.dndu * h;
    const Vec3f bv = dpdv + ns * ((hv - h) / kBumpDelta) + g.dndv * h;
    const Vec3f n = cross(bu, bv);
    const float len2 = length_squared(n);
    if (!(len2 > 0.0f) || !is_finite(n)) return ns;
    return face_forward(n * (1.0f / std::sqrt(len2)), ns);
}

// The shading normal of material m at the hit: ns perturbed by its normal map or bump map, on the
// geometric normal's side (pbrt-v4).
CANDELA_HD inline Vec3f mapped_normal(const Material& m, const TextureSet& textures, const ShadingGeometry& g,
                                      const SurfaceHit& hit) {
    const SurfaceParams& s = m.surface;
    Vec3f n = hit.ns;
    if (s.normal_map) {
        const Vec3f c = textures.eval_vector(*s.normal_map, TextureContext{g.uv, hit.p, nullptr, hit.ng});
        n = apply_normal_map(n, g, decode_normal_map(c, s.normal_map_convention));
    } else if (s.bump_map) {
        const FloatParam& bump = *s.bump_map;
        n = apply_bump_map(n, g, hit.p, [&](const Vec2f& uv, const Vec3f& p) {
            return textures.eval(bump, TextureContext{uv, p, nullptr, hit.ng});
        });
    }
    return face_forward(n, hit.ng);
}

// The shading frame of material m at the hit: z the mapped normal, x along dpdu for anisotropic
// lobes (Gram-Schmidt); for isotropic ones Frame::from_normal, as for every other material, so
// that a flat normal map leaves the image unchanged bit for bit.
CANDELA_HD inline Frame shading_frame(const Material& m, const TextureSet& textures, const ShadingGeometry& g,
                                      const SurfaceHit& hit) {
    const Vec3f n = m.surface.perturbs_normal() ? mapped_normal(m, textures, g, hit) : hit.ns;
    return m.anisotropic ? Frame::from_normal_and_tangent(n, g.dpdu) : Frame::from_normal(n);
}

}  // namespace candela
