#pragma once
// A streaming 64-bit hash of bytes, for telling inputs apart (a scene's content hash) and for
// detecting corrupt files (a checkpoint's checksum). Not cryptographic: it guards against
// accidents, not adversaries.
//
// Each 8-byte little-endian word is xored into the state, which is then mixed by mix_bits
// (core/mix_bits.h: splitmix64's output function), a bijection in which every input bit flips
// every output bit with probability ~1/2. The byte count goes into the final word, so inputs
// that differ only by trailing zero bytes differ. The result does not depend on how the input
// was split into add() calls.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "candela/core/mix_bits.h"

namespace candela {

class Hash64 {
  public:
    // Adds raw bytes.
    void add(const void* data, size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        length_ += size;
        size_t i = 0;
        while (i < size && pending_bytes_ != 0) add_byte(bytes[i++]);
        // Whole words while on the stream's word boundary (the fast path for large buffers),
        // assembled byte by byte so that the result is the same on any endianness.
        for (; i + 8 <= size; i += 8) {
            uint64_t word = 0;
            for (unsigned b = 0; b < 8; ++b) word |= uint64_t(bytes[i + b]) << (8u * b);
            state_ = mix_bits(state_ ^ word);
        }
        while (i < size) add_byte(bytes[i++]);
    }
    void add(std::string_view text) { add(text.data(), text.size()); }
    // Adds an integer as 8 little-endian bytes (the same on every machine).
    void add_u64(uint64_t value) {
        unsigned char bytes[8];
        for (int i = 0; i < 8; ++i) bytes[i] = static_cast<unsigned char>(value >> (8 * i));
        add(bytes, 8);
    }
    // Adds a string together with its length, so that ("ab", "c") and ("a", "bc") differ.
    void add_field(std::string_view text) {
        add_u64(text.size());
        add(text);
    }

    // The hash of everything added so far (the hasher can go on).
    uint64_t value() const { return mix_bits(mix_bits(state_ ^ pending_) ^ length_); }

  private:
    void add_byte(unsigned char byte) {
        pending_ |= uint64_t(byte) << (8u * pending_bytes_);
        if (++pending_bytes_ == 8) {
            state_ = mix_bits(state_ ^ pending_);
            pending_ = 0;
            pending_bytes_ = 0;
        }
    }
    uint64_t state_ = 0x6a09e667f3bcc908ull;  // the fraction bits of sqrt(2): any fixed start would do
    uint64_t pending_ = 0;                    // bytes not yet a full word, little-endian
    unsigned pending_bytes_ = 0;
    uint64_t length_ = 0;
};

}  // namespace candela
