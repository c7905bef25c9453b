#include "bench/image_compare.h"

#include <ImfRgbaFile.h>
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace candela::bench {

Image box_downsample(const Image& image, int factor) {
    if (factor < 1 || image.width % factor != 0 || image.height % factor != 0)
        throw std::runtime_error(fmt::format("cannot box-downsample {}x{} by {}", image.width, image.height, factor));
    Image out(image.width / factor, image.height / factor);
    const double scale = 1.0 / (double(factor) * double(factor));
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            double sum[3] = {0.0, 0.0, 0.0};
            for (int dy = 0; dy < factor; ++dy)
                for (int dx = 0; dx < factor; ++dx) {
                    const Rgb& p = image.at(x * factor + dx, y * factor + dy);
                    for (int c = 0; c < 3; ++c) sum[c] += double(p[c]);
                }
            out.at(x, y) = Rgb(float(sum[0] * scale), float(sum[1] * scale), float(sum[2] * scale));
        }
    return out;
}

double relmse(const Image& test, const Image& ref) {
    const int factor = ref.width > 0 ? test.width / ref.width : 0;
    if (factor < 1 || test.width != factor * ref.width || test.height != factor * ref.height)
        throw std::runtime_error(fmt::format("the test image ({}x{}) is not an integer multiple of the reference "
                                             "({}x{}) in size",
                                             test.width, test.height, ref.width, ref.height));
    const Image small = factor == 1 ? test : box_downsample(test, factor);
    double sum = 0.0;
    for (size_t i = 0; i < ref.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double r = double(ref.pixels[i][c]);
            const double d = double(small.pixels[i][c]) - r;
            sum += d * d / (r * r + 0.01);
        }
    return sum / (3.0 * double(ref.pixels.size()));
}

Image average(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::runtime_error(
            fmt::format("cannot average images of different sizes: {}x{} and {}x{}", a.width, a.height, b.width, b.height));
    Image out(a.width, a.height);
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const Rgb &p = a.pixels[i], &q = b.pixels[i];
        out.pixels[i] = Rgb(0.5f * (p.r + q.r), 0.5f * (p.g + q.g), 0.5f * (p.b + q.b));
    }
    return out;
}

void write_half_exr(const std::filesystem::path& file, const Image& image) {
    constexpr float kHalfMax = 65504.0f;
    std::vector<Imf::Rgba> pixels(image.pixels.size());
    for (size_t i = 0; i < pixels.size(); ++i) {
        const Rgb& p = image.pixels[i];
        pixels[i] = Imf::Rgba(half(std::clamp(p.r, -kHalfMax, kHalfMax)), half(std::clamp(p.g, -kHalfMax, kHalfMax)),
                              half(std::clamp(p.b, -kHalfMax, kHalfMax)), half(1.0f));
    }
    Imf::RgbaOutputFile out(file.c_str(), image.width, image.height, Imf::WRITE_RGB, 1.0f, Imath::V2f(0, 0), 1.0f,
                            Imf::INCREASING_Y, Imf::PIZ_COMPRESSION);
    out.setFrameBuffer(pixels.data(), 1, size_t(image.width));
    out.writePixels(image.height);
}

}  // namespace candela::bench
