#pragma once
// Catmull-Rom splines over non-uniform nodes: interpolation weights, the spline's integral and
// cumulative integral, inversion of a monotone spline, and sampling a 2D tabulated function
// along its second parameter (pbrt-v4's util/math and util/sampling spline routines, which the
// tabulated BSSRDF, materials/tabulated_bssrdf.h, uses for its profile).
//
// The spline through values f_i at nodes x_i is, on [x_i, x_{i+1}], the cubic Hermite
// interpolant whose end derivatives are finite differences of the neighbours,
//   f'(x_i) ~ (f_{i+1} - f_{i-1}) / (x_{i+1} - x_{i-1}),
// and one-sided differences (f_{i+1} - f_i) / (x_{i+1} - x_i) at the first and last nodes. Every
// routine here uses that same spline, so a value, its integral and its inverse agree.
#include <span>

namespace candela {

// The four weights of nodes offset .. offset + 3 whose sum with the function's values at those
// nodes is the spline's value at x. Returns false (and leaves the outputs untouched) when x lies
// outside [nodes.front(), nodes.back()]. offset may be -1 and offset + 3 may be nodes.size():
// the weight of such a missing node is 0.
bool catmull_rom_weights(std::span<const float> nodes, float x, int* offset, float weights[4]);

// Samples the second parameter of a function tabulated on nodes1 x nodes2 (values row-major,
// nodes1 outer) at first parameter alpha, in proportion to the spline's value there: the
// sample's value is the x with u = F(x) / F(max), F the integral of the spline (cdf holds F at
// the nodes of each row, as integrate_catmull_rom writes it). fval and pdf (if given) receive
// the interpolated function's value and the sample's density at x. Returns 0 when alpha is
// outside nodes1.
float sample_catmull_rom_2d(std::span<const float> nodes1, std::span<const float> nodes2,
                            std::span<const float> values, std::span<const float> cdf, float alpha,
                            float u, float* fval = nullptr, float* pdf = nullptr);

// The spline's integral over [x.front(), x.back()]; cdf (of x.size()) receives its integral from
// x.front() to each node.
float integrate_catmull_rom(std::span<const float> x, std::span<const float> values,
                            std::span<float> cdf);

// The x at which the spline through (x, values), which must increase, takes the value u;
// x.front() below values.front() and x.back() above values.back().
float invert_catmull_rom(std::span<const float> x, std::span<const float> values, float u);

}  // namespace candela
