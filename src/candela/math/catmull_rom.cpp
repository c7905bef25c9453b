#include "candela/math/catmull_rom.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace candela {
namespace {

// The largest index i in [0, size - 2] for which pred(i) holds, pred being true up to some index
// and false after it (0 when it holds nowhere): the interval [i, i + 1] that a bisection over
// sorted values finds.
template <class Pred>
int find_interval(int size, const Pred& pred) {
    int first = 1, count = size - 2;
    while (count > 0) {
        int half = count >> 1, middle = first + half;
        if (pred(middle)) {
            first = middle + 1;
            count -= half + 1;
        } else {
            count = half;
        }
    }
    int i = first - 1;
    return i < 0 ? 0 : (i > size - 2 ? size - 2 : i);
}

// A root in [0, 1] of f, which must change sign there, by Newton steps safeguarded by bisection:
// f(t) returns (value, derivative). Stops when the bracket is narrower than 1e-6 or |f| < f_eps
// (pbrt-v4's NewtonBisection, whose f_eps is 1e-6).
template <class F>
float newton_bisection(const F& f, float f_eps = 1e-6f) {
    constexpr float kEps = 1e-6f;
    float t0 = 0.0f, t1 = 1.0f;
    float f0 = f(t0).first, f1 = f(t1).first;
    if (std::abs(f0) < f_eps) return t0;
    if (std::abs(f1) < f_eps) return t1;
    const bool start_negative = f0 < 0.0f;
    float t = -f0 / (f1 - f0);  // the secant's root as the first guess
    for (;;) {
        if (!(t0 < t && t < t1)) t = 0.5f * (t0 + t1);
        std::pair<float, float> ft = f(t);
        if (start_negative == (ft.first < 0.0f))
            t0 = t;
        else
            t1 = t;
        if (t1 - t0 < kEps || std::abs(ft.first) < f_eps) return t;
        t -= ft.first / ft.second;
    }
}

// The spline's end derivatives on [x_i, x_{i+1}], scaled by the interval's width (so that they
// are derivatives in t = (x - x_i) / width): finite differences of the neighbours, one-sided at
// the ends. value(i) is the function's value at node i.
template <class Value>
std::pair<float, float> interval_slopes(std::span<const float> x, int i, const Value& value) {
    const int n = static_cast<int>(x.size());
    float x0 = x[static_cast<size_t>(i)], x1 = x[static_cast<size_t>(i) + 1];
    float f0 = value(i), f1 = value(i + 1), width = x1 - x0;
    float d0 = i > 0 ? width * (f1 - value(i - 1)) / (x1 - x[static_cast<size_t>(i) - 1]) : f1 - f0;
    float d1 = i + 2 < n ? width * (value(i + 2) - f0) / (x[static_cast<size_t>(i) + 2] - x0) : f1 - f0;
    return {d0, d1};
}

}  // namespace

bool catmull_rom_weights(std::span<const float> nodes, float x, int* offset, float weights[4]) {
    if (!(x >= nodes.front() && x <= nodes.back())) return false;
    const int n = static_cast<int>(nodes.size());
    int idx = find_interval(n, [&](int i) { return nodes[static_cast<size_t>(i)] <= x; });
    *offset = idx - 1;
    float x0 = nodes[static_cast<size_t>(idx)], x1 = nodes[static_cast<size_t>(idx) + 1];
    float t = (x - x0) / (x1 - x0), t2 = t * t, t3 = t2 * t;

    // The Hermite basis: h00 and h01 weigh the end values, h10 and h11 the end slopes, which
    // are differences of values and so spread over the neighbouring nodes.
    weights[1] = 2.0f * t3 - 3.0f * t2 + 1.0f;
    weights[2] = -2.0f * t3 + 3.0f * t2;
    float h10 = t3 - 2.0f * t2 + t, h11 = t3 - t2;
    if (idx > 0) {
        float w0 = h10 * (x1 - x0) / (x1 - nodes[static_cast<size_t>(idx) - 1]);
        weights[0] = -w0;
        weights[2] += w0;
    } else {
        weights[0] = 0.0f;
        weights[1] -= h10;
        weights[2] += h10;
    }
    if (idx + 2 < n) {
        float w3 = h11 * (x1 - x0) / (nodes[static_cast<size_t>(idx) + 2] - x0);
        weights[1] -= w3;
        weights[3] = w3;
    } else {
        weights[1] -= h11;
        weights[2] += h11;
        weights[3] = 0.0f;
    }
    return true;
}

