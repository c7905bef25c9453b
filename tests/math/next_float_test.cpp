// next_float_up / next_float_down agree with std::nextafter bit for bit, special values included.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "candela/math/next_float.h"
#include "candela/sampling/rng.h"

namespace candela {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

void expect_same(float a, float b) { EXPECT_EQ(std::bit_cast<uint32_t>(a), std::bit_cast<uint32_t>(b)) << a << " vs " << b; }

TEST(NextFloat, MatchesNextafterOnSpecialValues) {
    for (float v : {0.0f, -0.0f, 1.0f, -1.0f, std::numeric_limits<float>::denorm_min(),
                    -std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                    std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), kInf, -kInf}) {
        expect_same(next_float_up(v), std::nextafter(v, kInf));
        expect_same(next_float_down(v), std::nextafter(v, -kInf));
    }
    EXPECT_TRUE(std::isnan(next_float_up(std::nanf(""))));
    EXPECT_TRUE(std::isnan(next_float_down(std::nanf(""))));
}

TEST(NextFloat, MatchesNextafterOnRandomFloats) {
    Rng rng(4, 2);
    for (int i = 0; i < 200000; ++i) {
        auto v = std::bit_cast<float>(rng.next_u32());
        if (std::isnan(v)) continue;
        expect_same(next_float_up(v), std::nextafter(v, kInf));
        expect_same(next_float_down(v), std::nextafter(v, -kInf));
    }
}

}  // namespace
}  // namespace candela
