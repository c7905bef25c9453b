#pragma once
// Readable GoogleTest failure messages for candela's value types (found by argument-dependent
// lookup, so a failing EXPECT_EQ prints "(1, 2, 3)" instead of raw bytes).
#include <ostream>

#include "candela/math/rgb.h"
#include "candela/math/vec.h"

namespace candela {

inline void PrintTo(const Vec3f& v, std::ostream* os) { *os << "(" << v.x << ", " << v.y << ", " << v.z << ")"; }
inline void PrintTo(const Vec2f& v, std::ostream* os) { *os << "(" << v.x << ", " << v.y << ")"; }
inline void PrintTo(const Rgb& c, std::ostream* os) { *os << "rgb(" << c.r << ", " << c.g << ", " << c.b << ")"; }

}  // namespace candela
