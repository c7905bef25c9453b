// pbrt-v4's participating media in the importer (issue 24): MakeNamedMedium, MediumInterface, the
// camera's medium, the interface material and the integrator, as candela's JSON document writes
// them (docs/SCENE_FORMAT.md, "media"; docs/PBRT.md). Each case is checked against what pbrt-v4
// does with it (src/pbrt/scene.cpp, media.cpp, cpu/integrators.cpp at 5f7a6068).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"
#include "formats/pbrt/pbrt_import_text.h"

namespace candela::pbrt {
namespace CANDELA_UNITY_ID {

using Json = nlohmann::ordered_json;

const std::filesystem::path& kFile = test::kInlineFile;
using test::import;
std::string error_of(const std::string& text) { return test::import_error(text); }

bool has_warning(const ImportedScene& s, const std::string& part) {
    for (const std::string& w : s.warnings)
        if (w.find(part) != std::string::npos) return true;
    return false;
}

std::string all_warnings(const ImportedScene& s) {
    std::string out;
    for (const std::string& w : s.warnings) out += w + "\n";
    return out;
}

const char* kLight = "LightSource \"point\" \"rgb I\" [1 1 1]\n";

TEST(PbrtMedia, HomogeneousMediumTakesPbrtsParametersUnderCandelasNames) {
    const ImportedScene s = import(std::string("MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" "
                                               "\"rgb sigma_a\" [0.1 0.2 0.3] \"spectrum sigma_s\" [400 1 700 2] "
                                               "\"float scale\" 2 \"float g\" 0.5 \"blackbody Le\" 3000 "
                                               "\"float Lescale\" 4\nWorldBegin\n") +
                                   kLight);
    EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
    const Json& fog = s.document["media"]["fog"];
    EXPECT_EQ(fog["type"], "homogeneous");
    EXPECT_EQ(fog["sigma_a"], Json::array({0.1, 0.2, 0.3}));
    EXPECT_EQ(fog["sigma_s"], Json({{"spectrum", Json::array({400.0, 1.0, 700.0, 2.0})}}));
    EXPECT_EQ(fog["scale"], 2.0);
    EXPECT_EQ(fog["g"], 0.5);
    EXPECT_EQ(fog["Le"], Json({{"blackbody", 3000.0}}));
    EXPECT_EQ(fog["Le_scale"], 4.0);
    EXPECT_FALSE(fog.contains("transform"));  // identity
    // pbrt-v4's defaults (sigma_a = sigma_s = 1, scale 1, g 0, no emission) are the loader's.
    const ImportedScene d =
        import(std::string("MakeNamedMedium \"m\" \"string type\" \"homogeneous\"\nWorldBegin\n") + kLight);
    EXPECT_EQ(d.document["media"]["m"], Json({{"type", "homogeneous"}}));
}

TEST(PbrtMedia, APresetReplacesSigmaAAndSigmaS) {
    // pbrt-v4 reads sigma_a and sigma_s only where the preset is not found: next to a preset
    // they are unused parameters.
    const ImportedScene s = import(std::string("MakeNamedMedium \"milk\" \"string type\" \"homogeneous\" "
                                               "\"string preset\" \"Wholemilk\" \"float scale\" 0.1 "
                                               "\"rgb sigma_a\" [1 1 1]\nWorldBegin\n") +
                                   kLight);
    const Json& milk = s.document["media"]["milk"];
    EXPECT_EQ(milk["preset"], "Wholemilk");
    EXPECT_FALSE(milk.contains("sigma_a"));
    EXPECT_EQ(milk["scale"], 0.1);
    EXPECT_TRUE(has_warning(s, "inline.pbrt:1:98: MakeNamedMedium \"milk\": parameter \"rgb sigma_a\" is not used"))
        << all_warnings(s);
    // A preset pbrt-v4 does not know: it warns and takes sigma_a and sigma_s.
    const ImportedScene u = import(std::string("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" "
                                               "\"string preset\" \"Yoghurt\" \"rgb sigma_a\" [1 2 3]\nWorldBegin\n") +
                                   kLight);
    EXPECT_EQ(u.document["media"]["m"], Json({{"type", "homogeneous"}, {"sigma_a", Json::array({1.0, 2.0, 3.0})}}));
    EXPECT_TRUE(has_warning(u, "inline.pbrt:1:49: MakeNamedMedium \"m\": preset \"Yoghurt\" not found"))
        << all_warnings(u);
}

TEST(PbrtMedia, TheMediumsTransformIsTheOneCurrentAtTheDirective) {
    const ImportedScene s = import(std::string("WorldBegin\n") + kLight +
                                   "AttributeBegin Translate 1 2 3 Scale 2 2 2\n"
                                   "MakeNamedMedium \"g\" \"string type\" \"uniformgrid\" \"float density\" [1]\n"
                                   "AttributeEnd\n");
    const Json& m = s.document["media"]["g"]["transform"][0]["matrix"];
    // Rows: [2 0 0 1; 0 2 0 2; 0 0 2 3; 0 0 0 1].
    EXPECT_EQ(m, Json::array({2.0, 0.0, 0.0, 1.0, 0.0, 2.0, 0.0, 2.0, 0.0, 0.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0}));
    // Before WorldBegin the current transformation is the camera's (pbrt-v4 keeps it so).
    const ImportedScene c = import(std::string("Translate 0 0 5\nCamera \"perspective\"\n"
                                               "MakeNamedMedium \"h\" \"string type\" \"homogeneous\"\nWorldBegin\n") +
                                   kLight);
    EXPECT_EQ(c.document["media"]["h"]["transform"][0]["matrix"][11], 5.0);
}

TEST(PbrtMedia, UniformGridWithTemperature) {
    const ImportedScene s = import(std::string("WorldBegin\n") + kLight +
                                   "MakeNamedMedium \"smoke\" \"string type\" \"uniformgrid\" \"integer nx\" 2 "
                                   "\"integer ny\" 1 \"integer nz\" 1 \"float density\" [0.5 1] "
                                   "\"float temperature\" [1500 2500] \"float temperaturecutoff\" 400 "
                                   "\"float temperaturescale\" 2 \"float Lescale\" [3 4] \"point3 p0\" [-1 -1 -1] "
                                   "\"point3 p1\" [1 1 1] \"rgb sigma_a\" [1 2 3] \"float sigma_s\" 0.5 "
                                   "\"float scale\" 3 \"float g\" -0.5\n");
    EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
    const Json& m = s.document["media"]["smoke"];
    EXPECT_EQ(m["type"], "uniformgrid");
    EXPECT_EQ(m["size"], Json::array({2, 1, 1}));
    EXPECT_EQ(m["density"], Json::array({0.5, 1.0}));
    EXPECT_EQ(m["temperature"], Json::array({1500.0, 2500.0}));
    // pbrt-v4: temperatureoffset, defaulting to temperaturecutoff (its older name).
    EXPECT_EQ(m["temperature_offset"], 400.0);
    EXPECT_FALSE(m.contains("temperature_cutoff"));
    EXPECT_EQ(m["temperature_scale"], 2.0);
    EXPECT_EQ(m["Le_scale"], Json::array({3.0, 4.0}));
    EXPECT_EQ(m["p0"], Json::array({-1.0, -1.0, -1.0}));
    EXPECT_EQ(m["p1"], Json::array({1.0, 1.0, 1.0}));
    EXPECT_EQ(m["sigma_a"], Json::array({1.0, 2.0, 3.0}));
    EXPECT_EQ(m["sigma_s"], 0.5);
    EXPECT_EQ(m["scale"], 3.0);
    EXPECT_EQ(m["g"], -0.5);
    // temperatureoffset wins over temperaturecutoff; Le instead of a temperature; Lescale is an
    // array even for a grid of one voxel (pbrt-v4's grid of it is no constant).
    const ImportedScene o = import(std::string("WorldBegin\n") + kLight +
                                   "MakeNamedMedium \"g\" \"string type\" \"uniformgrid\" \"float density\" [2] "
                                   "\"float temperatureoffset\" 10 \"float temperaturecutoff\" 400 \"rgb Le\" [1 0 0] "
                                   "\"float Lescale\" 5\n");
    EXPECT_TRUE(o.warnings.empty()) << all_warnings(o);
    const Json& g = o.document["media"]["g"];
    EXPECT_EQ(g["temperature_offset"], 10.0);
    EXPECT_EQ(g["Le"], Json::array({1.0, 0.0, 0.0}));
    EXPECT_EQ(g["Le_scale"], Json::array({5.0}));
    EXPECT_EQ(g["size"], Json::array({1, 1, 1}));
}

TEST(PbrtMedia, RgbGridCloudAndNanoVdb) {
    const ImportedScene s =
        import(std::string("WorldBegin\n") + kLight +
               "MakeNamedMedium \"c\" \"string type\" \"rgbgrid\" \"integer nx\" 2 \"rgb sigma_a\" [1 2 3 4 5 6] "
               "\"rgb sigma_s\" [0 1 0 1 0 1] \"rgb Le\" [0 0 0 9 8 7] \"float Lescale\" 2 \"float scale\" 0.5 "
               "\"float g\" 0.1 \"point3 p1\" [2 2 2]\n"
               "MakeNamedMedium \"sky\" \"string type\" \"cloud\" \"float density\" 3 \"float wispiness\" 0.5 "
               "\"float frequency\" 7 \"rgb sigma_a\" [0.1 0.1 0.1] \"float g\" 0.7 \"point3 p0\" [-1 0 -1]\n"
               "MakeNamedMedium \"vdb\" \"string type\" \"nanovdb\" \"string filename\" \"volumes/smoke.nvdb\" "
               "\"string gridname\" \"dens\" \"string temperaturename\" \"heat\" \"float Lescale\" 0.25 "
               "\"float temperatureoffset\" 100 \"float temperaturescale\" 1000 \"rgb sigma_s\" [2 2 2] "
               "\"float scale\" 4 \"float g\" 0.2\n");
    EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
    const Json& media = s.document["media"];
    const Json& c = media["c"];
    EXPECT_EQ(c["type"], "rgbgrid");
    EXPECT_EQ(c["size"], Json::array({2, 1, 1}));
    EXPECT_EQ(c["sigma_a"], Json::array({1.0, 2.0, 3.0, 4.0, 5.0, 6.0}));
    EXPECT_EQ(c["sigma_s"], Json::array({0.0, 1.0, 0.0, 1.0, 0.0, 1.0}));
    EXPECT_EQ(c["Le"], Json::array({0.0, 0.0, 0.0, 9.0, 8.0, 7.0}));
    EXPECT_EQ(c["Le_scale"], 2.0);
    EXPECT_EQ(c["scale"], 0.5);
    EXPECT_EQ(c["g"], 0.1);
    EXPECT_EQ(c["p1"], Json::array({2.0, 2.0, 2.0}));
    EXPECT_EQ(media["sky"], Json({{"type", "cloud"},
                                  {"density", 3.0},
                                  {"wispiness", 0.5},
                                  {"frequency", 7.0},
                                  {"sigma_a", Json::array({0.1, 0.1, 0.1})},
                                  {"g", 0.7},
                                  {"p0", Json::array({-1.0, 0.0, -1.0})}}));
    EXPECT_EQ(media["vdb"], Json({{"type", "nanovdb"},
                                  {"file", "volumes/smoke.nvdb"},
                                  {"grid_name", "dens"},
                                  {"temperature_name", "heat"},
                                  {"Le_scale", 0.25},
                                  {"temperature_offset", 100.0},
                                  {"temperature_scale", 1000.0},
                                  {"sigma_s", Json::array({2.0, 2.0, 2.0})},
                                  {"scale", 4.0},
                                  {"g", 0.2}}));
}

TEST(PbrtMedia, MediumAttributesAreDefaults) {
    const ImportedScene s = import(std::string("WorldBegin\n") + kLight +
                                   "Attribute \"medium\" \"float g\" 0.8 \"float scale\" 2\n"
                                   "MakeNamedMedium \"a\" \"string type\" \"homogeneous\" \"float scale\" 5\n");
    EXPECT_EQ(s.document["media"]["a"]["g"], 0.8);
    EXPECT_EQ(s.document["media"]["a"]["scale"], 5.0);
}

TEST(PbrtMedia, ShapesGetTheirMediaWhereTheyDiffer) {
    const ImportedScene s = import(std::string("MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
                                               "MakeNamedMedium \"glass\" \"string type\" \"homogeneous\"\n"
                                               "WorldBegin\n") +
                                   kLight +
                                   "AttributeBegin MediumInterface \"glass\" \"fog\" Material \"dielectric\"\n"
                                   "Shape \"sphere\"\n"
                                   "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0]\n"
                                   "AttributeEnd\n"
                                   "Shape \"sphere\" \"float radius\" 2\n"
                                   "MediumInterface \"fog\"\nShape \"sphere\" \"float radius\" 3\n"
                                   "MediumInterface \"\" \"fog\"\nShape \"sphere\" \"float radius\" 4\n");
    EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
    const Json& shapes = s.document["shapes"];
    ASSERT_EQ(shapes.size(), 5u);
    for (int i : {0, 1}) {
        EXPECT_EQ(shapes[i]["interior"], "glass");
        EXPECT_EQ(shapes[i]["exterior"], "fog");
    }
    // No MediumInterface: no keys (pbrt-v4: no medium either side).
    EXPECT_FALSE(shapes[2].contains("interior"));
    EXPECT_FALSE(shapes[2].contains("exterior"));
    // One name is both sides: pbrt-v4 makes that no boundary (a ray keeps its medium): no keys.
    EXPECT_FALSE(shapes[3].contains("interior"));
    EXPECT_FALSE(shapes[3].contains("exterior"));
    // "" is no medium, written as such.
    EXPECT_EQ(shapes[4]["interior"], "");
    EXPECT_EQ(shapes[4]["exterior"], "fog");
    // The media section comes before the camera (the document's order is the loader's).
    std::vector<std::string> keys;
    for (const auto& [k, v] : s.document.items()) keys.push_back(k);
    EXPECT_EQ(keys[2], "media");
}

TEST(PbrtMedia, TheMediumInterfaceOutlivesWorldBegin) {
    // pbrt-v4's WorldBegin resets the transformation only: a MediumInterface given for the camera
    // still holds for the shapes and lights that follow.
    const ImportedScene s = import(std::string("MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
                                               "MediumInterface \"\" \"fog\"\nCamera \"perspective\"\nWorldBegin\n") +
                                   kLight + "Shape \"sphere\"\n");
    EXPECT_EQ(s.document["camera"]["medium"], "fog");
    EXPECT_EQ(s.document["shapes"][0]["interior"], "");
    EXPECT_EQ(s.document["shapes"][0]["exterior"], "fog");
}

TEST(PbrtMedia, ObjectShapesKeepTheirMediaAndTexturedSpheresCarryThemIntoTheirObject) {
    const ImportedScene s = import(std::string("MakeNamedMedium \"in\" \"string type\" \"homogeneous\"\n"
                                               "WorldBegin\n") +
                                   kLight +
                                   "ObjectBegin \"ball\" MediumInterface \"in\" \"\" Material \"interface\"\n"
                                   "Shape \"sphere\"\nObjectEnd\n"
                                   "ObjectInstance \"ball\"\n"
                                   "Texture \"t\" \"spectrum\" \"checkerboard\"\n"
                                   "Material \"diffuse\" \"texture reflectance\" \"t\"\n"
                                   "MediumInterface \"in\" \"\"\nShape \"sphere\"\n");
    const Json& objects = s.document["objects"];
    const Json& ball = objects["ball"]["shapes"][0];
    EXPECT_EQ(ball["interior"], "in");
    EXPECT_EQ(ball["exterior"], "");
    EXPECT_EQ(s.document["materials"][ball["material"].get<std::string>()]["type"], "interface");
    // The textured sphere is an instance of a sphere in pbrt's frame: its media go on that sphere.
    const Json& placed = s.document["shapes"][1];
    ASSERT_EQ(placed["type"], "instance");
    const Json& inner = objects[placed["object"].get<std::string>()]["shapes"][0];
    EXPECT_EQ(inner["interior"], "in");
    EXPECT_EQ(inner["exterior"], "");
}

TEST(PbrtMedia, TheCameraTakesTheOutsideMediumCurrentAtCamera) {
    const ImportedScene s = import(std::string("MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
                                               "MediumInterface \"ignored\" \"fog\"\nCamera \"perspective\"\n"
                                               "MediumInterface \"\"\nWorldBegin\n") +
                                   kLight);
    EXPECT_EQ(s.document["camera"]["medium"], "fog");
    const ImportedScene none = import(std::string("WorldBegin\n") + kLight);
    EXPECT_FALSE(none.document["camera"].contains("medium"));
    // pbrt-v4 looks the camera's medium up as the world begins.
    const std::string e = error_of(
        "MediumInterface \"fog\"\nCamera \"perspective\"\nWorldBegin\n"
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n");
    EXPECT_NE(e.find("inline.pbrt:2:1: Camera: medium \"fog\" is not defined"), std::string::npos) << e;
}

TEST(PbrtMedia, InterfaceMaterialAndItsAreaLightsAsPbrtV4) {
    const ImportedScene s = import(std::string("WorldBegin\n") + kLight +
                                   "MakeNamedMaterial \"a\" \"string type\" \"interface\"\n"
                                   "MakeNamedMaterial \"b\" \"string type\" \"none\"\n"
                                   "Material \"interface\"\n"
                                   "AttributeBegin AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                                   "Shape \"sphere\" \"float alpha\" 0.5\nAttributeEnd\n");
    const Json& m = s.document["materials"];
    EXPECT_EQ(m["a"], Json({{"type", "interface"}}));
    EXPECT_EQ(m["b"], Json({{"type", "interface"}}));
    // pbrt-v4 makes no light of a shape without a material (scene.cpp, CreateLights) ...
    const Json& shape = s.document["shapes"][0];
    EXPECT_FALSE(shape.contains("emission"));
    EXPECT_TRUE(has_warning(s, "inline.pbrt:6:16: AreaLightSource on a shape of material \"interface\""))
        << all_warnings(s);
    // ... and candela's interface takes no alpha.
    EXPECT_EQ(m[shape["material"].get<std::string>()], Json({{"type", "interface"}}));
    EXPECT_TRUE(has_warning(s, "inline.pbrt:7:16: alpha on a shape of material \"interface\"")) << all_warnings(s);
}

TEST(PbrtMedia, TheIntegratorIsVolpathWherePbrtV4RendersMedia) {
    const std::string medium = "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n";
    const std::string used = "MediumInterface \"fog\" \"\"\nShape \"sphere\"\n";
    // pbrt-v4's default integrator is volpath: volpath where the scene has media, else path
    // (the same image without media).
    EXPECT_EQ(import(std::string("WorldBegin\n") + kLight).document["integrator"]["type"], "path");
    EXPECT_EQ(import(medium + "WorldBegin\n" + kLight).document["integrator"]["type"], "volpath");
    // A file without WorldBegin has its options all the same.
    EXPECT_EQ(import(medium).document["integrator"]["type"], "volpath");
    const ImportedScene v =
        import("Integrator \"volpath\" \"integer maxdepth\" 12\nWorldBegin\n" + std::string(kLight));
    EXPECT_EQ(v.document["integrator"]["type"], "volpath");
    EXPECT_EQ(v.document["integrator"]["max_depth"], 12);
    EXPECT_TRUE(v.warnings.empty()) << all_warnings(v);
    const ImportedScene sv = import("Integrator \"simplevolpath\"\n" + medium + "WorldBegin\n" + kLight);
    EXPECT_EQ(sv.document["integrator"]["type"], "volpath");
    EXPECT_TRUE(has_warning(sv, "inline.pbrt:1:1: Integrator \"simplevolpath\": rendered with candela's volpath"));
    // bdpt renders media as volpath does.
    EXPECT_EQ(import("Integrator \"bdpt\"\n" + medium + "WorldBegin\n" + kLight).document["integrator"]["type"],
              "volpath");
    EXPECT_EQ(import("Integrator \"bdpt\"\nWorldBegin\n" + std::string(kLight)).document["integrator"]["type"], "path");
    // pbrt-v4's path ignores media and says so; the importer keeps path, the loader warns.
    const ImportedScene p = import("Integrator \"path\"\n" + medium + "WorldBegin\n" + kLight + used);
    EXPECT_EQ(p.document["integrator"]["type"], "path");
    bool warned = false;
    for (const std::string& w : load_imported_scene(p, kFile).warnings)
        warned = warned || w.find("the path integrator ignores them") != std::string::npos;
    EXPECT_TRUE(warned);
    // No media at all: no "media" section.
    EXPECT_FALSE(import(std::string("WorldBegin\n") + kLight).document.contains("media"));
}

TEST(PbrtMedia, ErrorsAreLocatedAsPbrtV4Stops) {
    auto expect_error = [](const std::string& text, const std::string& part) {
        const std::string e = error_of(text);
        EXPECT_NE(e.find(part), std::string::npos) << "got: " << e;
    };
    expect_error("WorldBegin\n\nMakeNamedMedium \"m\" \"string type\" \"fluffy\"\n",
                 "inline.pbrt:3:21: MakeNamedMedium \"m\": unknown medium type \"fluffy\"");
    expect_error("WorldBegin\nMakeNamedMedium \"m\" \"float g\" 0\n",
                 "inline.pbrt:2:1: MakeNamedMedium \"m\": \"string type\" is required");
    expect_error(
        "MakeNamedMedium \"m\" \"string type\" \"homogeneous\"\n"
        "MakeNamedMedium \"m\" \"string type\" \"homogeneous\"\n",
        "inline.pbrt:2:1: MakeNamedMedium: medium \"m\" is defined twice (first at ");
    // Shapes' media are looked up once the file is read: later is fine, never is an error.
    EXPECT_EQ(error_of("WorldBegin\nMediumInterface \"m\" \"\"\nShape \"sphere\"\n"
                       "MakeNamedMedium \"m\" \"string type\" \"homogeneous\"\n"),
              "no error");
    expect_error("WorldBegin\nMediumInterface \"m\" \"\"\n\nShape \"sphere\"\n",
                 "inline.pbrt:4:1: Shape: medium \"m\" is not defined");
    // A light's (outside) medium is looked up at the light.
    expect_error("WorldBegin\nMediumInterface \"\" \"m\"\nLightSource \"point\"\n",
                 "inline.pbrt:3:1: LightSource: medium \"m\" is not defined");
    // Grids: pbrt-v4's checks.
    expect_error("WorldBegin\nMakeNamedMedium \"g\" \"string type\" \"uniformgrid\" \"integer nx\" 2\n",
                 "inline.pbrt:2:1: uniformgrid: no \"float density\" values");
    expect_error(
        "WorldBegin\nMakeNamedMedium \"g\" \"string type\" \"uniformgrid\" \"integer nx\" 2 "
        "\"float density\" [1 2 3]\n",
        "the grid has 3 density values; expected nx*ny*nz = 2*1*1 = 2");
    expect_error(
        "WorldBegin\nMakeNamedMedium \"g\" \"string type\" \"uniformgrid\" \"float density\" [1] "
        "\"float temperature\" [1] \"rgb Le\" [1 1 1]\n",
        "uniformgrid: both \"Le\" and \"temperature\" are given");
    expect_error(
        "WorldBegin\nMakeNamedMedium \"g\" \"string type\" \"uniformgrid\" \"float density\" [1 2] "
        "\"integer nx\" 2 \"float Lescale\" [1 2 3]\n",
        "\"Lescale\" has 3 values; expected one per voxel, 2");
    expect_error(
        "WorldBegin\nMakeNamedMedium \"g\" \"string type\" \"rgbgrid\" \"rgb Le\" [1 1 1] "
        "\"rgb sigma_s\" [1 1 1]\n",
        "rgbgrid: \"Le\" needs \"sigma_a\"");
    expect_error("WorldBegin\nMakeNamedMedium \"g\" \"string type\" \"rgbgrid\" \"float sigma_a\" [1 1 1]\n",
                 "\"sigma_a\" must be \"rgb sigma_a\" values, not float");
    expect_error("WorldBegin\nMakeNamedMedium \"g\" \"string type\" \"nanovdb\"\n",
                 "inline.pbrt:2:1: nanovdb: \"string filename\" is required");
    expect_error("WorldBegin\nMakeNamedMedium \"h\" \"string type\" \"homogeneous\" \"texture sigma_a\" \"t\"\n",
                 "inline.pbrt:2:49: MakeNamedMedium \"h\": \"sigma_a\" cannot be a texture");
}

TEST(PbrtMedia, UnknownParametersAreWarnedAtTheirPlace) {
    const ImportedScene s = import(std::string("WorldBegin\n") + kLight +
                                   "MakeNamedMedium \"c\" \"string type\" \"cloud\" \"float scale\" 2\n");
    // pbrt-v4's cloud has no "scale" (pbrt-v4 stops on an unused parameter; candela warns).
    EXPECT_TRUE(has_warning(s, "inline.pbrt:3:43: MakeNamedMedium \"c\": parameter \"float scale\" is not used"))
        << all_warnings(s);
}

}  // namespace
}  // namespace candela::pbrt
