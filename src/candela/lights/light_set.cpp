#include "candela/lights/light_set.h"

#include <cmath>

#include "candela/core/check.h"
#include "candela/lights/emitter_bounds.h"

namespace candela {

namespace {

// The emitter of a shape's geometry.
Emitter make_emitter(const Shape& shape, std::span<const TriangleMesh> meshes, std::span<const Sphere> spheres,
                     std::span<const Disk> disks, std::span<const Quadric> quadrics) {
    // A disk shape given to the constructor without disks would read past the span. Curves do
    // not emit (the loaders refuse it, as pbrt-v4 cannot sample them).
    CANDELA_CHECK(shape.kind != ShapeKind::kCurves);
    CANDELA_CHECK(shape.index < (shape.kind == ShapeKind::kMesh     ? meshes.size()
                                 : shape.kind == ShapeKind::kSphere ? spheres.size()
                                 : shape.kind == ShapeKind::kQuadric ? quadrics.size()
                                                                    : disks.size()));
    switch (shape.kind) {
        case ShapeKind::kMesh: return MeshEmitter(meshes[shape.index]);
        case ShapeKind::kSphere: return SphereEmitter{spheres[shape.index]};
        case ShapeKind::kDisk: return DiskEmitter(disks[shape.index]);
        case ShapeKind::kQuadric: return QuadricEmitter(quadrics[shape.index]);
        case ShapeKind::kCurves: break;
    }
    return SphereEmitter{};
}

}  // namespace

LightSet::LightSet(std::span<const TriangleMesh> meshes, std::span<const Sphere> spheres, std::span<const Disk> disks,
                   std::span<const Shape> shapes, std::span<const DeltaLight> delta_lights, LightSelection selection,
                   std::optional<EnvironmentLight> environment, float scene_radius,
                   std::span<const Quadric> quadrics)
    : light_of_shape_(shapes.size(), kNoLight), environment_(std::move(environment)) {
    std::vector<float> weights;
    // kBvh: each light's bounds (or none: infinite), by selection index. The weights above stay
    // the powers, unused but for keeping selection_ the same size.
    const bool bvh = selection == LightSelection::kBvh;
    std::vector<std::pair<uint32_t, LightBounds>> bounded;
    std::vector<uint32_t> infinite;
    for (size_t id = 0; id < shapes.size(); ++id) {
        const Shape& shape = shapes[id];
        if (shape.emission.is_black()) continue;
        AreaLight light{make_emitter(shape, meshes, spheres, disks, quadrics), from_rgb(shape.emission), shape.two_sided,
                        static_cast<uint32_t>(id)};
        float area = visit([](const auto& e) { return e.area(); }, light.emitter);
        if (!(area > 0.0f) || !std::isfinite(area)) continue;
        light_of_shape_[id] = static_cast<uint32_t>(lights_.size());
        if (bvh) bounded.emplace_back(uint32_t(weights.size()), area_light_bounds(shape, meshes, spheres, disks, quadrics, area));
        weights.push_back(selection != LightSelection::kUniform ? area_light_power(light) : 1.0f);
        lights_.push_back(std::move(light));
    }
    if (environment_) {
        float power = environment_->power(scene_radius);
        if (power > 0.0f && std::isfinite(power)) {
            if (bvh) infinite.push_back(uint32_t(weights.size()));
            weights.push_back(selection != LightSelection::kUniform ? power : 1.0f);
        } else
            environment_.reset();  // black: nothing to see or sample
    }
    delta_begin_ = static_cast<uint32_t>(weights.size());
    for (size_t i = 0; i < delta_lights.size(); ++i) {
        const DeltaLight& light = delta_lights[i];
        float power = delta_light_power(light, scene_radius);
        if (!(power > 0.0f) || !std::isfinite(power)) continue;  // black: it would light nothing
        if (bvh) {
            if (std::optional<LightBounds> b = delta_light_bounds(light))
                bounded.emplace_back(uint32_t(weights.size()), *b);
            else
                infinite.push_back(uint32_t(weights.size()));
        }
        weights.push_back(selection != LightSelection::kUniform ? power : 1.0f);
        delta_lights_.push_back(light);
        delta_source_.push_back(static_cast<uint32_t>(i));
    }
    delta_spectral_.resize(delta_lights_.size());
    size_ = weights.size();
    selection_ = Distribution1D(weights);
    for (size_t i = 0; i < weights.size(); ++i) selection_probability_.push_back(selection_.probability(i));
    if (bvh) {
        bvh_.emplace(std::move(bounded), std::move(infinite), static_cast<uint32_t>(size_));
        // The environment's share is the same at every point: environment_pdf() reads it here.
        if (environment_) selection_probability_[lights_.size()] = bvh_->infinite_pmf();
    }
}

void LightSet::set_spectra(std::span<const SpectralColor> shape_emission, std::span<const SpectralColor> delta_emission) {
    for (AreaLight& light : lights_) light.spectral_emission = shape_emission[light.shape_id];
    for (size_t i = 0; i < delta_lights_.size(); ++i) delta_spectral_[i] = delta_emission[delta_source_[i]];
}

// An environment map's RGB radiance as the mode sees it; in spectral mode uplifted per lookup
// as an illuminant (pbrt-v4's ImageInfiniteLight).
template <bool kSpectral>
static Color environment_color(const Rgb& rgb, const Color* lambda) {
    if constexpr (kSpectral)
        return rgb_illuminant_spectrum(rgb).eval(*lambda);
    else
        return from_rgb(rgb);
}

template <bool kSpectral>
Color LightSet::environment_radiance_in(const Vec3f& w, const Color* lambda) const {
    return environment_ ? environment_color<kSpectral>(environment_->radiance(w), lambda) : Color(0.0f);
}

float LightSet::environment_pdf(const Vec3f& w) const {
    if (!environment_) return 0.0f;
    return selection_probability_[lights_.size()] * environment_->pdf(w);
}

template <bool kSpectral>
CANDELA_HD std::optional<LightSample> LightSet::sample_in(const Vec3f& ref, const Vec3f& ref_n, float uc,
                                                          const Vec2f& u, const Color* lambda,
                                                          SpectralEmissionCache* cache) const {
    // The one object returned on every path, built in place where the caller receives it.
    std::optional<LightSample> result;
    if (selection_.empty()) return result;
    uint32_t chosen;
    float probability;
    if (bvh_) {
        std::optional<LightBvh::Choice> c = bvh_->sample(ref, ref_n, uc);
        if (!c) return result;  // no light can reach ref
        chosen = c->light;
        probability = c->pmf;
    } else {
        chosen = uses_choice() ? selection_.sample_discrete(uc).index : 0;
        probability = selection_probability_[chosen];
    }
    if (chosen >= lights_.size()) {  // the environment or a delta light
        if (chosen >= delta_begin_) {
            sample_delta_light_at<kSpectral>(ref, chosen - delta_begin_, probability, lambda, cache, result);
            return result;
        }
        std::optional<EnvironmentSample> es = environment_->sample(u);
        if (!es) return result;
        float pdf = probability * es->pdf;
        if (!(pdf > 0.0f) || !std::isfinite(pdf)) return result;
        result.emplace(LightSample{ref + es->wi, -es->wi, es->wi, true, false, environment_color<kSpectral>(es->Le, lambda), pdf});
        return result;
    }
    const AreaLight& light = lights_[chosen];
    std::optional<EmitterSample> es = visit_emitter(light.emitter, [&](const auto& e) { return e.sample(ref, u); });
    if (!es) return result;
    // The same product, in the same order, as pdf() computes.
    float pdf = probability * es->pdf;
    if (!(pdf > 0.0f) || !std::isfinite(pdf)) return result;
    LightSample& ls = result.emplace();
    ls.p = es->p;
    ls.n = es->n;
    ls.wi = es->wi;
    ls.infinite = false;
    if constexpr (kSpectral)
        ls.Le = area_light_faces(light, es->n, -es->wi) ? area_emission(chosen, *lambda, cache) : Color();
    else
        ls.Le = area_light_radiance(light, es->n, -es->wi);
    ls.pdf = pdf;
    return result;
}

template <bool kSpectral>
CANDELA_HD void LightSet::sample_delta_light_at(const Vec3f& ref, uint32_t index, float probability,
                                                const Color* lambda, SpectralEmissionCache* cache,
                                                std::optional<LightSample>& result) const {
    std::optional<DeltaLightSample> ds = sample_delta_light(delta_lights_[index], ref);
    if (!ds || ds->Li.is_black()) return;
    Color Li = ds->Li;
    if constexpr (kSpectral) {
        const SpectralColor& e = delta_spectral_[index];
        Li = (cache ? cache->get(delta_begin_ + index, e, *lambda) : e.eval(*lambda)) * ds->factor;
    }
    // The sample is certain given the light: the only density is the selection's.
    result.emplace(LightSample{ds->p, -ds->wi, ds->wi, ds->infinite, true, Li, probability});
}

CANDELA_HD float LightSet::pdf(const Vec3f& ref, const Vec3f& ref_n, uint32_t shape_id, const Vec3f& p_light,
                               const Vec3f& n_light) const {
    uint32_t li = light_index(shape_id);
    if (li == kNoLight) return 0.0f;
    float emitter_pdf =
        visit_emitter(lights_[li].emitter, [&](const auto& e) { return e.pdf(ref, p_light, n_light); });
    const float probability = bvh_ ? bvh_->pmf(ref, ref_n, li) : selection_probability_[li];
    return probability * emitter_pdf;
}

template <bool kSpectral>
CANDELA_HD Color LightSet::emitted_in(uint32_t shape_id, const Vec3f& n, const Vec3f& w, const Color* lambda,
                                     SpectralEmissionCache* cache) const {
    uint32_t li = light_index(shape_id);
    if (li == kNoLight) return Color();
    if constexpr (kSpectral)
        return area_light_faces(lights_[li], n, w) ? area_emission(li, *lambda, cache) : Color();
    else
        return area_light_radiance(lights_[li], n, w);
}

CANDELA_HD float LightSet::selection_probability(uint32_t shape_id) const {
    uint32_t li = light_index(shape_id);
    return li == kNoLight ? 0.0f : selection_probability_[li];
}

CANDELA_HD float LightSet::selection_probability(const Vec3f& ref, const Vec3f& ref_n, uint32_t shape_id) const {
    uint32_t li = light_index(shape_id);
    if (li == kNoLight) return 0.0f;
    return bvh_ ? bvh_->pmf(ref, ref_n, li) : selection_probability_[li];
}

CANDELA_HD float LightSet::delta_selection_probability(const Vec3f& ref, const Vec3f& ref_n, uint32_t index) const {
    for (size_t i = 0; i < delta_source_.size(); ++i) {
        if (delta_source_[i] != index) continue;
        const uint32_t chosen = delta_begin_ + static_cast<uint32_t>(i);
        return bvh_ ? bvh_->pmf(ref, ref_n, chosen) : selection_probability_[chosen];
    }
    return 0.0f;
}

template Color LightSet::environment_radiance_in<false>(const Vec3f&, const Color*) const;
template Color LightSet::environment_radiance_in<true>(const Vec3f&, const Color*) const;
template std::optional<LightSample> LightSet::sample_in<false>(const Vec3f&, const Vec3f&, float, const Vec2f&,
                                                               const Color*, SpectralEmissionCache*) const;
template std::optional<LightSample> LightSet::sample_in<true>(const Vec3f&, const Vec3f&, float, const Vec2f&,
                                                              const Color*, SpectralEmissionCache*) const;
template Color LightSet::emitted_in<false>(uint32_t, const Vec3f&, const Vec3f&, const Color*,
                                           SpectralEmissionCache*) const;
template Color LightSet::emitted_in<true>(uint32_t, const Vec3f&, const Vec3f&, const Color*,
                                          SpectralEmissionCache*) const;

}  // namespace candela
