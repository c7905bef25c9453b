#include "candela/lights/light_set.h"

#include <cmath>

namespace candela {

LightSet::LightSet(std::span<const TriangleMesh> meshes, std::span<const Sphere> spheres,
                   std::span<const Shape> shapes, LightSelection selection,
                   std::optional<EnvironmentLight> environment, float scene_radius)
    : light_of_shape_(shapes.size(), kNoLight), environment_(std::move(environment)) {
    std::vector<float> weights;
    for (size_t id = 0; id < shapes.size(); ++id) {
        const Shape& shape = shapes[id];
        if (shape.emission.is_black()) continue;
        AreaLight light{shape.kind == ShapeKind::kMesh ? Emitter(MeshEmitter(meshes[shape.index]))
                                                       : Emitter(SphereEmitter{spheres[shape.index]}),
                        shape.emission, shape.two_sided, static_cast<uint32_t>(id)};
        float area = visit([](const auto& e) { return e.area(); }, light.emitter);
        if (!(area > 0.0f) || !std::isfinite(area)) continue;
        light_of_shape_[id] = static_cast<uint32_t>(lights_.size());
        weights.push_back(selection == LightSelection::kPower ? area_light_power(light) : 1.0f);
        lights_.push_back(std::move(light));
    }
    if (environment_) {
        float power = environment_->power(scene_radius);
        if (power > 0.0f && std::isfinite(power))
            weights.push_back(selection == LightSelection::kPower ? power : 1.0f);
        else
            environment_.reset();  // black: nothing to see or sample
    }
    selection_ = Distribution1D(weights);
    for (size_t i = 0; i < weights.size(); ++i) selection_probability_.push_back(selection_.probability(i));
}

Rgb LightSet::environment_radiance(const Vec3f& w) const {
    return environment_ ? environment_->radiance(w) : Rgb(0.0f);
}

float LightSet::environment_pdf(const Vec3f& w) const {
    if (!environment_) return 0.0f;
    return selection_probability_[lights_.size()] * environment_->pdf(w);
}

CANDELA_HD std::optional<LightSample> LightSet::sample(const Vec3f& ref, float uc, const Vec2f& u) const {
    // The one object returned on every path, built in place where the caller receives it.
    std::optional<LightSample> result;
    if (selection_.empty()) return result;
    const uint32_t chosen = uses_choice() ? selection_.sample_discrete(uc).index : 0;
    const float probability = selection_probability_[chosen];
    if (chosen == lights_.size()) {  // the environment
        std::optional<EnvironmentSample> es = environment_->sample(u);
        if (!es) return result;
        float pdf = probability * es->pdf;
        if (!(pdf > 0.0f) || !std::isfinite(pdf)) return result;
        result.emplace(LightSample{ref + es->wi, -es->wi, es->wi, true, es->Le, pdf});
        return result;
    }
    const AreaLight& light = lights_[chosen];
    std::optional<EmitterSample> es = visit([&](const auto& e) { return e.sample(ref, u); }, light.emitter);
    if (!es) return result;
    // The same product, in the same order, as pdf() computes.
    float pdf = probability * es->pdf;
    if (!(pdf > 0.0f) || !std::isfinite(pdf)) return result;
    LightSample& ls = result.emplace();
    ls.p = es->p;
    ls.n = es->n;
    ls.wi = es->wi;
    ls.infinite = false;
    ls.Le = area_light_radiance(light, es->n, -es->wi);
    ls.pdf = pdf;
    return result;
}

CANDELA_HD float LightSet::pdf(const Vec3f& ref, uint32_t shape_id, const Vec3f& p_light, const Vec3f& n_light) const {
    uint32_t li = light_index(shape_id);
    if (li == kNoLight) return 0.0f;
    float emitter_pdf = visit([&](const auto& e) { return e.pdf(ref, p_light, n_light); }, lights_[li].emitter);
    return selection_probability_[li] * emitter_pdf;
}

CANDELA_HD Rgb LightSet::emitted(uint32_t shape_id, const Vec3f& n, const Vec3f& w) const {
    uint32_t li = light_index(shape_id);
    return li == kNoLight ? Rgb() : area_light_radiance(lights_[li], n, w);
}

CANDELA_HD float LightSet::selection_probability(uint32_t shape_id) const {
    uint32_t li = light_index(shape_id);
    return li == kNoLight ? 0.0f : selection_probability_[li];
}

}  // namespace candela
