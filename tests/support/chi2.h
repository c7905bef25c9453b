#pragma once
// The one chi-square goodness-of-fit harness for every sampler in candela (warps, pixel filters,
// BSDFs, lights), after Mitsuba 3's chi2.py: a 2D parameter domain, a sampler and its claimed pdf.
//
//   1. Integrate the pdf over each cell of a res_x x res_y grid on the domain (adaptive Simpson),
//      giving the expected counts; check that the pdf integrates to what the test expects.
//   2. Histogram sample_count samples. A sample outside the domain, not finite, or in a cell
//      whose integrated pdf is exactly 0 fails at once: that is a bug, not noise.
//   3. Pool the cells with expected count < 5 (in increasing order of expectation), compute
//      Pearson's statistic and its p-value from the chi-square distribution, and reject when
//      p < the Sidak-corrected alpha (0.01 across all the tests of a suite, so a suite of 30
//      correct samplers still passes with probability 99%).
//
// Usage:
//   Chi2Options opt; opt.test_count = kTestsInThisSuite;
//   auto r = chi2_test(SphericalDomain{}, [](Sampler& rng) { return sample_cosine_hemisphere(
//       rng.next_vec2f()); }, [](Vec3f w) { return cosine_hemisphere_pdf(w); }, opt);
//   EXPECT_TRUE(r.passed) << r.message;
//
// The sampler takes the harness's Sampler& (a fresh one per sample: sample index s of one pixel)
// and returns a point or std::optional<point> (nullopt: the sampler failed, as a BSDF may; then
// the pdf integrates to the success probability). By default the histogram is drawn twice, from
// independent random numbers and from Owen-scrambled Sobol points, and both must pass: a sampling
// routine must be right whichever sampler feeds it. (Low-discrepancy points make the statistic
// smaller than chance would, so the Sobol run can only miss a defect that is tiny; the independent
// run keeps the test's full power.)
// Features of the pdf narrower than 1/16 of a cell can escape the integration: choose the grid
// so that the support spans several cells, and put known discontinuities on cell edges.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "candela/math/constants.h"
#include "candela/math/vec.h"
#include "candela/sampling/sampler.h"

namespace candela::test {

using Vec2d = Vec2<double>;

// ---- the chi-square distribution -------------------------------------------------------------

// Q(a, x) = Gamma(a, x) / Gamma(a), the regularized upper incomplete gamma function: its series
// below x = a + 1 and its continued fraction (modified Lentz) above, as in Numerical Recipes
// (3rd ed., 6.2). The iteration cap is generous because large a (thousands of degrees of
// freedom) needs about sqrt(a) terms.
inline double gamma_q(double a, double x) {
    if (!(a > 0.0) || !(x >= 0.0)) return std::nan("");
    if (x == 0.0) return 1.0;
    constexpr int kMaxIterations = 100000;
    constexpr double kEps = 1e-15;
    double log_prefactor = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1.0) {
        double ap = a, term = 1.0 / a, sum = term;
        for (int n = 0; n < kMaxIterations; ++n) {
            ap += 1.0;
            term *= x / ap;
            sum += term;
            if (std::abs(term) < std::abs(sum) * kEps) break;
        }
        return std::clamp(1.0 - sum * std::exp(log_prefactor), 0.0, 1.0);
    }
    constexpr double kTiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
    for (int i = 1; i < kMaxIterations; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        double del = d * c;
        h *= del;
        if (std::abs(del - 1.0) < kEps) break;
    }
    return std::clamp(std::exp(log_prefactor) * h, 0.0, 1.0);
}

// P(X >= statistic) for X chi-square distributed with `dof` degrees of freedom.
inline double chi2_p_value(double statistic, double dof) {
    return gamma_q(0.5 * dof, 0.5 * statistic);
}

// The per-test level that keeps the family-wise rejection rate of `test_count` independent tests
// at `alpha` (Sidak): 1 - (1 - alpha)^(1 / test_count).
inline double sidak_alpha(double alpha, int test_count) {
    return -std::expm1(std::log1p(-alpha) / static_cast<double>(test_count));
}

// ---- domains: a rectangle of parameters, and the map from samples to it ------------------------

// Points of the plane in [min.x, max.x] x [min.y, max.y], parametrised by themselves.
struct PlanarDomain {
    using Point = Vec2f;
    Vec2d min{0.0, 0.0};
    Vec2d max{1.0, 1.0};

    Vec2d param_min() const { return min; }
    Vec2d param_max() const { return max; }
    Vec2d to_param(Vec2f p) const { return {p.x, p.y}; }
    Vec2f from_param(Vec2d q) const { return {static_cast<float>(q.x), static_cast<float>(q.y)}; }
    // Density of the point measure per unit parameter area.
    double jacobian(Vec2d) const { return 1.0; }
};

