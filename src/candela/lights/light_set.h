#pragma once
// The scene's lights: every shape with emission (area lights), the environment, and the point,
// spot and directional lights (delta lights, delta_light_type.h). Diffuse emitters: radiance
// `emission` leaves the front side (the side the geometric normal points to), both sides when
// two_sided. Selection among all lights is proportional to emitted power (or uniform); points are
// sampled uniformly by area on meshes, quads and disks, and by the cone of directions a sphere
// subtends when seen from outside (uniformly by area from inside). All pdfs are per unit solid
// angle at the reference point: area pdf * distance^2 / |cos theta_light|. A delta light's sample
// is certain: its pdf is the probability of selecting the light, and it is marked is_delta.
//
// Selection indices: the area lights first, then the environment, then the delta lights, so that
// the area lights' path through sample() is the same whether a scene has delta lights or not.
//
// A shape with emission but zero area (degenerate triangles) cannot be hit or sampled and is not
// a light. Random numbers: uc picks the light (only read when there are several: uses_choice());
// u picks the triangle of a mesh and places the point (MeshEmitter::sample).
//
// With LightSelection::kBvh the choice depends on the point lit: pbrt-v4's BVH light sampler
// (light_bvh.h) over the area, point and spot lights, with the environment and directional lights
// as its "infinite" lights. sample() and pdf() then take the point's surface normal (shading
// normal; zero in a medium), as pbrt-v4's LightSampleContext does.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "candela/core/platform.h"
#include "candela/geometry/disk.h"
#include "candela/geometry/quadric.h"
#include "candela/geometry/shape.h"
#include "candela/geometry/sphere.h"
#include "candela/geometry/triangle_mesh.h"
#include "candela/lights/area_light.h"
#include "candela/lights/delta_light.h"
#include "candela/lights/environment_light.h"
#include "candela/lights/light_bvh.h"
#include "candela/lights/light_sample.h"
#include "candela/lights/light_selection.h"
#include "candela/lights/spectral_emission_cache.h"
#include "candela/sampling/distribution_1d.h"

namespace candela {

class LightSet {
  public:
    LightSet() = default;
    // The spans of geometry must outlive the set. Shapes with black emission are not lights. The
    // environment, if any, and the delta lights compete for selection with the area lights, by
    // their power for a scene of bounding-sphere radius `scene_radius` (EnvironmentLight::power,
    // DeltaLightType::power); delta lights of zero power are left out.
    LightSet(std::span<const TriangleMesh> meshes, std::span<const Sphere> spheres, std::span<const Disk> disks,
             std::span<const Shape> shapes, std::span<const DeltaLight> delta_lights, LightSelection selection,
             std::optional<EnvironmentLight> environment, float scene_radius,
             std::span<const Quadric> quadrics = {});
    // Area lights of meshes and spheres, and the environment.
    LightSet(std::span<const TriangleMesh> meshes, std::span<const Sphere> spheres, std::span<const Shape> shapes,
             LightSelection selection = LightSelection::kPower,
             std::optional<EnvironmentLight> environment = std::nullopt, float scene_radius = 1.0f)
        : LightSet(meshes, spheres, {}, shapes, {}, selection, std::move(environment), scene_radius) {}

    // The count of all lights is kept, not summed from the three kinds: the integrators ask
    // empty() and uses_choice() at every vertex.
    CANDELA_HD bool empty() const { return size_ == 0; }
    CANDELA_HD size_t size() const { return size_; }
    CANDELA_HD bool has_environment() const { return environment_.has_value(); }
    // Whether there are point, spot or directional lights, which only light sampling can find.
    CANDELA_HD bool has_delta_lights() const { return !delta_lights_.empty(); }
    // Whether sample() reads uc: there is more than one light to choose from.
    CANDELA_HD bool uses_choice() const { return size() > 1; }

    // Spectral mode: the emission of the area light of each shape (indexed by shape id; shapes
    // that are not lights are skipped) and of each delta light (in the order the constructor got
    // them, including any it left out). The spectra must outlive the set.
    void set_spectra(std::span<const SpectralColor> shape_emission, std::span<const SpectralColor> delta_emission);

    // The functions below give RGB-mode colours, and with `lambda` the values at a path's
    // wavelengths (spectral mode): two instances of one template each, so that RGB mode's code
    // is what it was before spectral mode existed. A spectral `cache` (one per path, optional)
    // holds the lights' emission at the path's wavelengths.

    // Radiance arriving from world direction w (unit) from the environment; black without one.
    Color environment_radiance(const Vec3f& w) const { return environment_radiance_in<false>(w, nullptr); }
    Color environment_radiance(const Vec3f& w, const Color& lambda) const {
        return environment_radiance_in<true>(w, &lambda);
    }
    // The pdf per solid angle (selection included) with which sample() produces direction w
    // towards the environment; 0 without one.
    float environment_pdf(const Vec3f& w) const;

    // Samples a light (with uc) and a point on it (with u) as seen from `ref`.
    // nullopt when nothing can be sampled (no lights, a zero pdf, or a delta light that sends
    // nothing to ref). A point on the back of a one-sided light comes back with black Le and its
    // true pdf (a sphere of reverse orientation seen from outside shows only its back).
    // `ref_n`: the surface normal at ref, or zero in a medium (read only by kBvh).
    CANDELA_HD std::optional<LightSample> sample(const Vec3f& ref, const Vec3f& ref_n, float uc,
                                                 const Vec2f& u) const {
        return sample_in<false>(ref, ref_n, uc, u, nullptr, nullptr);
    }
    CANDELA_HD std::optional<LightSample> sample(const Vec3f& ref, const Vec3f& ref_n, float uc, const Vec2f& u,
                                                 const Color& lambda, SpectralEmissionCache* cache = nullptr) const {
        return sample_in<true>(ref, ref_n, uc, u, &lambda, cache);
    }
    // The same as seen from a point in a medium (no normal).
    CANDELA_HD std::optional<LightSample> sample(const Vec3f& ref, float uc, const Vec2f& u) const {
        return sample_in<false>(ref, Vec3f{}, uc, u, nullptr, nullptr);
    }
    CANDELA_HD std::optional<LightSample> sample(const Vec3f& ref, float uc, const Vec2f& u, const Color& lambda,
                                                 SpectralEmissionCache* cache = nullptr) const {
        return sample_in<true>(ref, Vec3f{}, uc, u, &lambda, cache);
    }

