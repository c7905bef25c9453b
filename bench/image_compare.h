#pragma once
// Image comparison for the benchmark tools: box downsampling, relMSE, half-float EXR output.
//
// With a box pixel filter, a render at 1/k the resolution is, in expectation, exactly the k x k
// box average of the full-resolution render (each of its pixels integrates the same film area),
// so references are rendered small with many samples per pixel and a full-size benchmark image
// is box-downsampled before it is compared.
#include <filesystem>

#include "candela/image/image.h"

namespace candela::bench {

// The mean of each factor x factor block; the sides must be multiples of factor.
Image box_downsample(const Image& image, int factor);

// Mean over pixels and channels of (test - ref)^2 / (ref^2 + 0.01). `test` may be an integer
// multiple of `ref` in size (the same on both axes): it is box-downsampled first. Throws
// std::runtime_error for other sizes.
double relmse(const Image& test, const Image& ref);

// The per-pixel mean of two images of the same size.
Image average(const Image& a, const Image& b);

// RGB half-float OpenEXR, PIZ-compressed (small for noisy images). Values beyond half's range
// (65504) are clamped to it.
void write_half_exr(const std::filesystem::path& file, const Image& image);

}  // namespace candela::bench