// Unit directions parametrised by (phi, cos theta) in [-pi, pi] x [cos_theta_min, cos_theta_max].
// The map has unit Jacobian (d omega = d phi d cos(theta)), so equal cells are equal solid angles
// and a pdf per solid angle integrates as it is. Narrow the cos theta range for narrow supports
// (cones): then any direction below cos_theta_min fails as outside the domain.
struct SphericalDomain {
    using Point = Vec3f;
    double cos_theta_min = -1.0;
    double cos_theta_max = 1.0;

    Vec2d param_min() const { return {-kPiD, cos_theta_min}; }
    Vec2d param_max() const { return {kPiD, cos_theta_max}; }
    Vec2d to_param(Vec3f w) const {
        return {std::atan2(static_cast<double>(w.y), static_cast<double>(w.x)),
                std::clamp(static_cast<double>(w.z), -1.0, 1.0)};
    }
    Vec3f from_param(Vec2d q) const {
        double sin_theta = std::sqrt(std::max(0.0, 1.0 - q.y * q.y));
        return Vec3f(Vec3d(sin_theta * std::cos(q.x), sin_theta * std::sin(q.x), q.y));
    }
    double jacobian(Vec2d) const { return 1.0; }
};

// ---- options and result ----------------------------------------------------------------------

struct Chi2Options {
    int res_x = 100;  // histogram columns (first parameter; phi for SphericalDomain)
    int res_y = 50;   // histogram rows (second parameter; cos theta)
    uint64_t sample_count = 1'000'000;
    uint64_t seed = 0;
    double min_expected = 5.0;  // cells expecting fewer samples are pooled
    double alpha = 0.01;        // family-wise significance level
    int test_count = 1;         // chi-square tests in the suite, for the Sidak correction
    // What the pdf must integrate to over the domain (the sampler's success probability);
    // nullopt skips the check.
    std::optional<double> expected_integral = 1.0;
    double integral_tolerance = 1e-3;  // absolute
    // The samplers that feed the histogram, each in its own test.
    std::vector<SamplerType> sources = {SamplerType::kIndependent, SamplerType::kSobol};
};

struct Chi2Result {
    bool passed = false;
    double statistic = 0.0;
    int dof = 0;
    double p_value = 0.0;
    double alpha = 0.0;         // the Sidak-corrected level the p-value was compared to
    double pdf_integral = 0.0;  // of the pdf over the domain
    std::string message;        // what was computed and, on failure, why and where
};

namespace detail {

// Adaptive Simpson on [a, b] given f at a, (a+b)/2, b and the panel's Simpson estimate, with
// Richardson's correction (Lyness 1969). The depth cap bounds the work at discontinuities, where
// the error estimate never drops below the tolerance.
template <class F>
double adaptive_simpson(const F& f, double a, double b, double fa, double fm, double fb,
                        double whole, double eps, int depth) {
    double m = 0.5 * (a + b);
    double flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
    double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    double delta = left + right - whole;
    if (depth <= 0 || std::abs(delta) <= 15.0 * eps) return left + right + delta / 15.0;
    return adaptive_simpson(f, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1) +
           adaptive_simpson(f, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1);
}

// The integral of f over [a, b] to absolute tolerance eps. Starting from 4 panels (17 nodes)
// keeps a feature that misses the first 5 nodes from being read as zero.
template <class F>
double integrate_1d(const F& f, double a, double b, double eps) {
    constexpr int kPanels = 4;
    constexpr int kMaxDepth = 14;
    double sum = 0.0, h = (b - a) / kPanels;
    double x0 = a, f0 = f(a);
    for (int i = 0; i < kPanels; ++i) {
        double x1 = i + 1 == kPanels ? b : a + h * (i + 1);
        double xm = 0.5 * (x0 + x1);
        double fm = f(xm), f1 = f(x1);
        double whole = (x1 - x0) / 6.0 * (f0 + 4.0 * fm + f1);
        sum += adaptive_simpson(f, x0, x1, f0, fm, f1, whole, eps / kPanels, kMaxDepth);
        x0 = x1;
        f0 = f1;
    }
    return sum;
}

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

struct PdfCheck {
    bool ok = true;
    std::string message;
};

}  // namespace detail