    // The pdf per solid angle (selection included) with which sample() from `ref` would have
    // produced point `p_light` with front normal `n_light` on shape `shape_id`; 0 if that shape
    // is not a light. Bit-identical to the pdf sample() returned for that point. `ref_n` as for
    // sample(); the form without it is for a point in a medium.
    CANDELA_HD float pdf(const Vec3f& ref, const Vec3f& ref_n, uint32_t shape_id, const Vec3f& p_light,
                         const Vec3f& n_light) const;
    CANDELA_HD float pdf(const Vec3f& ref, uint32_t shape_id, const Vec3f& p_light, const Vec3f& n_light) const {
        return pdf(ref, Vec3f{}, shape_id, p_light, n_light);
    }

    // Radiance leaving a point of shape `shape_id` with front normal n in direction w (unit,
    // pointing away from the surface); black for non-emitters and from behind one-sided ones.
    CANDELA_HD Color emitted(uint32_t shape_id, const Vec3f& n, const Vec3f& w) const {
        return emitted_in<false>(shape_id, n, w, nullptr, nullptr);
    }
    CANDELA_HD Color emitted(uint32_t shape_id, const Vec3f& n, const Vec3f& w, const Color& lambda,
                             SpectralEmissionCache* cache = nullptr) const {
        return emitted_in<true>(shape_id, n, w, &lambda, cache);
    }

    // The probability that sample() picks the light of shape `shape_id`; 0 if it is not a light.
    // For kPower and kUniform (the same at every point); kBvh: selection_probability(ref, ref_n, ...).
    CANDELA_HD float selection_probability(uint32_t shape_id) const;
    // The probability that sample() from (ref, ref_n) picks the light of shape `shape_id`.
    CANDELA_HD float selection_probability(const Vec3f& ref, const Vec3f& ref_n, uint32_t shape_id) const;
    // The probability that sample() from (ref, ref_n) picks delta light `index` (in the order the
    // constructor got them); 0 for one it left out.
    CANDELA_HD float delta_selection_probability(const Vec3f& ref, const Vec3f& ref_n, uint32_t index) const;
    // The probability that sample() picks the environment (the same at every point); 0 without one.
    CANDELA_HD float environment_selection_probability() const {
        return environment_ ? selection_probability_[lights_.size()] : 0.0f;
    }

  private:
    static constexpr uint32_t kNoLight = 0xffffffffu;

    // The mode's implementations (lambda and cache null when !kSpectral; cache may be null when
    // kSpectral); instantiated in light_set.cpp.
    template <bool kSpectral>
    Color environment_radiance_in(const Vec3f& w, const Color* lambda) const;
    template <bool kSpectral>
    CANDELA_HD std::optional<LightSample> sample_in(const Vec3f& ref, const Vec3f& ref_n, float uc, const Vec2f& u,
                                                    const Color* lambda, SpectralEmissionCache* cache) const;
    template <bool kSpectral>
    CANDELA_HD Color emitted_in(uint32_t shape_id, const Vec3f& n, const Vec3f& w, const Color* lambda,
                                SpectralEmissionCache* cache) const;

    // sample() for delta_lights_[index], chosen with `probability`: written into `result`, out
    // of line (the area lights' and the environment's paths stay as they were without delta
    // lights).
    template <bool kSpectral>
    CANDELA_HD void sample_delta_light_at(const Vec3f& ref, uint32_t index, float probability, const Color* lambda,
                                          SpectralEmissionCache* cache, std::optional<LightSample>& result) const;

    // Area light `li`'s spectral emission at `lambda`, through the path's cache when given.
    CANDELA_HD Color area_emission(uint32_t li, const Color& lambda, SpectralEmissionCache* cache) const {
        const SpectralColor& e = lights_[li].spectral_emission;
        return cache ? cache->get(li, e, lambda) : e.eval(lambda);
    }

    // The index in lights_ of shape `shape_id`, or kNoLight.
    CANDELA_HD uint32_t light_index(uint32_t shape_id) const {
        return shape_id < light_of_shape_.size() ? light_of_shape_[shape_id] : kNoLight;
    }

    std::vector<AreaLight> lights_;
    std::vector<uint32_t> light_of_shape_;  // shape id -> index in lights_, or kNoLight
    std::optional<EnvironmentLight> environment_;
    std::vector<DeltaLight> delta_lights_;
    std::vector<uint32_t> delta_source_;          // delta_lights_[i] is the constructor's delta_source_[i]
    std::vector<SpectralColor> delta_spectral_;   // parallel to delta_lights_ (set_spectra)
    uint32_t delta_begin_ = 0;              // the selection index of delta_lights_[0]
    size_t size_ = 0;                       // area lights, environment and delta lights
    Distribution1D selection_;              // over lights_, then the environment, then delta_lights_
    std::vector<float> selection_probability_;  // selection_.probability(i), computed once: it
                                                // divides in double, and NEE and MIS ask per vertex;
                                                // with kBvh, the environment's is the BVH's share
    std::optional<LightBvh> bvh_;  // kBvh only: the choice by importance, over the selection indices
};

}  // namespace candela
