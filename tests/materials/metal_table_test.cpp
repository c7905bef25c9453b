// The measured-metal table (materials/metal_table.h, computed in the build by
// tools/metals/make_metal_table): each metal's normal-incidence reflectance is the colour
// docs/SCENE_FORMAT.md documents, and every reflectance is physical.
#include <gtest/gtest.h>

#include "candela/materials/fresnel.h"
#include "candela/materials/metal_table.h"

namespace candela {
namespace CANDELA_UNITY_ID {

struct DocumentedMetal {
    Metal metal;
    Color normal_reflectance;  // as docs/SCENE_FORMAT.md lists it, to 3 decimals
};

constexpr DocumentedMetal kDocumented[] = {
    {Metal::kAu, {0.997f, 0.783f, 0.343f}}, {Metal::kAg, {0.972f, 0.960f, 0.915f}},
    {Metal::kCu, {0.953f, 0.638f, 0.538f}}, {Metal::kAl, {0.913f, 0.921f, 0.924f}},
    {Metal::kCr, {0.550f, 0.556f, 0.554f}}, {Metal::kFe, {0.530f, 0.513f, 0.494f}},
    {Metal::kTi, {0.618f, 0.579f, 0.542f}}, {Metal::kCuZn, {0.908f, 0.778f, 0.422f}},
};
static_assert(std::size(kDocumented) == kMetalCount, "document every metal");

TEST(MetalTable, NormalReflectanceIsTheDocumentedColour) {
    for (const DocumentedMetal& d : kDocumented) {
        const MetalIor& ior = metal_ior(d.metal);
        Color f0 = fresnel_complex(1.0f, from_rgb(ior.eta), from_rgb(ior.k));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(f0[c], d.normal_reflectance[c], 5.001e-4f)
                << "metal " << static_cast<int>(d.metal) << " channel " << c;
    }
}

TEST(MetalTable, ReflectanceStaysPhysicalAtEveryAngle) {
    for (const MetalIor& ior : kMetalIors) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT(ior.eta[c], 0.0f);
            EXPECT_GT(ior.k[c], 0.0f);
        }
        for (float cos_theta = 0.0f; cos_theta <= 1.0f; cos_theta += 1.0f / 64.0f) {
            Color f = fresnel_complex(cos_theta, from_rgb(ior.eta), from_rgb(ior.k));
            for (int c = 0; c < 3; ++c) {
                EXPECT_GE(f[c], 0.0f);
                EXPECT_LE(f[c], 1.0f);
            }
        }
    }
}

}  // namespace
}  // namespace candela