// The integral of pdf over each cell of a res_x x res_y grid on the domain, row-major (y outer),
// scaled by `scale`, to an absolute tolerance of `eps` (in scaled units) per cell. A negative or
// non-finite pdf value is reported through `check`.
template <class Domain, class Pdf>
std::vector<double> integrate_cells(const Domain& domain, const Pdf& pdf, int res_x, int res_y,
                                    double scale, double eps, detail::PdfCheck* check = nullptr) {
    Vec2d lo = domain.param_min(), hi = domain.param_max();
    double cw = (hi.x - lo.x) / res_x, ch = (hi.y - lo.y) / res_y;
    auto density = [&](double x, double y) {
        Vec2d q{x, y};
        double v = static_cast<double>(pdf(domain.from_param(q))) * domain.jacobian(q);
        if (!(v >= 0.0) || !std::isfinite(v)) {
            if (check != nullptr && check->ok) {
                check->ok = false;
                check->message = fmt::format(
                    "pdf is {} (negative or not finite) at parameters ({}, {})", v, x, y);
            }
            return 0.0;
        }
        return scale * v;
    };
    std::vector<double> cells(static_cast<size_t>(res_x) * static_cast<size_t>(res_y));
    for (int j = 0; j < res_y; ++j) {
        double y0 = lo.y + ch * j, y1 = j + 1 == res_y ? hi.y : lo.y + ch * (j + 1);
        for (int i = 0; i < res_x; ++i) {
            double x0 = lo.x + cw * i, x1 = i + 1 == res_x ? hi.x : lo.x + cw * (i + 1);
            // Inner integrals 10x tighter than the outer tolerance (scaled by the row height), so
            // their error does not look like structure to the outer adaptive rule.
            double inner_eps = 0.1 * eps / (y1 - y0);
            auto row = [&](double y) {
                auto at_y = [&](double x) { return density(x, y); };
                return detail::integrate_1d(at_y, x0, x1, inner_eps);
            };
            cells[static_cast<size_t>(j) * static_cast<size_t>(res_x) + static_cast<size_t>(i)] =
                detail::integrate_1d(row, y0, y1, eps);
        }
    }
    return cells;
}

// The integral of pdf over the whole domain (to about 1e-7 absolute).
template <class Domain, class Pdf>
double integrate_pdf(const Domain& domain, const Pdf& pdf, int res_x = 40, int res_y = 20) {
    double eps = 1e-7 / (res_x * res_y);
    std::vector<double> cells = integrate_cells(domain, pdf, res_x, res_y, 1.0, eps);
    double sum = 0.0;
    for (double c : cells) sum += c;
    return sum;
}

// Tests that `sample` draws points distributed as `pdf` over `domain` (see the top of the file).
namespace detail {
template <class Domain, class SampleFn>
void histogram_test(const Domain& domain, SampleFn& sample, const std::vector<double>& expected,
                    const Chi2Options& opt, SamplerType source, Chi2Result& result);
}  // namespace detail

template <class Domain, class SampleFn, class Pdf>
Chi2Result chi2_test(const Domain& domain, SampleFn&& sample, Pdf&& pdf,
                     const Chi2Options& opt = {}) {
    Chi2Result result;
    result.alpha = sidak_alpha(opt.alpha, opt.test_count);
    const int nx = opt.res_x, ny = opt.res_y;
    const auto n = static_cast<double>(opt.sample_count);

    // 1. Expected counts, to 0.01 of a sample per cell: far below the sampling noise (>= 2 samples
    //    in any cell that is not pooled).
    detail::PdfCheck check;
    std::vector<double> expected = integrate_cells(domain, pdf, nx, ny, n, 0.01, &check);
    if (!check.ok) {
        result.message = check.message;
        return result;
    }
    double total = 0.0;
    for (double e : expected) total += e;
    result.pdf_integral = total / n;
    if (opt.expected_integral &&
        !(std::abs(result.pdf_integral - *opt.expected_integral) <= opt.integral_tolerance)) {
        result.message =
            fmt::format("the pdf integrates to {:.6f} over the domain, expected {:.6f}",
                        result.pdf_integral, *opt.expected_integral);
        return result;
    }

    // 2. and 3. for each source of random numbers.
    std::string messages;
    bool all_passed = true;
    const Chi2Result before_histogram = result;
    for (SamplerType source : opt.sources) {
        Chi2Result r = before_histogram;
        detail::histogram_test(domain, sample, expected, opt, source, r);
        messages += fmt::format("{}{}: {}", messages.empty() ? "" : "\n",
                                source == SamplerType::kSobol ? "sobol" : "independent", r.message);
        all_passed = all_passed && r.passed;
        if (!r.passed || source == opt.sources.front()) result = r;
    }
    result.passed = all_passed;
    result.message = messages;
    return result;
}

