// mix_bits (core/mix_bits.h) is splitmix64's output function: the values below are the first
// outputs of Vigna's reference splitmix64.c seeded with 0, whose state advances by the same
// golden-ratio increment mix_bits adds. Every hash and seed of candela depends on these bits.
#include <gtest/gtest.h>

#include "candela/core/mix_bits.h"

namespace candela {
namespace CANDELA_UNITY_ID {

TEST(MixBits, IsSplitmix64sOutputFunction) {
    constexpr uint64_t kGolden = 0x9e3779b97f4a7c15ull;
    static_assert(mix_bits(0) == 0xe220a8397b1dcdafull);
    EXPECT_EQ(mix_bits(kGolden), 0x6e789e6aa1b965f4ull);
    EXPECT_EQ(mix_bits(2 * kGolden), 0x06c45d188009454full);
}

}  // namespace
}  // namespace candela
