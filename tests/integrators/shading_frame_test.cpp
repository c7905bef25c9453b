// The shading frame of materials with normal maps, bump maps or anisotropic lobes
// (integrators/shading_frame.h): the perturbed normal points where the maps' math says.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/integrators/shading_frame.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"

namespace candela {
namespace CANDELA_UNITY_ID {

void expect_near(const Vec3f& a, const Vec3f& b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// A hit on the plane z = 0 at uv (0.3, 0.2), front +z, with the given derivatives.
struct PlaneHit {
    SurfaceHit hit;
    ShadingGeometry g;
    PlaneHit(Vec3f dpdu = {1, 0, 0}, Vec3f dpdv = {0, 1, 0}) {
        hit.p = Vec3f(0.3f, 0.2f, 0.0f);
        hit.ng = hit.ns = Vec3f(0, 0, 1);
        g.uv = Vec2f(0.3f, 0.2f);
        g.dpdu = dpdu;
        g.dpdv = dpdv;
    }
};

// A diffuse material with a constant normal map of colour c.
Material normal_mapped(Vec3f c, NormalMapConvention convention = NormalMapConvention::kOpenGl) {
    Material m = make_diffuse(Rgb(0.5f));
    SurfaceParams s;
    s.normal_map = ColorParam{Rgb(c.x, c.y, c.z)};
    s.normal_map_convention = convention;
    set_surface(m, s);
    return m;
}

// The colour of tangent-space normal n.
Vec3f encode(Vec3f n) { return n * 0.5f + Vec3f(0.5f); }

TEST(ShadingFrame, FlatNormalMapGivesTheShadingNormalBitForBit) {
    const TextureSet textures;
    Rng rng(1, 1);
    for (int i = 0; i < 1000; ++i) {
        SurfaceHit hit;
        hit.ns = sample_uniform_sphere(rng.next_vec2f());
        hit.ng = normalize(hit.ns + Vec3f(0.1f, 0.0f, 0.0f));
        ShadingGeometry g;
        fallback_tangents(hit.ng, g.dpdu, g.dpdv);
        g.dpdu = g.dpdu * 3.0f + hit.ns * 0.5f;  // any tangent, not perpendicular to ns
        const Material m = normal_mapped(Vec3f(0.5f, 0.5f, 1.0f));
        if (dot(hit.ns, hit.ng) <= 0.0f) continue;
        const Frame f = shading_frame(m, textures, g, hit);
        const Frame plain = Frame::from_normal(hit.ns);
        EXPECT_EQ(f.n, plain.n);
        EXPECT_EQ(f.s, plain.s);
        EXPECT_EQ(f.t, plain.t);
    }
}

// A map tilted by angle a towards +u turns the normal towards dpdu by a; towards +v, towards
// dpdv (the OpenGL convention), or away from it (DirectX).
TEST(ShadingFrame, NormalMapTiltsTheNormalTowardsTheMappedDirection) {
    const TextureSet textures;
    const float a = 0.4f;
    const Vec3f towards_u(std::sin(a), 0.0f, std::cos(a)), towards_v(0.0f, std::sin(a), std::cos(a));
    // dpdu along +y, dpdv along -x (still right-handed: cross = +z), lengths that do not matter.
    PlaneHit p(Vec3f(0, 2, 0), Vec3f(-3, 0, 0));
    expect_near(shading_frame(normal_mapped(encode(towards_u)), textures, p.g, p.hit).n,
                Vec3f(0, std::sin(a), std::cos(a)), 1e-6f);
    expect_near(shading_frame(normal_mapped(encode(towards_v)), textures, p.g, p.hit).n,
                Vec3f(-std::sin(a), 0, std::cos(a)), 1e-6f);
    expect_near(shading_frame(normal_mapped(encode(towards_v), NormalMapConvention::kDirectX), textures, p.g, p.hit).n,
                Vec3f(std::sin(a), 0, std::cos(a)), 1e-6f);
    // A mirrored uv map (dpdv along +x, cross(dpdu, dpdv) = -z): +v still tilts towards dpdv.
    PlaneHit mirrored(Vec3f(0, 2, 0), Vec3f(3, 0, 0));
    expect_near(shading_frame(normal_mapped(encode(towards_v)), textures, mirrored.g, mirrored.hit).n,
                Vec3f(std::sin(a), 0, std::cos(a)), 1e-6f);
    // dpdu not in the tangent plane (a shading normal off the geometric one): its projection counts.
    PlaneHit skew(Vec3f(1, 0, 5), Vec3f(0, 1, 0));
    expect_near(shading_frame(normal_mapped(encode(towards_u)), textures, skew.g, skew.hit).n,
                towards_u, 1e-6f);
}

TEST(ShadingFrame, MappedNormalIsFlippedToTheGeometricNormalsSide) {
    const TextureSet textures;
    PlaneHit p;
    // (0, 0, -1) in tangent space points into the surface: pbrt-v4 flips it back.
    const Frame f = shading_frame(normal_mapped(Vec3f(0.5f, 0.5f, 0.0f)), textures, p.g, p.hit);
    expect_near(f.n, Vec3f(0, 0, 1), 1e-6f);
    // A black texel (zero vector after decoding: (0.5, 0.5, 0.5)) leaves the normal alone.
    expect_near(shading_frame(normal_mapped(Vec3f(0.5f)), textures, p.g, p.hit).n, Vec3f(0, 0, 1), 0.0f);
}

// Height h(u, v) = k u on a plane whose dpdu has length L: the surface rises by k / L per unit
// length along dpdu, so the normal tilts away from dpdu by atan(k / L).
TEST(ShadingFrame, BumpMapOfALinearRampTiltsByItsSlope) {
    for (float k : {0.1f, 1.0f, -3.0f}) {
        const Vec3f dpdu(2, 0, 0);
        PlaneHit p(dpdu, Vec3f(0, 0.5f, 0));
        const Vec3f n = apply_bump_map(p.hit.ns, p.g, p.hit.p, [k](const Vec2f& uv, const Vec3f&) { return k * uv.x; });
        const float angle = std::atan(k / 2.0f);
        expect_near(n, Vec3f(-std::sin(angle), 0.0f, std::cos(angle)), 2e-3f);
        // A ramp in v tilts away from dpdv.
        const Vec3f nv = apply_bump_map(p.hit.ns, p.g, p.hit.p, [k](const Vec2f& uv, const Vec3f&) { return k * uv.y; });
        const float angle_v = std::atan(k / 0.5f);
        expect_near(nv, Vec3f(0.0f, -std::sin(angle_v), std::cos(angle_v)), 2e-3f);
    }
    // A constant height on a plane changes nothing.
    PlaneHit p;
    expect_near(apply_bump_map(p.hit.ns, p.g, p.hit.p, [](const Vec2f&, const Vec3f&) { return 0.7f; }),
                Vec3f(0, 0, 1), 1e-6f);
}

// A 1-texel float image of colour c (any uv reads c) and a 2x1 grey one of values 0 and 1 (with
// clamp, bilinear lookups rise linearly from 0 at u = 1/4 to 1 at u = 3/4).
TextureImage one_texel(Vec3f c) {
    TextureImage image;
    image.width = image.height = 1;
    image.channels = 3;
    image.floats = {c.x, c.y, c.z};
    return image;
}
TextureImage ramp() {
    TextureImage image;
    image.width = 2;
    image.height = 1;
    image.channels = 1;
    image.floats = {0.0f, 1.0f};
    return image;
}

TEST(ShadingFrame, NormalMapImageTiltsTheNormal) {
    const float a = 0.3f;
    TextureSet textures;
    ImageTexture t;
    t.image = textures.add_image(one_texel(encode(Vec3f(std::sin(a), 0.0f, std::cos(a)))));
    Material m = make_diffuse(Rgb(0.5f));
    SurfaceParams s;
    s.normal_map = ColorParam{Rgb(1.0f), textures.add(t), 0.0f, 1.0f};
    set_surface(m, s);
    PlaneHit p;
    expect_near(shading_frame(m, textures, p.g, p.hit).n, Vec3f(std::sin(a), 0, std::cos(a)), 1e-6f);
}

TEST(ShadingFrame, BumpMapOfAnImageRampTiltsByItsSlope) {
    // Height k (u - 1/4) (the ramp, 2 (u - 1/4), scaled by k / 2) on a plane with |dpdu| = 1:
    // slope k, a tilt of atan(k) away from dpdu.
    const float k = 0.05f;
    TextureSet textures;
    ImageTexture t;
    t.image = textures.add_image(ramp());
    t.wrap = TextureWrap::kClamp;
    t.scale = 0.5f * k;
    Material m = make_diffuse(Rgb(0.5f));
    SurfaceParams s;
    s.bump_map = FloatParam{0.0f, textures.add(t)};
    set_surface(m, s);
    PlaneHit p;  // u = 0.3 is on the ramp
    const float angle = std::atan(k);
    expect_near(shading_frame(m, textures, p.g, p.hit).n, Vec3f(-std::sin(angle), 0, std::cos(angle)), 1e-4f);
}

TEST(ShadingFrame, AnisotropicFrameFollowsDpdu) {
    const TextureSet textures;
    Material m = make_diffuse(Rgb(0.5f));
    m.anisotropic = true;
    set_surface(m, SurfaceParams{});
    ASSERT_TRUE(m.needs_shading_geometry);
    PlaneHit p(normalize(Vec3f(1, 1, 0)) * 4.0f, Vec3f(-1, 1, 0));
    const Frame f = shading_frame(m, textures, p.g, p.hit);
    expect_near(f.s, normalize(Vec3f(1, 1, 0)), 1e-6f);
    expect_near(f.t, normalize(Vec3f(-1, 1, 0)), 1e-6f);
    expect_near(f.n, Vec3f(0, 0, 1), 0.0f);
    // Without the flag and maps, nothing asks for the geometry.
    EXPECT_FALSE(make_diffuse(Rgb(0.5f)).needs_shading_geometry);
}

TEST(ShadingFrame, TangentFrameIsOrthonormalOrFallsBack) {
    Rng rng(2, 2);
    for (int i = 0; i < 1000; ++i) {
        const Vec3f n = sample_uniform_sphere(rng.next_vec2f());
        const Vec3f tangent = sample_uniform_sphere(rng.next_vec2f()) * 3.0f;
        const Frame f = Frame::from_normal_and_tangent(n, tangent);
        EXPECT_NEAR(length(f.s), 1.0f, 1e-5f);
        EXPECT_NEAR(length(f.t), 1.0f, 1e-5f);
        EXPECT_NEAR(dot(f.s, f.t), 0.0f, 1e-5f);
        EXPECT_NEAR(dot(f.s, n), 0.0f, 1e-5f);
        expect_near(cross(f.s, f.t), n, 1e-5f);
        EXPECT_GT(dot(f.s, tangent), 0.0f);
    }
    const Vec3f n(0, 0, 1);
    const Frame parallel = Frame::from_normal_and_tangent(n, Vec3f(0, 0, 2));
    const Frame plain = Frame::from_normal(n);
    EXPECT_EQ(parallel.s, plain.s);
    EXPECT_EQ(parallel.t, plain.t);
}

}  // namespace
}  // namespace candela
