// The `blend` material end to end (pbrt-v4's `mix`): a quad of a blend of two diffuse albedos a
// and b fills the view of a camera under a constant environment of 1. With BSDF sampling each
// camera sample's value is exactly the albedo of the part chosen at its hit (f cos / pdf is the
// albedo and every bounce escapes), so the image's mean is a + (b - a) k / N for the k of N
// samples that chose b: binomial, of mean N amount. That is pbrt-v4's and Mitsuba's blendbsdf's
// expectation, (1 - amount) a + amount b, within a bound from the binomial variance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "candela/render/renderer.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 32;
constexpr int kSpp = 16;

// The quad [-1, 1]^2 in the z = 0 plane, seen from +z, filling the view; its material is "m"
// of `materials`.
Scene blend_quad(const std::string& materials, const std::string& integrator = "bsdf", bool spectral = false) {
    const std::string json = R"({
      "integrator": {"type": ")" + integrator + R"(", "spectral": )" + (spectral ? "true" : "false") + R"(},
      "sampler": {"spp": )" + std::to_string(kSpp) + R"(, "seed": 7},
      "camera": {"position": [0, 0, 2], "look_at": [0, 0, 0], "up": [0, 1, 0],
                 "fov": 43.6028, "resolution": [)" + std::to_string(kSize) + ", " + std::to_string(kSize) + R"(]},
      "materials": {)" + materials + R"(},
      "shapes": [{"type": "quad", "corner": [-1, -1, 0], "edge1": [2, 0, 0], "edge2": [0, 2, 0],
                  "material": "m"}],
      "lights": [{"type": "environment", "color": 1}]})";
    return load_scene_from_string(json, std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes" / "inline.json");
}

// The mean of the image's red channel.
double image_mean(const Image& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) sum += double(image.at(x, y)[0]);
    return sum / double(image.width * image.height);
}

const char* kParts = R"("a": {"type": "diffuse", "albedo": 0.2}, "b": {"type": "diffuse", "albedo": 0.8}, )";

TEST(BlendRender, AveragesToTheAmountWeightedMixOfItsParts) {
    for (float amount : {0.3f, 0.5f, 0.9f}) {
        const Image image = render(blend_quad(std::string(kParts) + R"("m": {"type": "blend", "materials": ["a", "b"],
                                              "amount": )" + std::to_string(amount) + "}"),
                                   {.threads = 2})
                                .image;
        // Each sample is 0.2 or 0.8; the count of 0.8s is binomial(N, amount).
        const double n = double(kSize * kSize * kSpp);
        const double expected = 0.2 + 0.6 * double(amount);
        const double sigma = 0.6 * std::sqrt(double(amount) * (1.0 - double(amount)) / n);
        EXPECT_NEAR(image_mean(image), expected, 5.0 * sigma) << "amount " << amount;
        // And no pixel is anything but a mean of 0.2s and 0.8s.
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                EXPECT_GE(image.at(x, y)[0], 0.2f - 1e-6f);
                EXPECT_LE(image.at(x, y)[0], 0.8f + 1e-6f);
            }
    }
}

TEST(BlendRender, NestedBlendsMultiplyTheirAmounts) {
    // outer: inner with probability 1/2, c = 1 otherwise; inner: a or b with probability 1/2 each.
    const Image image = render(blend_quad(std::string(kParts) + R"("c": {"type": "diffuse", "albedo": 1},
        "inner": {"type": "blend", "materials": ["a", "b"]},
        "m": {"type": "blend", "materials": ["c", "inner"]})"), {.threads = 2}).image;
    // Values 0.2, 0.8 (probability 1/4 each) and 1 (1/2): mean 0.75, variance 0.105.
    const double n = double(kSize * kSize * kSpp);
    EXPECT_NEAR(image_mean(image), 0.75, 5.0 * std::sqrt(0.105 / n));
}

TEST(BlendRender, AmountZeroAndOneRenderExactlyTheirPart) {
    // No sampler dimension is spent on the choice, so the images are the parts' bit for bit,
    // in both modes and with the full path tracer.
    for (bool spectral : {false, true}) {
        auto image = [&](const std::string& m) {
            return render(blend_quad(std::string(kParts) + m, "path", spectral), {.threads = 2}).image;
        };
        const Image a = image(R"("m": {"type": "diffuse", "albedo": 0.2})");
        const Image b = image(R"("m": {"type": "diffuse", "albedo": 0.8})");
        const Image zero = image(R"("m": {"type": "blend", "materials": ["a", "b"], "amount": 0})");
        const Image one = image(R"("m": {"type": "blend", "materials": ["a", "b"], "amount": 1})");
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                for (int c = 0; c < 3; ++c) {
                    EXPECT_EQ(zero.at(x, y)[c], a.at(x, y)[c]);
                    EXPECT_EQ(one.at(x, y)[c], b.at(x, y)[c]);
                }
    }
}

TEST(BlendRender, TexturedAmountChoosesByPoint) {
    // amount 0 on the left half of the quad (u < 1/2), 1 on the right: the albedo view shows a
    // on the left and b on the right.
    const Image image = render(blend_quad(std::string(kParts) + R"("m": {"type": "blend", "materials": ["a", "b"],
        "amount": {"type": "checkerboard", "color0": 0, "color1": 1, "uv_scale": [2, 1]}})", "albedo"),
                               {.threads = 2})
                            .image;
    for (int y = 0; y < kSize; ++y) {
        EXPECT_EQ(image.at(2, y)[0], 0.2f);
        EXPECT_EQ(image.at(kSize - 3, y)[0], 0.8f);
    }
}

TEST(BlendRender, TheChoiceIsTheSameEveryRender) {
    const std::string m = std::string(kParts) + R"("m": {"type": "blend", "materials": ["a", "b"], "amount": 0.5})";
    const Image first = render(blend_quad(m, "path"), {.threads = 1}).image;
    const Image second = render(blend_quad(m, "path"), {.threads = 2}).image;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) EXPECT_EQ(first.at(x, y)[0], second.at(x, y)[0]);
}

}  // namespace
}  // namespace candela
