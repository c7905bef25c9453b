// candela_relmse TEST REFERENCE: the relative mean squared error of an image against a reference,
// mean over pixels and channels of (test - ref)^2 / (ref^2 + 0.01) (the 0.01 keeps black pixels
// from dominating, as in the denoising and rendering literature). Benchmarks use it to compare
// estimators at equal sample counts. A TEST that is an integer multiple of REFERENCE in size is
// box-downsampled first (bench/image_compare.h says why that is exact for box-filtered renders).
#include <fmt/format.h>

#include <cstdio>
#include <exception>

#include "bench/image_compare.h"
#include "candela/image/image_io.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        fmt::print(stderr, "usage: candela_relmse TEST REFERENCE\n");
        return 2;
    }
    try {
        candela::Image test = candela::read_image(argv[1]);
        candela::Image ref = candela::read_image(argv[2]);
        fmt::print("{:.6g}\n", candela::bench::relmse(test, ref));
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "candela_relmse: {}\n", e.what());
        return 2;
    }
}
