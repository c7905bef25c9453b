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
}

Rgb LightSet::environment_radiance(const Vec3f& w) const {
    return environment_ ? environment_->radiance(w) : Rgb(0.0f);
}

float LightSet::environment_pdf(const Vec3f& w) const {
    if (!environment_) return 0.0f;
    return selection_.probability(lights_.size()) * environment_->pdf(w);
}

CANDELA_HD std::optional<LightSample> LightSet::sample(const Vec3f& ref, float uc, const Vec2f& u) const {
    if (selection_.empty()) return std::nullopt;
    DiscreteSample chosen = selection_.sample_discrete(uc);
    if (chosen.index == lights_.size()) {  // the environment
        std::optional<EnvironmentSample> es = environment_->sample(u);
        if (!es) return std::nullopt;
        float pdf = chosen.probability * es->pdf;
        if (!(pdf > 0.0f) || !std::isfinite(pdf)) return std::nullopt;
        return LightSample{ref + es->wi, -es->wi, es->wi, true, es->Le, pdf};
    }
    const AreaLight& light = lights_[chosen.index];
    std::optional<EmitterSample> es =
        visit([&](const auto& e) { return e.sample(ref, chosen.u_remapped, u); }, light.emitter);
    if (!es) return std::nullopt;
    // The same product, in the same order, as pdf() computes.
    float pdf = chosen.probability * es->pdf;
    if (!(pdf > 0.0f) || !std::isfinite(pdf)) return std::nullopt;
    // Towards ref, in double: only its side of the surface matters, and far from the origin
    // (smallpt's 1e5) a float difference could flip it at grazing angles.
    Vec3f w = Vec3f(Vec3d(ref) - Vec3d(es->p));
    return LightSample{es->p, es->n, normalize(-w), false, area_light_radiance(light, es->n, w), pdf};
}

CANDELA_HD float LightSet::pdf(const Vec3f& ref, uint32_t shape_id, const Vec3f& p_light, const Vec3f& n_light) const {
    uint32_t li = light_index(shape_id);
    if (li == kNoLight) return 0.0f;
    float emitter_pdf = visit([&](const auto& e) { return e.pdf(ref, p_light, n_light); }, lights_[li].emitter);
    return selection_.probability(li) * emitter_pdf;
}

CANDELA_HD Rgb LightSet::emitted(uint32_t shape_id, const Vec3f& n, const Vec3f& w) const {
    uint32_t li = light_index(shape_id);
    return li == kNoLight ? Rgb() : area_light_radiance(lights_[li], n, w);
}

CANDELA_HD float LightSet::selection_probability(uint32_t shape_id) const {
    uint32_t li = light_index(shape_id);
    return li == kNoLight ? 0.0f : selection_.probability(li);
}

}  // namespace candela
