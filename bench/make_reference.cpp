// candela_make_reference OUT.exr A.exr B.exr: the mean of two independent renders (different
// seeds, same settings) written as half-float EXR, the benchmark's converged reference. Prints
// the reference's own expected relMSE: relMSE(A, B) / 4, since E[(A - B)^2] is twice the
// variance of one render and the mean has half that. A benchmark target must lie well above it.
#include <fmt/format.h>

#include <cstdio>
#include <exception>

#include "bench/image_compare.h"
#include "candela/image/image_io.h"

int main(int argc, char** argv) {
    if (argc != 4) {
        fmt::print(stderr, "usage: candela_make_reference OUT.exr A.exr B.exr\n");
        return 2;
    }
    try {
        candela::Image a = candela::read_image(argv[2]);
        candela::Image b = candela::read_image(argv[3]);
        candela::bench::write_half_exr(argv[1], candela::bench::average(a, b));
        fmt::print("{:.6g}\n", candela::bench::relmse(a, b) / 4.0);
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "candela_make_reference: {}\n", e.what());
        return 2;
    }
}
