// Chi-square goodness of fit of Distribution1D (tests/support/chi2.h): the discrete counts of
// sample_discrete against probability(), and sample_continuous against pdf_continuous. Zero
// weights make zero-pdf cells, where a single sample fails the test at once.
#include <gtest/gtest.h>

#include <vector>

#include "candela/sampling/distribution_1d.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr int kChi2Tests = 3;  // in this file, for the Sidak correction

// Weights over several decades, with zeros at both ends and in the middle.
std::vector<float> uneven_weights(size_t n) {
    std::vector<float> w(n);
    for (size_t i = 0; i < n; ++i) {
        bool zero = i == 0 || i + 1 == n || i % 9 == 4;
        w[i] = zero ? 0.0f : 0.05f + static_cast<float>((i * 37) % 23) * static_cast<float>(i % 3 + 1);
    }
    return w;
}

// The density of bin-wise constant values on [0, 1) in n bins (n a power of two, so bin edges are
// floats and cell edges). At an edge it takes the smaller neighbour: then a zero bin integrates
// to exactly 0 and a sample there fails at once.
template <class BinValue>
float binned_density(float x, size_t n, const BinValue& value) {
    if (!(x >= 0.0f && x <= 1.0f)) return 0.0f;
    double t = static_cast<double>(x) * static_cast<double>(n);
    auto bin = static_cast<size_t>(t);
    if (static_cast<double>(bin) != t) return value(bin);
    float left = bin > 0 ? value(bin - 1) : 0.0f;
    float right = bin < n ? value(bin) : 0.0f;
    return left < right ? left : right;
}

// Index i drawn with u is histogrammed as the point ((i + v) / n, y) for fresh uniforms v and y,
// so that a cell of the planar grid (res_x = n) counts exactly one index.
void expect_discrete_fits(const std::vector<float>& w) {
    Distribution1D d(w);
    const auto n = static_cast<float>(w.size());
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.res_x = static_cast<int>(w.size());
    opt.res_y = 4;
    auto sampler = [&](Sampler& rng) {
        float u = rng.next_float();
        float v = rng.next_float();
        float y = rng.next_float();
        return Vec2f((static_cast<float>(d.sample_discrete(u).index) + v) / n, y);
    };
    auto pdf = [&](Vec2f p) {
        return binned_density(p.x, w.size(), [&](size_t i) { return d.probability(i) * n; });
    };
    Chi2Result r = chi2_test(PlanarDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Distribution1DChi2, DiscreteCountsMatchProbabilities) { expect_discrete_fits(uneven_weights(64)); }

TEST(Distribution1DChi2, DiscreteCountsMatchForFewWeights) {
    expect_discrete_fits({0.0f, 1.0f, 0.0f, 0.0f, 5.0f, 0.25f, 0.0f, 2.0f});
}

TEST(Distribution1DChi2, ContinuousSamplesMatchDensity) {
    // 32 bins, histogrammed in 64 columns: bin edges are column edges. (Bins whose edges are not
    // floats are checked in distribution_1d_test.cpp.)
    Distribution1D d(uneven_weights(32));
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.res_x = 64;
    opt.res_y = 4;
    auto sampler = [&](Sampler& rng) {
        float u = rng.next_float();
        float y = rng.next_float();
        return Vec2f(d.sample_continuous(u).x, y);
    };
    auto pdf = [&](Vec2f p) {
        auto bin_density = [&](size_t i) { return d.pdf_continuous((static_cast<float>(i) + 0.5f) / 32.0f); };
        return binned_density(p.x, d.size(), bin_density);
    };
    Chi2Result r = chi2_test(PlanarDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace candela::test
