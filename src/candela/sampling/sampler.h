#pragma once
// The source of every random number of one camera sample. Integrators draw from it in a fixed
// order (one request per decision, the same requests every bounce whether or not they are used),
// so a request's position in that order is its dimension:
//
//   request 0      2D  pixel filter (film position)
//   request 1      2D  lens point, only for a camera with a lens (aperture_radius > 0: a property
//                      of the scene, so every sample of a render asks the same requests)
//   per bounce     1D  light choice, 2D light point (next-event estimation; the point's x also
//                      picks a mesh light's triangle, MeshEmitter::sample)
//                  1D  BSDF lobe choice, 2D BSDF direction
//                  1D  Russian roulette
//
// A request whose number a decision does not need is skipped (skip_float, skip_vec2f) rather
// than computed: it still takes its place in the order. What is skipped is known before the
// bounce's ray is traced (the light choice with a single light, the lobe choice when no material
// reads it, roulette before rr_depth), so the integrators draw a bounce's numbers first and the
// CPU computes them while Embree traverses (integrators/path_common.h).
//
// Two kinds (scene key sampler.type):
//  - independent: PCG32 from Rng::for_sample(pixel, sample, seed), as before: every number
//    independent of every other.
//  - sobol: Owen-scrambled Sobol points (owen_sobol.h), randomized per pixel: request d of sample
//    i in pixel p is point shuffle(i) of the 2D (0,2)-sequence, scrambled and shuffled by hashes
//    of (seed, p, d). The first 2^m samples of a pixel are then a (0,m,2)-net for every request.
//
// Either way a sample is a pure function of (pixel, sample index, seed): images do not depend on
// thread count, tile order or interruptions.
#include <cstdint>

#include "candela/core/platform.h"
#include "candela/math/vec.h"
#include "candela/sampling/owen_sobol.h"
#include "candela/sampling/rng.h"

namespace candela {

enum class SamplerType { kIndependent, kSobol };

class Sampler;

// What the samples of one pixel share. For sobol, the hash (key) of each request depends only on
// (seed, pixel, request number), not on the sample: the first kCachedKeys keys are computed once
// for the pixel and read by all its samples. A key heads the dependency chain of every request,
// so this shortens the chain by a 64-bit hash (1.3% of a Cornell box render, bench/RESULTS.md).
// The renderer makes one per pixel and pass; it must outlive the samplers it makes.
class PixelSampler {
  public:
    static constexpr uint32_t kCachedKeys = 32;  // the requests of six path vertices

    PixelSampler(SamplerType type, uint64_t pixel_index, uint64_t seed);
    // Sample `sample_index` of the pixel: the same numbers as
    // Sampler(type, pixel_index, sample_index, seed).
    Sampler sample(uint32_t sample_index) const;

  private:
    friend class Sampler;
    SamplerType type_;
    uint64_t pixel_index_;
    uint64_t seed_;
    uint64_t pixel_key_ = 0;      // sobol only: Sampler::hash_pixel(seed, pixel_index)
    uint64_t keys_[kCachedKeys];  // sobol only
};

class Sampler {
  public:
    CANDELA_HD Sampler(SamplerType type, uint64_t pixel_index, uint32_t sample_index, uint64_t seed)
        : type_(type), index_(sample_index) {
        if (type == SamplerType::kIndependent)
            rng_ = Rng::for_sample(pixel_index, sample_index, seed);
        else
            pixel_key_ = hash_pixel(seed, pixel_index);
        reversed_index_ = reverse_bits(sample_index);
    }
    // The same sampler, reading the pixel's key and request keys (PixelSampler::sample).
    Sampler(const PixelSampler& pixel, uint32_t sample_index) : type_(pixel.type_), index_(sample_index) {
        if (type_ == SamplerType::kIndependent) {
            rng_ = Rng::for_sample(pixel.pixel_index_, sample_index, pixel.seed_);
        } else {
            pixel_key_ = pixel.pixel_key_;
            key_cache_ = pixel.keys_;
            cached_keys_ = PixelSampler::kCachedKeys;
        }
        reversed_index_ = reverse_bits(sample_index);
    }

    // A uniform number in [0, 1), never 1.0.
    CANDELA_HD float next_float() {
        if (type_ == SamplerType::kIndependent) return rng_.next_float();
        uint64_t key = request_key();
        return u32_to_unit_float(scrambled_dimension0(shuffled_index(key), uint32_t(key >> 32)));
    }

