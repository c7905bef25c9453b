// Agreement of the estimators (DESIGN.md, "Correctness"): path tracing with MIS, with next-event
// estimation only, and with BSDF sampling only are unbiased estimators of the same image, so their
// renders of one scene must agree within their noise. Each pair is compared per block of pixels
// and channel by z = (m_a - m_b) / sqrt(var_a + var_b), the variances of the block means measured
// from the samples, with Sidak's correction over all blocks, channels and pairs (at the level
// render_moments.h sets: 1% for the whole render label).
// A negative control proves the comparison has the power to see a small bias: the same test
// against one image scaled by 1.05 must reject, broadly (see expect_agreement). A missing cosine
// or a light pdf off by a factor is a far larger error than 5%.
//
// Whitted ray tracing leaves out indirect diffuse light and caustics, so it is compared where
// those are zero: direct light only (path with max_depth = 1), and a scene whose only path
// through a mirror ends in direct light.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "candela/render/renderer.h"
#include "candela/formats/json/scene_loader.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 32;
constexpr int kBlock = 4;

// `s` rendered by `type` with spp samples per pixel (the noisier estimators get more).
Scene with_integrator(Scene s, IntegratorType type, bool mis, int spp) {
    s.integrator.type = type;
    s.integrator.mis = mis;
    s.sampler.spp = spp;
    return s;
}

Scene with_sobol(Scene s) {
    s.sampler.type = SamplerType::kSobol;
    return s;
}

struct Named {
    std::string name;
    test::RenderMoments moments;
};

// Renders the scene with each estimator, a different seed each so the renders are independent.
std::vector<Named> render_estimators(const Scene& base, const std::vector<std::pair<std::string, Scene>>& variants) {
    std::vector<Named> out;
    uint64_t seed = base.sampler.seed;
    for (const auto& [name, scene] : variants) {
        Scene s = scene;
        s.sampler.seed = seed++;
        out.push_back({name, test::render_moments(s)});
        EXPECT_EQ(out.back().moments.dropped, 0u) << name;
    }
    return out;
}

// Compares every pair at once (one Sidak family). Then the negative control: each pair again, with
// the second render scaled by 1.05, must reject, and not only where the light itself is seen (an
// exact, noiseless value) but in at least a quarter of the lit blocks and channels.
void expect_agreement(const std::vector<Named>& renders, const std::string& scene_name) {
    const long pairs = long(renders.size() * (renders.size() - 1) / 2);
    const long tests = pairs * 3 * long(kSize / kBlock) * long(kSize / kBlock);
    const double z_critical = test::sidak_critical_z(test::kRenderTestAlpha, tests);
    bool all_passed = true;
    for (size_t i = 0; i < renders.size(); ++i) {
        for (size_t j = i + 1; j < renders.size(); ++j) {
            const test::RenderMoments &a = renders[i].moments, &b = renders[j].moments;
            const std::string pair_name = renders[i].name + " vs " + renders[j].name;
            test::ZTestFamily pair(z_critical);
            test::compare_renders(a, b, kBlock, pair);
            EXPECT_TRUE(pair.passed()) << pair_name << ": " << pair.summary();
            all_passed = all_passed && pair.passed();

            test::ZTestFamily control(z_critical);
            test::compare_renders(a, b, kBlock, control, 1.05);
            EXPECT_GE(control.rejected(), test::lit_blocks(b, kBlock) / 4)
                << pair_name << " x 1.05 should differ: " << control.summary();
        }
    }
    if (all_passed) return;
    for (const Named& r : renders) test::write_diagnostic(r.moments, scene_name + "_" + r.name);
}

bool bit_identical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

// The harness measures the renderer itself: its means are render()'s image, bit for bit.
TEST(RenderMoments, MeanIsTheRenderersImage) {
    for (SamplerType type : {SamplerType::kIndependent, SamplerType::kSobol}) {
        Scene scene = test::cornell_glass_scene(20, 12, 4);
        scene.film.filter = FilterType::kTent;
        scene.sampler.type = type;
        test::RenderMoments m = test::render_moments(scene, /*for_variance=*/false);
        RenderResult r = render(scene, {.threads = 2});
        EXPECT_TRUE(bit_identical(m.image(), r.image));
        EXPECT_EQ(m.dropped, r.stats.dropped_samples);
    }
}

TEST(EstimatorAgreement, PathNeeAndBsdfAgreeOnCornellBox) {
    Scene base = test::cornell_box_scene(kSize, kSize, /*spp=*/1);  // each estimator sets its own
    expect_agreement(render_estimators(base, {{"path", with_integrator(base, IntegratorType::kPath, true, 2048)},
                                              {"nee", with_integrator(base, IntegratorType::kPath, false, 2048)},
                                              {"bsdf", with_integrator(base, IntegratorType::kBsdf, true, 8192)}}),
                     "cornell");
}

