// candela_compare_pbrt TEST REFERENCE [--bounds MEAN P95] [--block N]: compares a candela render
// with pbrt-v4's render of the same scene as ../shared/refs/pbrt-v4/README.md defines
// (bench/block_compare.h): the mean ratio per channel (sum TEST / sum REFERENCE) and the p50, p95
// and maximum of the NxN blocks' (16x16 by default; tests/data/pbrt-media/ uses 8x8 on its 96x96
// images) relative luminance differences, blocks darker than 5% of the median block left out.
// With --bounds (scenes.txt's two columns), exits 1 when a channel's |ratio - 1| exceeds MEAN or
// the block p95 exceeds P95; 2 for usage or file errors.
// candela_compare_pbrt --write-block-means IMAGE OUT.exr [N] writes IMAGE's NxN-block means (16
// by default), all the comparison reads of a reference: how tests/data/refs/ holds pbrt-v4's
// images small.
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <string>

#include "bench/block_compare.h"
#include "candela/image/image_io.h"

int main(int argc, char** argv) {
    if ((argc == 4 || argc == 5) && std::string(argv[1]) == "--write-block-means") {
        try {
            const int block = argc == 5 ? std::stoi(argv[4]) : 16;
            candela::write_image(argv[3], candela::bench::block_means(candela::read_image(argv[2]), block),
                                 candela::DisplayEncoding{});
            return 0;
        } catch (const std::exception& e) {
            fmt::print(stderr, "candela_compare_pbrt: {}\n", e.what());
            return 2;
        }
    }
    std::string test_file, ref_file;
    double max_mean_bias = -1.0, max_p95 = -1.0;
    int block = 16;
    bool usage_error = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--bounds" && i + 2 < argc) {
            try {
                max_mean_bias = std::stod(argv[++i]);
                max_p95 = std::stod(argv[++i]);
            } catch (const std::exception&) {
                usage_error = true;
            }
            usage_error = usage_error || !(max_mean_bias >= 0.0) || !(max_p95 >= 0.0);
        } else if (a == "--block" && i + 1 < argc) {
            try {
                block = std::stoi(argv[++i]);
            } catch (const std::exception&) {
                usage_error = true;
            }
            usage_error = usage_error || block < 1;
        } else if (a.starts_with("--") || !ref_file.empty()) {
            usage_error = true;
        } else {
            (test_file.empty() ? test_file : ref_file) = a;
        }
    }
    if (usage_error || ref_file.empty()) {
        fmt::print(stderr, "usage: candela_compare_pbrt TEST REFERENCE [--bounds MEAN P95] [--block N]  (bounds as fractions, "
                             ">= 0)\n");
        return 2;
    }
    try {
        const candela::Image test = candela::read_image(test_file);
        const candela::Image ref = candela::read_image(ref_file);
        const candela::bench::BlockComparison c = candela::bench::compare_blocks(test, ref, block);
        fmt::print("mean ratio R G B: {:.4f} {:.4f} {:.4f}\n", c.mean_ratio[0], c.mean_ratio[1], c.mean_ratio[2]);
        fmt::print("{}x{}-block luminance relative difference ({} of {} blocks): p50 {:.2f}%  p95 {:.2f}%  max {:.2f}%\n",
                   block, block, c.blocks_compared, c.blocks_total, 100.0 * c.p50, 100.0 * c.p95, 100.0 * c.max);
        if (max_mean_bias < 0.0) return 0;
        const bool ok = candela::bench::within_bounds(c, max_mean_bias, max_p95);
        fmt::print("{} bounds: mean {:g}, block p95 {:g}\n", ok ? "within" : "OUTSIDE", max_mean_bias, max_p95);
        return ok ? 0 : 1;
    } catch (const std::exception& e) {
        fmt::print(stderr, "candela_compare_pbrt: {}\n", e.what());
        return 2;
    }
}