    // A uniform point in [0, 1)^2 (for independent sampling: x drawn first).
    CANDELA_HD Vec2f next_vec2f() {
        if (type_ == SamplerType::kIndependent) return rng_.next_vec2f();
        uint64_t key = request_key();
        uint32_t i = shuffled_index(key);
        // The y scramble's seed: the key's halves already seed the shuffle and x; a 32-bit
        // multiplicative hash of them gives a third, unrelated one.
        uint32_t y_seed = (uint32_t(key) ^ uint32_t(key >> 32)) * 0x9e3779b9u + 0x7f4a7c15u;
        // Both coordinates are Owen scrambles of reversed values, reversed back in one step.
        uint64_t scrambled_reversed = uint64_t(laine_karras_permutation(i, uint32_t(key >> 32))) << 32u |
                                      laine_karras_permutation(sobol_dimension1_reversed(i), y_seed);
        uint64_t xy = reverse_bits_of_halves(scrambled_reversed);  // x in the low half, y in the high
        return {u32_to_unit_float(uint32_t(xy)), u32_to_unit_float(uint32_t(xy >> 32u))};
    }

    // The request next_float() or next_vec2f() would answer, skipped without computing it: for
    // numbers a decision does not need this time (Russian roulette before rr_depth, the lobe
    // choice of a one-lobe BSDF). Every later request gets the number it would have got.
    CANDELA_HD void skip_float() {
        if (type_ == SamplerType::kIndependent)
            rng_.next_u32();
        else
            ++request_;
    }
    CANDELA_HD void skip_vec2f() {
        if (type_ == SamplerType::kIndependent) {
            rng_.next_u32();
            rng_.next_u32();
        } else {
            ++request_;
        }
    }

    CANDELA_HD SamplerType type() const { return type_; }
    CANDELA_HD uint32_t sample_index() const { return index_; }

  private:
    friend class PixelSampler;
    // The hash of (seed, pixel, request number), from the pixel's cache when it holds it; the
    // request counter moves on.
    CANDELA_HD uint64_t request_key() {
        const uint32_t r = request_++;
        return r < cached_keys_ ? key_cache_[r] : hash_request(pixel_key_, r);
    }
    CANDELA_HD static uint64_t hash_request(uint64_t pixel_key, uint32_t r) {
        return mix_bits(pixel_key ^ (uint64_t(r) << 1u));
    }
    CANDELA_HD static uint64_t hash_pixel(uint64_t seed, uint64_t pixel_index) {
        return mix_bits(mix_bits(seed) ^ pixel_index);
    }
    // The sample's position in this request's private order of the sequence. The index is
    // scrambled like a fraction: bit k of the result depends on bits k and above. The first 2^m
    // indices have zeros from bit m up, so they map to one aligned block of 2^m points of the
    // sequence (in scrambled order), and an aligned block of Sobol points is a net.
    // (nested_uniform_scramble(index_, seed), with the first reversal done once per sample.)
    CANDELA_HD uint32_t shuffled_index(uint64_t key) const {
        return reverse_bits(laine_karras_permutation(reversed_index_, uint32_t(key)));
    }

    // nested_uniform_scramble(sobol_dimension0(i), seed) without the two reversals that cancel.
    CANDELA_HD static uint32_t scrambled_dimension0(uint32_t i, uint32_t seed) {
        return reverse_bits(laine_karras_permutation(i, seed));
    }

    SamplerType type_;
    uint32_t index_;
    uint32_t reversed_index_;
    uint32_t request_ = 0;
    uint64_t pixel_key_ = 0;
    const uint64_t* key_cache_ = nullptr;  // the pixel's first cached_keys_ keys (PixelSampler)
    uint32_t cached_keys_ = 0;
    Rng rng_;
};

inline PixelSampler::PixelSampler(SamplerType type, uint64_t pixel_index, uint64_t seed)
    : type_(type), pixel_index_(pixel_index), seed_(seed) {
    if (type != SamplerType::kSobol) return;
    pixel_key_ = Sampler::hash_pixel(seed, pixel_index);
    for (uint32_t r = 0; r < kCachedKeys; ++r) keys_[r] = Sampler::hash_request(pixel_key_, r);
}

inline Sampler PixelSampler::sample(uint32_t sample_index) const { return Sampler(*this, sample_index); }

}  // namespace candela
