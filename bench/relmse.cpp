// candela_relmse TEST REFERENCE: the relative mean squared error of an image against a reference,
// mean over pixels and channels of (test - ref)^2 / (ref^2 + 0.01) (the 0.01 keeps black pixels
// from dominating, as in the denoising and rendering literature). Benchmarks use it to compare
// estimators at equal sample counts.
#include <fmt/format.h>

#include <cstdio>
#include <exception>

#include "candela/image/image_io.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        fmt::print(stderr, "usage: candela_relmse TEST REFERENCE\n");
        return 2;
    }
    try {
        candela::Image test = candela::read_image(argv[1]);
        candela::Image ref = candela::read_image(argv[2]);
        if (test.width != ref.width || test.height != ref.height) {
            fmt::print(stderr, "candela_relmse: sizes differ: {}x{} vs {}x{}\n", test.width, test.height, ref.width,
                       ref.height);
            return 2;
        }
        double sum = 0.0;
        for (size_t i = 0; i < ref.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                double d = double(test.pixels[i][c]) - double(ref.pixels[i][c]);
                sum += d * d / (double(ref.pixels[i][c]) * double(ref.pixels[i][c]) + 0.01);
            }
        fmt::print("{:.6g}\n", sum / (3.0 * double(ref.pixels.size())));
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "candela_relmse: {}\n", e.what());
        return 2;
    }
}
