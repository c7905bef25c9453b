#include "candela/lights/light_bvh.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "candela/core/check.h"

namespace candela {

namespace {

float surface_area(const Bounds3f& b) {
    const Vec3f d = b.diagonal();
    return 2.0f * (d.x * d.y + d.x * d.z + d.y * d.z);
}

float component(const Vec3f& v, int dim) { return dim == 0 ? v.x : dim == 1 ? v.y : v.z; }

// pbrt-v4's EvaluateCost: power times the solid-angle measure M_omega of the directions the
// bounds may emit into, times the box's surface area, times Kr, which penalizes splitting a box
// along its short side (it would make thin children).
float split_cost(const LightBounds& b, const Bounds3f& bounds, int dim) {
    const float theta_o = safe_acos(b.cos_theta_o), theta_e = safe_acos(b.cos_theta_e);
    const float theta_w = std::min(theta_o + theta_e, kPi);
    const float sin_theta_o = safe_sqrt(1.0f - b.cos_theta_o * b.cos_theta_o);
    const float m_omega = 2.0f * kPi * (1.0f - b.cos_theta_o) +
                          kPi / 2.0f *
                              (2.0f * theta_w * sin_theta_o - std::cos(theta_o - 2.0f * theta_w) -
                               2.0f * theta_o * sin_theta_o + b.cos_theta_o);
    const Vec3f d = bounds.diagonal();
    const float kr = max_component(d) / component(d, dim);
    return b.phi * m_omega * kr * surface_area(b.bounds);
}

// The bucket of a centroid along dim among n buckets over `centroids`.
int bucket_of(const Vec3f& c, const Bounds3f& centroids, int dim, int n) {
    const float lo = component(centroids.lo, dim), hi = component(centroids.hi, dim);
    int b = static_cast<int>(float(n) * ((component(c, dim) - lo) / (hi - lo)));
    return std::clamp(b, 0, n - 1);
}

}  // namespace

LightBvh::LightBvh(std::vector<std::pair<uint32_t, LightBounds>> bounded, std::vector<uint32_t> infinite,
                   uint32_t light_count)
    : infinite_(std::move(infinite)), bit_trail_(light_count, kNotInTree) {
    std::erase_if(bounded, [](const auto& l) { return !(l.second.phi > 0.0f); });
    if (!bounded.empty()) build(bounded, 0, bounded.size(), 0, 0);
    p_infinite_ = float(infinite_.size()) / float(infinite_.size() + (nodes_.empty() ? 0 : 1));
}

std::pair<uint32_t, LightBounds> LightBvh::build(std::vector<std::pair<uint32_t, LightBounds>>& bounded,
                                                 size_t start, size_t end, uint64_t bit_trail, int depth) {
    CANDELA_CHECK(start < end && depth < 64);
    if (end - start == 1) {
        const uint32_t index = static_cast<uint32_t>(nodes_.size());
        nodes_.push_back(Node{bounded[start].second, bounded[start].first, true});
        bit_trail_[bounded[start].first] = bit_trail;
        return {index, bounded[start].second};
    }
    Bounds3f bounds, centroids;
    for (size_t i = start; i < end; ++i) {
        bounds.extend(bounded[i].second.bounds);
        centroids.extend(bounded[i].second.centroid());
    }
    // The cheapest split between 12 buckets of centroids, over the three axes.
    constexpr int kBuckets = 12;
    float min_cost = kInfinity;
    int best_bucket = -1, best_dim = -1;
    for (int dim = 0; dim < 3; ++dim) {
        if (component(centroids.hi, dim) == component(centroids.lo, dim)) continue;
        std::array<LightBounds, kBuckets> buckets{};
        for (size_t i = start; i < end; ++i) {
            int b = bucket_of(bounded[i].second.centroid(), centroids, dim, kBuckets);
            buckets[b] = union_of(buckets[b], bounded[i].second);
        }
        for (int i = 0; i < kBuckets - 1; ++i) {
            LightBounds b0, b1;
            for (int j = 0; j <= i; ++j) b0 = union_of(b0, buckets[j]);
            for (int j = i + 1; j < kBuckets; ++j) b1 = union_of(b1, buckets[j]);
            const float cost = split_cost(b0, bounds, dim) + split_cost(b1, bounds, dim);
            // pbrt-v4 considers the splits after buckets 1 to 10 only: kept, for the same trees.
            if (i >= 1 && cost > 0.0f && cost < min_cost) {
                min_cost = cost;
                best_bucket = i;
                best_dim = dim;
            }
        }
    }
    size_t mid = (start + end) / 2;
    if (best_dim != -1) {
        auto it = std::partition(bounded.begin() + long(start), bounded.begin() + long(end), [&](const auto& l) {
            return bucket_of(l.second.centroid(), centroids, best_dim, kBuckets) <= best_bucket;
        });
        mid = static_cast<size_t>(it - bounded.begin());
        if (mid == start || mid == end) mid = (start + end) / 2;
    }
    const uint32_t index = static_cast<uint32_t>(nodes_.size());
    nodes_.emplace_back();
    const auto child0 = build(bounded, start, mid, bit_trail, depth + 1);
    const auto child1 = build(bounded, mid, end, bit_trail | (uint64_t(1) << depth), depth + 1);
    CANDELA_CHECK(child0.first == index + 1);
    const LightBounds lb = union_of(child0.second, child1.second);
    nodes_[index] = Node{lb, child1.first, false};
    return {index, lb};
}

CANDELA_HD std::optional<LightBvh::Choice> LightBvh::sample(const Vec3f& p, const Vec3f& n, float u) const {
    std::optional<Choice> result;
    if (u < p_infinite_) {
        // Uniformly among the infinite lights, u stretched over their share.
        u /= p_infinite_;
        const size_t count = infinite_.size();
        const size_t i = std::min(static_cast<size_t>(u * float(count)), count - 1);
        result.emplace(Choice{infinite_[i], p_infinite_ / float(count)});
        return result;
    }
    if (nodes_.empty()) return result;
    u = std::min((u - p_infinite_) / (1.0f - p_infinite_), kOneMinusEpsilon);
    float pmf = 1.0f - p_infinite_;
    uint32_t index = 0;
    while (!nodes_[index].leaf) {
        const uint32_t children[2] = {index + 1, nodes_[index].child_or_light};
        const float c[2] = {nodes_[children[0]].bounds.importance(p, n), nodes_[children[1]].bounds.importance(p, n)};
        if (c[0] == 0.0f && c[1] == 0.0f) return result;
        // Child 0 on the first c0 / (c0 + c1) of u, and u stretched back over [0, 1) within the
        // child's share (pbrt-v4's SampleDiscrete with two weights).
        const float sum = c[0] + c[1];
        float up = u * sum;
        if (up == sum) up = std::nextafter(sum, 0.0f);
        const int k = up < c[0] ? 0 : 1;
        u = std::min(k == 0 ? up / c[0] : (up - c[0]) / c[1], kOneMinusEpsilon);
        pmf *= c[k] / (c[0] + c[1]);  // the same expression as pmf()'s
        index = children[k];
    }
    // The root as a leaf (a single bounded light) was not tested: it may light nothing here.
    if (index > 0 || nodes_[index].bounds.importance(p, n) > 0.0f)
        result.emplace(Choice{nodes_[index].child_or_light, pmf});
    return result;
}

CANDELA_HD float LightBvh::pmf(const Vec3f& p, const Vec3f& n, uint32_t light) const {
    uint64_t trail = light < bit_trail_.size() ? bit_trail_[light] : kNotInTree;
    if (trail == kNotInTree) {
        for (uint32_t i : infinite_)
            if (i == light) return infinite_pmf();
        return 0.0f;
    }
    float pmf = 1.0f - p_infinite_;
    uint32_t index = 0;
    while (!nodes_[index].leaf) {
        const uint32_t children[2] = {index + 1, nodes_[index].child_or_light};
        const float c[2] = {nodes_[children[0]].bounds.importance(p, n), nodes_[children[1]].bounds.importance(p, n)};
        const int k = static_cast<int>(trail & 1u);
        if (c[k] == 0.0f) return 0.0f;
        pmf *= c[k] / (c[0] + c[1]);
        index = children[k];
        trail >>= 1;
    }
    // A lone bounded light is never chosen where it has no importance (see sample()).
    if (index == 0 && !(nodes_[0].bounds.importance(p, n) > 0.0f)) return 0.0f;
    return pmf;
}

}  // namespace candela