// Sobol sampling (padded, Owen-scrambled) must converge to the same image as independent sampling.
// Its error is measured from 16 independent re-randomizations (render_moments_replicated), the
// only valid variance estimate for dependent samples; the negative control shows the comparison
// can still see a 5% bias.
TEST(EstimatorAgreement, SobolAndIndependentPathAgreeOnCornellBox) {
    Scene base = test::cornell_box_scene(kSize, kSize, /*spp=*/2048);
    Scene sobol = with_sobol(base);
    sobol.sampler.spp = 128;
    sobol.sampler.seed = 1000;
    std::vector<Named> renders;
    renders.push_back({"path", test::render_moments(base)});
    renders.push_back({"path-sobol", test::render_moments_replicated(sobol, 16)});
    for (const Named& r : renders) EXPECT_EQ(r.moments.dropped, 0u) << r.name;
    expect_agreement(renders, "cornell_sobol");
}

TEST(EstimatorAgreement, PathNeeAndBsdfAgreeOnGlassAndMirrorSpheres) {
    // Caustics through the glass ball are found by BSDF sampling alone in all three: more samples.
    Scene base = test::cornell_glass_scene(kSize, kSize, /*spp=*/1);
    expect_agreement(render_estimators(base, {{"path", with_integrator(base, IntegratorType::kPath, true, 4096)},
                                              {"nee", with_integrator(base, IntegratorType::kPath, false, 4096)},
                                              {"bsdf", with_integrator(base, IntegratorType::kBsdf, true, 16384)}}),
                     "glass");
}

// Coated surfaces (pbrt-v4's layered BSDF): next-event estimation uses their eval(), BSDF
// sampling their sample() with pdf() as the MIS density; all three estimators agree only if
// those estimate the same BSDF (materials/layered.h) and pdf() is a fixed function of the
// directions. A rough coat over a diffuse base in a scattering medium, and a nearly smooth coat
// over rough gold.
Scene cornell_coated_scene(int spp) {
    Scene s = test::cornell_walls_scene(kSize, kSize, spp);
    CoatedDiffuseParams diffuse;
    diffuse.albedo = ColorParam{Rgb(0.7f, 0.3f, 0.2f)};
    diffuse.coat.roughness = RoughnessParams{FloatParam{0.2f}, FloatParam{0.2f}};
    diffuse.coat.medium_albedo = ColorParam{Rgb(0.5f)};
    diffuse.coat.thickness = FloatParam{0.3f};
    diffuse.coat.g = FloatParam{0.3f};
    CoatedConductorParams gold;
    gold.coat.roughness = RoughnessParams{FloatParam{0.05f}, FloatParam{0.05f}};
    gold.conductor_eta = ColorParam{Rgb(0.143f, 0.374f, 1.442f)};
    gold.conductor_k = ColorParam{Rgb(3.983f, 2.385f, 1.603f)};
    gold.conductor_roughness = RoughnessParams{FloatParam{0.3f}, FloatParam{0.3f}};
    s.materials.push_back(make_material(diffuse));
    s.materials.push_back(make_material(gold));
    s.material_names.push_back("coated_diffuse");
    s.material_names.push_back("coated_gold");
    test::add_sphere(s, {-0.45, -0.6, 0.35}, 0.4, uint32_t(s.materials.size() - 2));
    test::add_sphere(s, {0.45, -0.6, -0.2}, 0.4, uint32_t(s.materials.size() - 1));
    return s;
}

TEST(EstimatorAgreement, PathNeeAndBsdfAgreeOnCoatedSpheres) {
    Scene base = cornell_coated_scene(/*spp=*/1);
    expect_agreement(render_estimators(base, {{"path", with_integrator(base, IntegratorType::kPath, true, 2048)},
                                              {"nee", with_integrator(base, IntegratorType::kPath, false, 2048)},
                                              {"bsdf", with_integrator(base, IntegratorType::kBsdf, true, 8192)}}),
                     "coated");
}

// On a diffuse scene Whitted computes direct light: path tracing cut after one bounce.
TEST(EstimatorAgreement, WhittedMatchesDirectLightingPath) {
    Scene base = test::cornell_box_scene(kSize, kSize, /*spp=*/1);
    Scene direct = with_integrator(base, IntegratorType::kPath, true, 512);
    direct.integrator.max_depth = 1;
    expect_agreement(render_estimators(base, {{"path_depth1", direct},
                                              {"whitted", with_integrator(base, IntegratorType::kWhitted, true, 512)}}),
                     "direct");
}

// A diffuse ball under a one-sided light, seen directly and in a mirror overhead. Whitted and the
// full path tracer agree because the scene has no light that Whitted leaves out: the ball is convex
// and the mirror lies outside its orthogonal projection onto the mirror's plane, so the ball cannot
// see itself in the mirror (no indirect diffuse light); the mirror lies behind the light's plane,
// so no light reaches the ball through it (no caustic); everything else is open sky.
Scene mirror_scene() {
    Scene s;
    s.materials = {make_diffuse(Rgb(0.7f, 0.5f, 0.3f)), make_mirror(Rgb(0.9f)), make_diffuse(Rgb(0.0f))};
    s.material_names = {"ball", "mirror", "black"};
    test::add_sphere(s, {0, 0, 0}, 1.0, 0);
    uint32_t light = test::add_quad(s, {-1, 2, -1}, {2, 0, 0}, {0, 0, 2}, 2);  // y = 2, faces -y
    test::set_emission(s, light, Rgb(5.0f));
    test::add_quad(s, {1.2f, 2.5f, -2}, {2.8f, 0, 0}, {0, 0, 4}, 1);  // y = 2.5, x in [1.2, 4], faces -y
    // The ball below, the light in the middle, the ball's lit top in the mirror above.
    test::set_camera(s, Vec3f{4, 0.5f, 0}, Vec3f{0, 2, 0}, 80, kSize, kSize);
    s.sampler.seed = 3;
    s.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    return s;
}

