// The Sampler: the independent kind is exactly the old per-sample PCG32 stream; the Sobol kind is
// Owen-scrambled, per-pixel randomized, and its first 2^m samples are a (0,m,2)-net in every
// request.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "candela/sampling/owen_sobol.h"
#include "candela/sampling/sampler.h"

namespace candela {
namespace CANDELA_UNITY_ID {

TEST(OwenSobol, ReverseBits) {
    EXPECT_EQ(reverse_bits(1u), 0x80000000u);
    EXPECT_EQ(reverse_bits(0x80000000u), 1u);
    EXPECT_EQ(reverse_bits(0x12345678u), 0x1e6a2c48u);
    for (uint32_t x : {0u, 7u, 0xdeadbeefu}) EXPECT_EQ(reverse_bits(reverse_bits(x)), x);
}

TEST(OwenSobol, ReverseBitsOfHalvesReversesEachHalfAndSwapsThem) {
    Rng rng(5, 6);
    for (int k = 0; k < 10000; ++k) {
        uint32_t lo = rng.next_u32(), hi = rng.next_u32();
        uint64_t r = reverse_bits_of_halves(uint64_t(hi) << 32u | lo);
        ASSERT_EQ(uint32_t(r), reverse_bits(hi));
        ASSERT_EQ(uint32_t(r >> 32u), reverse_bits(lo));
    }
}

TEST(OwenSobol, SecondDimensionMatchesTheKnownSequence) {
    // Sobol dimension 1 (polynomial x + 1, direction numbers 1/2, 3/4, 5/8), in binary (not Gray)
    // index order: 0, 1/2, 3/4, 1/4, 5/8, 1/8, 3/8, 7/8.
    const double expected[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    for (uint32_t i = 0; i < 8; ++i) EXPECT_EQ(sobol_dimension1(i) * 0x1p-32, expected[i]) << i;
    // The byte-table form equals the bit-by-bit definition, over all 32 bits.
    Rng rng(1, 2);
    for (int k = 0; k < 100000; ++k) {
        uint32_t i = rng.next_u32();
        ASSERT_EQ(sobol_dimension1(i), sobol_dimension1_reference(i)) << i;
        ASSERT_EQ(sobol_dimension1_reversed(i), reverse_bits(sobol_dimension1_reference(i))) << i;
    }
    // Dimension 0 is van der Corput: 0, 1/2, 1/4, 3/4 ...
    EXPECT_EQ(sobol_dimension0(3) * 0x1p-32, 0.75);
}

TEST(OwenSobol, ScrambleIsABijectionThatKeepsDyadicIntervalsTogether) {
    // Owen scrambling maps each dyadic interval [k/2^m, (k+1)/2^m) onto one whole such interval:
    // the top m bits of the result depend only on the top m bits of the input.
    const uint32_t seed = 0x9e3779b9u;
    for (uint32_t top = 0; top < 16; ++top) {
        std::set<uint32_t> images;
        for (uint32_t low = 0; low < 1000; ++low) {
            uint32_t x = (top << 28) | (low * 2654435761u >> 4);
            images.insert(nested_uniform_scramble(x, seed) >> 28);
        }
        EXPECT_EQ(images.size(), 1u) << top;
    }
    std::set<uint32_t> all;
    for (uint32_t x = 0; x < 4096; ++x) all.insert(nested_uniform_scramble(x << 20, seed) >> 20);
    EXPECT_EQ(all.size(), 4096u);  // a permutation of the 4096 intervals of size 2^-12
}

TEST(Sampler, IndependentIsThePerSampleRngStream) {
    Sampler s(SamplerType::kIndependent, 12345, 17, 99);
    Rng r = Rng::for_sample(12345, 17, 99);
    for (int k = 0; k < 10; ++k) EXPECT_EQ(s.next_float(), r.next_float());
    Vec2f a = s.next_vec2f(), b = r.next_vec2f();
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
}

// Each of the 2^m elementary rectangles of shape 2^-a x 2^-(m-a) holds exactly one point.
bool is_02_net(const std::vector<Vec2f>& points, int m) {
    const uint32_t n = 1u << m;
    for (int a = 0; a <= m; ++a) {
        std::vector<int> count(n, 0);
        for (Vec2f p : points) {
            auto i = uint32_t(p.x * float(1u << a));
            auto j = uint32_t(p.y * float(1u << (m - a)));
            ++count[i * (1u << (m - a)) + j];
        }
        for (int c : count)
            if (c != 1) return false;
    }
    return true;
}

TEST(Sampler, FirstPowerOfTwoSamplesAreANetInEveryRequest) {
    for (int m : {4, 8, 10}) {
        for (uint64_t pixel : {0ull, 1ull, 777ull}) {
            // Requests 0..5 (2D) of samples 0..2^m-1.
            for (int request = 0; request < 6; ++request) {
                std::vector<Vec2f> points;
                for (uint32_t i = 0; i < (1u << m); ++i) {
                    Sampler s(SamplerType::kSobol, pixel, i, 42);
                    for (int r = 0; r < request; ++r) s.next_vec2f();
                    points.push_back(s.next_vec2f());
                }
                EXPECT_TRUE(is_02_net(points, m)) << "m " << m << " pixel " << pixel << " request " << request;
            }
        }
    }
}

TEST(Sampler, OneDimensionalRequestsAreStratified) {
    // 256 samples of a 1D request: one in each interval [k/256, (k+1)/256).
    std::vector<int> count(256, 0);
    for (uint32_t i = 0; i < 256; ++i) {
        Sampler s(SamplerType::kSobol, 5, i, 3);
        s.next_vec2f();
        ++count[size_t(s.next_float() * 256.0f)];
    }
    for (int c : count) EXPECT_EQ(c, 1);
}

TEST(Sampler, PixelsSeedsAndRequestsAreDecorrelated) {
    // Different pixels, seeds and requests give different point sets (not shifted copies).
    auto first = [](uint64_t pixel, uint64_t seed, int request) {
        Sampler s(SamplerType::kSobol, pixel, 0, seed);
        for (int r = 0; r < request; ++r) s.next_vec2f();
        return s.next_vec2f();
    };
    std::set<std::pair<float, float>> seen;
    for (uint64_t pixel = 0; pixel < 20; ++pixel)
        for (uint64_t seed = 0; seed < 5; ++seed)
            for (int request = 0; request < 5; ++request) {
                Vec2f p = first(pixel, seed, request);
                seen.insert({p.x, p.y});
            }
    EXPECT_EQ(seen.size(), 500u);
}

// A skipped request takes its place in the order without being computed: every other request
// gets the number it gets when nothing is skipped.
TEST(Sampler, SkippedRequestsLeaveTheOthersUnchanged) {
    for (SamplerType type : {SamplerType::kIndependent, SamplerType::kSobol}) {
        Sampler all(type, 77, 5, 3), skipping(type, 77, 5, 3);
        for (int bounce = 0; bounce < 6; ++bounce) {
            all.next_float();
            skipping.skip_float();
            EXPECT_EQ(all.next_vec2f(), skipping.next_vec2f());
            EXPECT_EQ(all.next_float(), skipping.next_float());
            all.next_vec2f();
            skipping.skip_vec2f();
            EXPECT_EQ(all.next_float(), skipping.next_float());
        }
        // A control: not skipping shifts every later request (so the checks above can fail).
        Sampler a(type, 77, 5, 3), b(type, 77, 5, 3);
        a.next_float();
        EXPECT_NE(a.next_vec2f(), b.next_vec2f());
    }
}

// The pixel's shared request keys change nothing: every request, cached (the first
// PixelSampler::kCachedKeys) or not, 1D or 2D, skipped or drawn, gives the bits the stand-alone
// sampler gives, for both kinds.
TEST(Sampler, PixelSamplerGivesTheStandAloneSamplersNumbers) {
    for (SamplerType type : {SamplerType::kSobol, SamplerType::kIndependent})
        for (uint64_t pixel : {uint64_t(0), uint64_t(77), uint64_t(1) << 40}) {
            const PixelSampler shared(type, pixel, 12345);
            for (uint32_t s = 0; s < 9; ++s) {
                Sampler a = shared.sample(s), b(type, pixel, s, 12345);
                for (uint32_t r = 0; r < 3 * PixelSampler::kCachedKeys; ++r) {
                    switch (r % 4) {
                        case 0: ASSERT_EQ(a.next_float(), b.next_float()) << r; break;
                        case 1: ASSERT_EQ(a.next_vec2f(), b.next_vec2f()) << r; break;
                        case 2: a.skip_vec2f(); b.skip_vec2f(); break;
                        default: a.skip_float(); b.skip_float(); break;
                    }
                }
            }
        }
}

TEST(Sampler, SobolIsDeterministicAndInTheUnitSquare) {
    for (uint32_t i = 0; i < 1000; ++i) {
        Sampler a(SamplerType::kSobol, 9, i, 1), b(SamplerType::kSobol, 9, i, 1);
        for (int r = 0; r < 20; ++r) {
            float x = a.next_float();
            EXPECT_EQ(x, b.next_float());
            EXPECT_GE(x, 0.0f);
            EXPECT_LT(x, 1.0f);
        }
    }
}

}  // namespace
}  // namespace candela