namespace detail {

// Steps 2 and 3 of chi2_test for one source of random numbers: the histogram and Pearson's test.
template <class Domain, class SampleFn>
void histogram_test(const Domain& domain, SampleFn& sample, const std::vector<double>& expected,
                    const Chi2Options& opt, SamplerType source, Chi2Result& result) {
    const int nx = opt.res_x, ny = opt.res_y;
    Vec2d lo = domain.param_min(), hi = domain.param_max();
    // 2. The histogram; impossible samples fail at once.
    std::vector<double> observed(expected.size(), 0.0);
    for (uint64_t s = 0; s < opt.sample_count; ++s) {
        Sampler sampler(source, 0x63686932ull /* "chi2" */, static_cast<uint32_t>(s), opt.seed);
        auto drawn = sample(sampler);
        typename Domain::Point point;
        if constexpr (detail::IsOptional<decltype(drawn)>::value) {
            if (!drawn) continue;
            point = *drawn;
        } else {
            point = drawn;
        }
        Vec2d q = domain.to_param(point);
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || q.x < lo.x || q.x > hi.x || q.y < lo.y ||
            q.y > hi.y) {
            result.message = fmt::format(
                "sample {} has parameters ({}, {}), outside the domain [{}, {}] x [{}, {}]", s, q.x,
                q.y, lo.x, hi.x, lo.y, hi.y);
            return;
        }
        int i = std::min(nx - 1, static_cast<int>((q.x - lo.x) / (hi.x - lo.x) * nx));
        int j = std::min(ny - 1, static_cast<int>((q.y - lo.y) / (hi.y - lo.y) * ny));
        size_t cell = static_cast<size_t>(j) * static_cast<size_t>(nx) + static_cast<size_t>(i);
        if (expected[cell] == 0.0) {
            result.message = fmt::format("sample {} at parameters ({}, {}) fell in cell ({}, {}), "
                                         "where the pdf integrates to 0", s, q.x, q.y, i, j);
            return;
        }
        observed[cell] += 1.0;
    }

    // 3. Pool small cells in increasing order of expectation (Mitsuba's chi2): a pool is closed
    //    once it expects min_expected samples, and what is left over joins the last bin.
    std::vector<size_t> order(expected.size());
    for (size_t c = 0; c < order.size(); ++c) order[c] = c;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    std::vector<std::pair<double, double>> bins;  // (observed, expected)
    double pool_obs = 0.0, pool_exp = 0.0;
    int pooled_cells = 0;
    for (size_t c : order) {
        if (expected[c] == 0.0) continue;  // and observed is 0 too, or step 2 failed
        if (expected[c] < opt.min_expected) ++pooled_cells;
        pool_obs += observed[c];
        pool_exp += expected[c];
        if (pool_exp >= opt.min_expected) {
            bins.emplace_back(pool_obs, pool_exp);
            pool_obs = pool_exp = 0.0;
        }
    }
    if (pool_exp > 0.0) {
        if (bins.empty()) bins.emplace_back(0.0, 0.0);
        bins.back().first += pool_obs;
        bins.back().second += pool_exp;
    }
    for (auto [o, e] : bins) result.statistic += (o - e) * (o - e) / e;
    result.dof = static_cast<int>(bins.size()) - 1;
    if (result.dof < 1) {
        result.message = fmt::format("only {} bin(s) after pooling: refine the grid or draw more "
                                     "samples", bins.size());
        return;
    }
    result.p_value = chi2_p_value(result.statistic, result.dof);
    result.passed = result.p_value >= result.alpha;

    // The cells that disagree most, to say where a sampler and its pdf part ways.
    std::vector<size_t> worst;
    for (size_t c = 0; c < expected.size(); ++c)
        if (expected[c] >= opt.min_expected) worst.push_back(c);
    auto contribution = [&](size_t c) {
        return (observed[c] - expected[c]) * (observed[c] - expected[c]) / expected[c];
    };
    size_t shown = std::min<size_t>(5, worst.size());
    auto shown_end = worst.begin() + static_cast<std::ptrdiff_t>(shown);
    std::partial_sort(worst.begin(), shown_end, worst.end(),
                      [&](size_t a, size_t b) { return contribution(a) > contribution(b); });
    result.message = fmt::format(
        "{}: chi2 = {:.2f}, dof = {}, p-value = {:.4g}, alpha = {:.4g} (Sidak, {} tests); {} of {} "
        "cells pooled; pdf integral = {:.6f}; worst cells:",
        result.passed ? "accepted" : "REJECTED", result.statistic, result.dof, result.p_value,
        result.alpha, opt.test_count, pooled_cells, expected.size(), result.pdf_integral);
    double cw = (hi.x - lo.x) / nx, ch = (hi.y - lo.y) / ny;
    for (size_t k = 0; k < shown; ++k) {
        size_t c = worst[k];
        size_t i = c % static_cast<size_t>(nx), j = c / static_cast<size_t>(nx);
        result.message += fmt::format(
            "\n  cell ({}, {}) = [{:.4g}, {:.4g}] x [{:.4g}, {:.4g}]: observed {}, expected {:.1f}",
            i, j, lo.x + cw * static_cast<double>(i), lo.x + cw * static_cast<double>(i + 1),
            lo.y + ch * static_cast<double>(j), lo.y + ch * static_cast<double>(j + 1), observed[c],
            expected[c]);
    }
}

}  // namespace detail

}  // namespace candela::test