float sample_catmull_rom_2d(std::span<const float> nodes1, std::span<const float> nodes2,
                            std::span<const float> values, std::span<const float> cdf, float alpha,
                            float u, float* fval, float* pdf) {
    int offset;
    float weights[4];
    if (!catmull_rom_weights(nodes1, alpha, &offset, weights)) return 0.0f;
    const int n2 = static_cast<int>(nodes2.size());
    // A table entry at node idx of nodes2, interpolated at alpha across the rows.
    auto interpolate = [&](std::span<const float> table, int idx) {
        float v = 0.0f;
        for (int i = 0; i < 4; ++i)
            if (weights[i] != 0.0f) v += table[static_cast<size_t>((offset + i) * n2 + idx)] * weights[i];
        return v;
    };

    // The interval whose cumulative integral brackets u times the total.
    float maximum = interpolate(cdf, n2 - 1);
    u *= maximum;
    int idx = find_interval(n2, [&](int i) { return interpolate(cdf, i) <= u; });
    auto value = [&](int i) { return interpolate(values, i); };
    float f0 = value(idx), f1 = value(idx + 1);
    float x0 = nodes2[static_cast<size_t>(idx)], x1 = nodes2[static_cast<size_t>(idx) + 1];
    float width = x1 - x0;
    // Plain variables, not a structured binding: the lambdas below capture them (clang 14, which
    // the sanitizer build uses, cannot capture a binding).
    const std::pair<float, float> slopes = interval_slopes(nodes2, idx, value);
    const float d0 = slopes.first, d1 = slopes.second;
    u = (u - interpolate(cdf, idx)) / width;

    // Invert the segment's integral in t, F(t) = int_0^t f, a quartic whose derivative is the
    // cubic Hermite interpolant f(t) (both divided by the width).
    float big_f = 0.0f, small_f = 0.0f;
    auto eval = [&](float t) {
        big_f = t * (f0 + t * (0.5f * d0 + t * ((1.0f / 3.0f) * (-2.0f * d0 - d1) + f1 - f0 +
                                                t * (0.25f * (d0 + d1) + 0.5f * (f0 - f1)))));
        small_f = f0 + t * (d0 + t * (-2.0f * d0 - d1 + 3.0f * (f1 - f0) + t * (d0 + d1 + 2.0f * (f0 - f1))));
        return std::pair<float, float>(big_f - u, small_f);
    };
    // The tolerance on F relative to the segment's integral F(1): pbrt-v4's absolute 1e-6 stops
    // at t = 0 in segments whose integral is below it, so that every sample of a profile's far
    // tail (the last 1e-5 of its mass at low albedo) lands on a node (a chi-square test sees the
    // pile-up, tests/materials/tabulated_bssrdf_stat_test.cpp). Elsewhere the two agree to 1e-6.
    const float segment = (interpolate(cdf, idx + 1) - interpolate(cdf, idx)) / width;
    float t = newton_bisection(eval, 1e-6f * std::min(1.0f, std::abs(segment)));
    if (fval != nullptr) *fval = small_f;
    if (pdf != nullptr) *pdf = small_f / maximum;
    return x0 + width * t;
}

float integrate_catmull_rom(std::span<const float> x, std::span<const float> values,
                            std::span<float> cdf) {
    const int n = static_cast<int>(x.size());
    auto value = [&](int i) { return values[static_cast<size_t>(i)]; };
    float sum = 0.0f;
    cdf[0] = 0.0f;
    for (int i = 0; i + 1 < n; ++i) {
        float width = x[static_cast<size_t>(i) + 1] - x[static_cast<size_t>(i)];
        auto [d0, d1] = interval_slopes(x, i, value);
        // The Hermite cubic's integral over its interval: the trapezoid plus (d0 - d1) / 12.
        sum += width * ((value(i) + value(i + 1)) * 0.5f + (d0 - d1) * (1.0f / 12.0f));
        cdf[static_cast<size_t>(i) + 1] = sum;
    }
    return sum;
}

float invert_catmull_rom(std::span<const float> x, std::span<const float> values, float u) {
    if (!(u > values.front())) return x.front();
    if (!(u < values.back())) return x.back();
    const int n = static_cast<int>(x.size());
    int i = find_interval(n, [&](int k) { return values[static_cast<size_t>(k)] <= u; });
    auto value = [&](int k) { return values[static_cast<size_t>(k)]; };
    float x0 = x[static_cast<size_t>(i)], width = x[static_cast<size_t>(i) + 1] - x0;
    float f0 = value(i), f1 = value(i + 1);
    const std::pair<float, float> slopes = interval_slopes(x, i, value);  // captured below (clang 14)
    const float d0 = slopes.first, d1 = slopes.second;
    auto eval = [&](float t) {
        float t2 = t * t, t3 = t2 * t;
        float spline = (2.0f * t3 - 3.0f * t2 + 1.0f) * f0 + (-2.0f * t3 + 3.0f * t2) * f1 +
                       (t3 - 2.0f * t2 + t) * d0 + (t3 - t2) * d1;
        float slope = (6.0f * t2 - 6.0f * t) * f0 + (-6.0f * t2 + 6.0f * t) * f1 +
                      (3.0f * t2 - 4.0f * t + 1.0f) * d0 + (3.0f * t2 - 2.0f * t) * d1;
        return std::pair<float, float>(spline - u, slope);
    };
    return x0 + newton_bisection(eval) * width;
}

}  // namespace candela
