#include "candela/film/filter.h"

#include "candela/sampling/normal.h"
#include "candela/sampling/warps.h"

namespace candela {

namespace {

// pbrt's TriangleFilter with radius 1: a separable tent reaching the neighbouring pixel centres.
constexpr float kTentRadius = 1.0f;

// The Gaussian filter: sigma 0.5 pixel, cut at 3 sigma. Sampled exactly from the truncated normal,
// so the weight is exactly 1; pbrt-v4's GaussianFilter instead subtracts the value at the radius
// (so its filter reaches 0 there) and tabulates the result, which needs weights != 1.
constexpr float kGaussianSigma = 0.5f;
constexpr float kGaussianRadius = 1.5f;

// smallpt: 2x2 subpixels, a tent of radius half a pixel (one subpixel width) around each centre.
constexpr float kSubpixelTentRadius = 0.5f;

// The centre of subpixel s (0 or 1) along one axis.
CANDELA_HD float subpixel_centre(uint32_t s) { return 0.5f * static_cast<float>(s) + 0.25f; }

// The 1D marginal of the smallpt filter: the average of the two subpixel tents along one axis.
CANDELA_HD float smallpt_pdf_1d(float x) {
    return 0.5f * (tent_pdf(x - subpixel_centre(0), kSubpixelTentRadius) +
                   tent_pdf(x - subpixel_centre(1), kSubpixelTentRadius));
}

}  // namespace

CANDELA_HD Vec2f sample_filter(FilterType type, uint32_t sample_index, Vec2f u) {
    switch (type) {
        case FilterType::kBox:
            return u;
        case FilterType::kTent:
            return {0.5f + sample_tent(u.x, kTentRadius), 0.5f + sample_tent(u.y, kTentRadius)};
        case FilterType::kGaussian:
            return {0.5f + sample_truncated_normal(u.x, kGaussianSigma, kGaussianRadius),
                    0.5f + sample_truncated_normal(u.y, kGaussianSigma, kGaussianRadius)};
        case FilterType::kSmallpt: {
            // smallpt's loops visit the subpixels in turn; cycling by sample index instead splits
            // every multiple of 4 samples evenly, which progressive passes need.
            uint32_t sx = sample_index % 2u;
            uint32_t sy = (sample_index / 2u) % 2u;
            return {subpixel_centre(sx) + sample_tent(u.x, kSubpixelTentRadius),
                    subpixel_centre(sy) + sample_tent(u.y, kSubpixelTentRadius)};
        }
        default:  // the tabulated filters are PixelFilter's (pixel_filter.h)
            break;
    }
    return u;
}

CANDELA_HD float filter_pdf(FilterType type, Vec2f offset) {
    switch (type) {
        case FilterType::kBox: {
            bool inside_x = offset.x >= 0.0f && offset.x <= 1.0f;
            bool inside_y = offset.y >= 0.0f && offset.y <= 1.0f;
            return inside_x && inside_y ? 1.0f : 0.0f;
        }
        case FilterType::kTent:
            return tent_pdf(offset.x - 0.5f, kTentRadius) * tent_pdf(offset.y - 0.5f, kTentRadius);
        case FilterType::kGaussian:
            return truncated_normal_pdf(offset.x - 0.5f, kGaussianSigma, kGaussianRadius) *
                   truncated_normal_pdf(offset.y - 0.5f, kGaussianSigma, kGaussianRadius);
        case FilterType::kSmallpt:
            // The subpixels are independent in x and y and equally likely, so the average of the
            // four 2D tents factors into the product of two 1D averages.
            return smallpt_pdf_1d(offset.x) * smallpt_pdf_1d(offset.y);
        default:  // the tabulated filters are PixelFilter's (pixel_filter.h)
            break;
    }
    return 0.0f;
}

CANDELA_HD float filter_radius(FilterType type) {
    switch (type) {
        case FilterType::kBox: return 0.5f;
        case FilterType::kTent: return kTentRadius;
        case FilterType::kGaussian: return kGaussianRadius;
        case FilterType::kSmallpt: return 0.25f + kSubpixelTentRadius;  // subpixel centre + tent
        default:  // the tabulated filters are PixelFilter's (pixel_filter.h)
            break;
    }
    return 0.0f;
}

}  // namespace candela
