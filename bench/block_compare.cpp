#include "bench/block_compare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace candela::bench {

namespace {

double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

// The mean luminance of each whole block x block block, row by row.
std::vector<double> block_luminances(const Image& image, int block) {
    std::vector<double> out;
    for (int by = 0; by + block <= image.height; by += block)
        for (int bx = 0; bx + block <= image.width; bx += block) {
            double sum = 0.0;
            for (int y = by; y < by + block; ++y)
                for (int x = bx; x < bx + block; ++x) {
                    const Rgb& p = image.at(x, y);
                    sum += luminance(double(p.r), double(p.g), double(p.b));
                }
            out.push_back(sum / (double(block) * double(block)));
        }
    return out;
}

}  // namespace

double quantile(std::vector<double> values, double q) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const double pos = q * double(values.size() - 1);
    const size_t lo = size_t(std::floor(pos));
    const size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (pos - double(lo)) * (values[hi] - values[lo]);
}

BlockComparison compare_blocks(const Image& test, const Image& ref, int block, double dark_fraction) {
    if (test.width != ref.width || test.height != ref.height)
        throw std::runtime_error(fmt::format("the images differ in size: {}x{} and {}x{}", test.width, test.height,
                                             ref.width, ref.height));
    if (block < 1 || block > ref.width || block > ref.height)
        throw std::runtime_error(fmt::format("{}x{} pixel blocks do not fit a {}x{} image", block, block, ref.width,
                                             ref.height));
    BlockComparison c;
    std::array<double, 3> sum_test{}, sum_ref{};
    for (size_t i = 0; i < ref.pixels.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            sum_test[size_t(ch)] += double(test.pixels[i][ch]);
            sum_ref[size_t(ch)] += double(ref.pixels[i][ch]);
        }
    for (size_t ch = 0; ch < 3; ++ch) {
        if (sum_ref[ch] == 0.0)
            throw std::runtime_error(fmt::format("the reference's channel {} sums to 0", "RGB"[ch]));
        c.mean_ratio[ch] = sum_test[ch] / sum_ref[ch];
    }

    const std::vector<double> y_test = block_luminances(test, block);
    const std::vector<double> y_ref = block_luminances(ref, block);
    const double threshold = dark_fraction * quantile(y_ref, 0.5);
    std::vector<double> differences;
    for (size_t k = 0; k < y_ref.size(); ++k)
        if (y_ref[k] >= threshold && y_ref[k] > 0.0) differences.push_back(std::abs(y_test[k] - y_ref[k]) / y_ref[k]);
    c.blocks_total = int(y_ref.size());
    c.blocks_compared = int(differences.size());
    c.p50 = quantile(differences, 0.5);
    c.p95 = quantile(differences, 0.95);
    c.max = differences.empty() ? 0.0 : *std::max_element(differences.begin(), differences.end());
    return c;
}

bool within_bounds(const BlockComparison& c, double max_mean_bias, double max_p95) {
    for (double r : c.mean_ratio)
        if (!(std::abs(r - 1.0) <= max_mean_bias)) return false;
    return c.p95 <= max_p95;
}

std::string describe(const BlockComparison& c) {
    return fmt::format("mean ratio {} {} {}, block p50 {}, p95 {}, max {}", c.mean_ratio[0], c.mean_ratio[1],
                       c.mean_ratio[2], c.p50, c.p95, c.max);
}

Image block_means(const Image& image, int block) {
    if (block < 1 || block > image.width || block > image.height)
        throw std::runtime_error("block_means: the block is larger than the image");
    Image means(image.width / block, image.height / block);
    for (int by = 0; by < means.height; ++by) {
        for (int bx = 0; bx < means.width; ++bx) {
            double sum[3] = {0.0, 0.0, 0.0};
            for (int y = by * block; y < (by + 1) * block; ++y)
                for (int x = bx * block; x < (bx + 1) * block; ++x)
                    for (int c = 0; c < 3; ++c) sum[c] += double(image.at(x, y)[c]);
            const double n = double(block) * double(block);
            means.at(bx, by) = Rgb(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
        }
    }
    return means;
}

}  // namespace candela::bench
