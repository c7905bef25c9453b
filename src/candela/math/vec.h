#pragma once
// 2D and 3D vectors for points, directions and normals (one type, as in Mitsuba's and yocto's
// math: the meaning is in the name). Vec3f for rendering, Vec3d where precision matters (sphere
// intersection, transforms at load time).
#include <cmath>
#include <cstdint>

#include "candela/core/platform.h"

namespace candela {

template <class T>
struct Vec2 {
    T x{}, y{};
    CANDELA_HD constexpr Vec2() = default;
    CANDELA_HD constexpr Vec2(T x_, T y_) : x(x_), y(y_) {}
    CANDELA_HD constexpr T operator[](int i) const { return i == 0 ? x : y; }
    CANDELA_HD constexpr T& operator[](int i) { return i == 0 ? x : y; }
    CANDELA_HD constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
    CANDELA_HD constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
    CANDELA_HD constexpr Vec2 operator*(T s) const { return {x * s, y * s}; }
    CANDELA_HD constexpr bool operator==(const Vec2&) const = default;
};

template <class T>
struct Vec3 {
    T x{}, y{}, z{};
    CANDELA_HD constexpr Vec3() = default;
    CANDELA_HD constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
    CANDELA_HD explicit constexpr Vec3(T s) : x(s), y(s), z(s) {}
    template <class U>
    CANDELA_HD explicit constexpr Vec3(const Vec3<U>& o) : x(T(o.x)), y(T(o.y)), z(T(o.z)) {}

    CANDELA_HD constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    CANDELA_HD constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    CANDELA_HD constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    CANDELA_HD constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    CANDELA_HD constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    CANDELA_HD constexpr Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
    CANDELA_HD constexpr Vec3 operator*(T s) const { return {x * s, y * s, z * s}; }
    CANDELA_HD constexpr Vec3 operator/(T s) const { return {x / s, y / s, z / s}; }
    CANDELA_HD constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    CANDELA_HD constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    CANDELA_HD constexpr Vec3& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
    CANDELA_HD constexpr bool operator==(const Vec3&) const = default;
};

template <class T>
CANDELA_HD constexpr Vec3<T> operator*(T s, const Vec3<T>& v) { return v * s; }
template <class T>
CANDELA_HD constexpr Vec2<T> operator*(T s, const Vec2<T>& v) { return v * s; }

using Vec2f = Vec2<float>;
using Vec2i = Vec2<int>;
using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;

template <class T>
CANDELA_HD constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T>
CANDELA_HD constexpr T abs_dot(const Vec3<T>& a, const Vec3<T>& b) { return std::abs(dot(a, b)); }
template <class T>
CANDELA_HD constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
CANDELA_HD constexpr T length_squared(const Vec3<T>& v) { return dot(v, v); }
template <class T>
CANDELA_HD inline T length(const Vec3<T>& v) { return std::sqrt(dot(v, v)); }
template <class T>
CANDELA_HD inline Vec3<T> normalize(const Vec3<T>& v) { return v * (T(1) / length(v)); }
template <class T>
CANDELA_HD inline Vec3<T> abs(const Vec3<T>& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
template <class T>
CANDELA_HD constexpr T max_component(const Vec3<T>& v) {
    // Two plain "a > b ? a : b" steps, each one maxss: the nested form compiled to a branch on
    // which component is largest, which hit points make random (about 1% of a Cornell box
    // render). The same result for every input, NaN included.
    T m = v.x > v.y ? v.x : v.y;
    return m > v.z ? m : v.z;
}
template <class T>
CANDELA_HD constexpr Vec3<T> min(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
template <class T>
CANDELA_HD constexpr Vec3<T> max(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}
// Flips v to lie in the hemisphere of n.
template <class T>
CANDELA_HD constexpr Vec3<T> face_forward(const Vec3<T>& v, const Vec3<T>& n) {
    return dot(v, n) < T(0) ? -v : v;
}
template <class T>
CANDELA_HD inline bool is_finite(const Vec3<T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace candela
