#pragma once
// pbrt-v4's BVHLightSampler (lightsamplers.{h,cpp}): lights chosen in proportion to their
// importance at the point being lit (light_bounds.h), by walking a binary tree of light bounds
// from the root and choosing each child in proportion to its bounds' importance. The lights
// without bounds (environment, directional: "infinite") are chosen uniformly with probability
// n_infinite / (n_infinite + 1), the tree taking the rest (pbrt-v4's share).
//
// Lights are numbered by the caller (LightSet's selection indices); sample() and pmf() agree
// exactly: pmf() walks to the light along its recorded path and multiplies the same factors, in
// the same order, that sample() multiplied.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "candela/core/platform.h"
#include "candela/lights/light_bounds.h"

namespace candela {

class LightBvh {
  public:
    // `bounded`: (light index, bounds) of the lights with bounds (those of zero power are never
    // chosen); `infinite`: the indices of those without; every index < light_count.
    LightBvh(std::vector<std::pair<uint32_t, LightBounds>> bounded, std::vector<uint32_t> infinite,
             uint32_t light_count);

    struct Choice {
        uint32_t light;
        float pmf;
    };
    // A light for point p with surface normal n (zero in a medium), with u in [0, 1); nullopt when
    // no light can contribute at p (all the tree's importances are zero there).
    CANDELA_HD std::optional<Choice> sample(const Vec3f& p, const Vec3f& n, float u) const;
    // The probability that sample() at (p, n) returns `light`.
    CANDELA_HD float pmf(const Vec3f& p, const Vec3f& n, uint32_t light) const;
    // The probability of each infinite light (the same at every point).
    CANDELA_HD float infinite_pmf() const { return infinite_.empty() ? 0.0f : p_infinite_ / float(infinite_.size()); }

  private:
    struct Node {
        LightBounds bounds;
        uint32_t child_or_light = 0;  // interior: the second child's index (the first follows); leaf: the light
        bool leaf = false;
    };
    static constexpr uint64_t kNotInTree = ~uint64_t(0);

    // Builds the subtree of bounded[start, end) with pbrt-v4's modified SAH (bucketed on the
    // centroids, cost phi * M_omega * Kr * surface area); returns its node index and bounds.
    std::pair<uint32_t, LightBounds> build(std::vector<std::pair<uint32_t, LightBounds>>& bounded, size_t start,
                                           size_t end, uint64_t bit_trail, int depth);

    std::vector<Node> nodes_;
    std::vector<uint32_t> infinite_;
    std::vector<uint64_t> bit_trail_;  // per light: bit d = 1 when its path takes the second child at depth d
    float p_infinite_ = 0.0f;          // probability of choosing an infinite light
};

}  // namespace candela
