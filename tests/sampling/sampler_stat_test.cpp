// Convergence rates of the two samplers on 2D integrands with known integrals. The RMSE over R
// independent randomizations (pixels) is fitted against N on a log-log scale:
//   independent samples:      RMSE ~ N^-0.5 for any square-integrable integrand;
//   Owen-scrambled (0,2)-net: RMSE ~ N^-1.5 (up to a sqrt(log N)) for smooth integrands (Owen
//                             1997), N^-0.75 for integrands with a discontinuity along a curve.
// With R = 256 the RMSE at each N is known to about 5% (sqrt(1 / (2 R)) for normal errors), so
// the fitted slope over N = 16..4096 (a factor 256, ln = 5.5) is known to a few hundredths: the
// bounds below are 0.15 to 0.25 wide around the theory, many standard errors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "candela/sampling/sampler.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kReplications = 256;
const std::vector<uint32_t> kCounts = {16, 64, 256, 1024, 4096};

struct Rates {
    double slope;                 // of log RMSE against log N
    std::vector<double> rmse;     // at each of kCounts
};

// `skip` requests are drawn and thrown away first, to test a later dimension of the path.
Rates convergence(SamplerType type, const std::function<double(Vec2f)>& f, double integral, int skip = 0) {
    Rates rates;
    std::vector<double> xs, ys;
    for (uint32_t n : kCounts) {
        double squared_error = 0.0;
        for (int r = 0; r < kReplications; ++r) {
            double sum = 0.0;
            for (uint32_t i = 0; i < n; ++i) {
                Sampler s(type, uint64_t(r) + 1000, i, 7);
                for (int k = 0; k < skip; ++k) s.next_vec2f();
                sum += f(s.next_vec2f());
            }
            double e = sum / n - integral;
            squared_error += e * e;
        }
        double rmse = std::sqrt(squared_error / kReplications);
        rates.rmse.push_back(rmse);
        xs.push_back(std::log(double(n)));
        ys.push_back(std::log(rmse));
    }
    double mx = 0, my = 0;
    for (size_t k = 0; k < xs.size(); ++k) mx += xs[k] / xs.size(), my += ys[k] / ys.size();
    double sxy = 0, sxx = 0;
    for (size_t k = 0; k < xs.size(); ++k) sxy += (xs[k] - mx) * (ys[k] - my), sxx += (xs[k] - mx) * (xs[k] - mx);
    rates.slope = sxy / sxx;
    return rates;
}

// Smooth: x^2 e^y over the unit square, integral (e - 1) / 3.
double smooth(Vec2f p) { return double(p.x) * double(p.x) * std::exp(double(p.y)); }
const double kSmoothIntegral = (std::exp(1.0) - 1.0) / 3.0;

// Discontinuous along a curve (like a pixel crossed by an edge): the quarter disk x^2 + y^2 < 1,
// integral pi / 4.
double quarter_disk(Vec2f p) { return double(p.x) * double(p.x) + double(p.y) * double(p.y) < 1.0 ? 1.0 : 0.0; }
const double kQuarterDiskIntegral = 0.25 * 3.14159265358979323846;

TEST(SamplerConvergence, IndependentIsMonteCarloRate) {
    Rates r = convergence(SamplerType::kIndependent, smooth, kSmoothIntegral);
    EXPECT_GT(r.slope, -0.6);
    EXPECT_LT(r.slope, -0.4);
}

TEST(SamplerConvergence, SobolIsOrderOneFasterOnSmoothIntegrands) {
    Rates sobol = convergence(SamplerType::kSobol, smooth, kSmoothIntegral);
    Rates independent = convergence(SamplerType::kIndependent, smooth, kSmoothIntegral);
    EXPECT_LT(sobol.slope, -1.25);
    EXPECT_GT(sobol.slope, -1.75);
    EXPECT_LT(sobol.slope - independent.slope, -0.75);
    // At 4096 samples the gap is more than a factor 30 (theory: about 64 / sqrt(log)).
    EXPECT_LT(sobol.rmse.back() * 30.0, independent.rmse.back());
}

TEST(SamplerConvergence, LaterRequestsConvergeAsFast) {
    // Request 7 is, e.g., the BSDF direction of the second bounce: padding keeps its quality.
    Rates r = convergence(SamplerType::kSobol, smooth, kSmoothIntegral, 7);
    EXPECT_LT(r.slope, -1.25);
    EXPECT_GT(r.slope, -1.75);
}

TEST(SamplerConvergence, SobolIsFasterOnDiscontinuousIntegrands) {
    Rates sobol = convergence(SamplerType::kSobol, quarter_disk, kQuarterDiskIntegral);
    EXPECT_LT(sobol.slope, -0.6);
    EXPECT_GT(sobol.slope, -0.95);
}

}  // namespace
}  // namespace candela
