#pragma once
// Numeric constants and small scalar helpers.
#include <cmath>
#include <limits>

#include "candela/core/platform.h"

namespace candela {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInv2Pi = 0.15915494309189533577f;
inline constexpr float kInv4Pi = 0.07957747154594766788f;
inline constexpr float kPiOver2 = 1.57079632679489661923f;
inline constexpr float kPiOver4 = 0.78539816339744830962f;
inline constexpr double kPiD = 3.14159265358979323846;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();
// The largest float below 1: uniform samples live in [0, kOneMinusEpsilon].
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

CANDELA_HD inline constexpr float radians(float deg) { return deg * (kPi / 180.0f); }
CANDELA_HD inline constexpr float degrees(float rad) { return rad * (180.0f / kPi); }

template <class T>
CANDELA_HD constexpr T clamp(T v, T lo, T hi) {
    return v < lo ? lo : (v > hi ? hi : v);
}
template <class T>
CANDELA_HD constexpr T lerp(float t, T a, T b) {
    return (1 - t) * a + t * b;
}
CANDELA_HD inline float safe_sqrt(float x) { return std::sqrt(x > 0.0f ? x : 0.0f); }
CANDELA_HD inline double safe_sqrt(double x) { return std::sqrt(x > 0.0 ? x : 0.0); }
CANDELA_HD inline float sqr(float x) { return x * x; }
CANDELA_HD inline double sqr(double x) { return x * x; }

}  // namespace candela