TEST(EstimatorAgreement, WhittedMatchesPathThroughMirror) {
    Scene base = mirror_scene();
    expect_agreement(render_estimators(base, {{"path", with_integrator(base, IntegratorType::kPath, true, 4096)},
                                              {"whitted", with_integrator(base, IntegratorType::kWhitted, true,
                                                                          4096)}}),
                     "mirror");
}

// Every material of the version-2 scene format in one scene (rough, anisotropic and multiscatter
// conductors, rough and thin glass, both coated materials, a textured floor) under an area light
// and a spot light: path tracing with MIS and with next-event estimation only must converge to
// the same image. Their weights differ wherever a glossy lobe meets a light (the MIS weight of a
// BSDF sample against the light's density), so a pdf() inconsistent with sample() or eval() in
// any lobe shows here as a bias between the two.
Scene every_material_scene() {
    const std::string json = R"({
      "integrator": {"type": "path", "max_depth": 6},
      "sampler": {"type": "independent", "seed": 11},
      "camera": {"position": [0, 1.2, 4.2], "look_at": [0, 0.7, 0], "fov": 45, "resolution": [32, 32]},
      "textures": {"checks": {"type": "checkerboard", "color0": 0.2, "color1": 0.8, "uv_scale": [6, 6]}},
      "materials": {
        "floor":    {"type": "diffuse", "albedo": {"texture": "checks"}},
        "wall":     {"type": "diffuse", "albedo": [0.6, 0.5, 0.4]},
        "black":    {"type": "diffuse", "albedo": 0},
        "gold":     {"type": "conductor", "metal": "Au", "roughness": 0.2},
        "brushed":  {"type": "conductor", "eta": [0.2, 0.9, 1.1], "k": [3.9, 2.4, 2.1], "roughness": [0.05, 0.4]},
        "white_ms": {"type": "conductor", "reflectance": 0.9, "roughness": 0.6, "multiscatter": true},
        "frosted":  {"type": "dielectric", "ior": 1.5, "roughness": 0.3},
        "pane":     {"type": "thin_dielectric", "ior": 1.5},
        "plastic":  {"type": "coated_diffuse", "albedo": [0.7, 0.2, 0.1], "roughness": 0.1},
        "coated_cu":{"type": "coated_conductor", "interface_roughness": 0.05, "conductor_roughness": 0.3}
      },
      "shapes": [
        {"type": "quad", "corner": [-2, 0, 2], "edge1": [4, 0, 0], "edge2": [0, 0, -4], "material": "floor"},
        {"type": "quad", "corner": [-2, 0, -2], "edge1": [4, 0, 0], "edge2": [0, 3, 0], "material": "wall"},
        {"type": "quad", "corner": [-0.5, 2.5, -0.5], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "material": "black",
         "emission": 6},
        {"type": "sphere", "center": [-1.2, 0.35, -0.6], "radius": 0.35, "material": "gold"},
        {"type": "sphere", "center": [0, 0.35, -0.6], "radius": 0.35, "material": "brushed"},
        {"type": "sphere", "center": [1.2, 0.35, -0.6], "radius": 0.35, "material": "white_ms"},
        {"type": "sphere", "center": [-1.2, 0.35, 0.6], "radius": 0.35, "material": "frosted"},
        {"type": "sphere", "center": [0, 0.35, 0.6], "radius": 0.35, "material": "plastic"},
        {"type": "sphere", "center": [1.2, 0.35, 0.6], "radius": 0.35, "material": "coated_cu"},
        {"type": "quad", "corner": [-0.4, 0.05, 1.4], "edge1": [0.8, 0, 0], "edge2": [0, 0.8, 0], "material": "pane"}
      ],
      "lights": [{"type": "spot", "position": [1.5, 2.5, 2], "look_at": [0, 0.3, 0], "intensity": 8,
                  "cone_angle": 30, "cone_delta": 10}]
    })";
    return load_scene_from_string(json, std::string(CANDELA_SOURCE_DIR) + "/tests/data/scenes/inline.json");
}

TEST(EstimatorAgreement, PathAndNeeAgreeOnEveryNewMaterial) {
    Scene base = every_material_scene();
    expect_agreement(render_estimators(base, {{"path", with_integrator(base, IntegratorType::kPath, true, 2048)},
                                              {"nee", with_integrator(base, IntegratorType::kPath, false, 2048)}}),
                     "materials");
}

}  // namespace
}  // namespace candela
