#include "candela/formats/pbrt/pbrt_parser.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_null_target.h"
#include "recording_target.h"
#include "support/fixtures.h"

namespace candela::pbrt {
namespace CANDELA_UNITY_ID {

using test::RecordingTarget;

RecordingTarget parse(const std::string& text, const ParseOptions& options = {}) {
    RecordingTarget target;
    parse_string(text, "s.pbrt", target, options);
    EXPECT_TRUE(target.ended);
    return target;
}

std::string error_of(const std::string& text) {
    RecordingTarget target;
    try {
        parse_string(text, "s.pbrt", target);
    } catch (const SceneError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected a SceneError for " << text;
    return "";
}

testing::AssertionResult starts_with(const std::string& text, const std::string& prefix) {
    if (text.compare(0, prefix.size(), prefix) == 0) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "\"" << text << "\" does not start with \"" << prefix << "\"";
}

TEST(PbrtParser, EveryDirectiveReachesTheTarget) {
    RecordingTarget target;
    parse_string(candela::test::read_fixture("pbrt/every_directive.pbrt"), "every_directive.pbrt", target);
    const std::vector<std::string> expected{
        "Option disablepixeljitter {bool disablepixeljitter: true} @3:1",
        "Option seed {integer seed: 7} @4:1",
        "ColorSpace srgb @5:1",
        "LookAt 0 1 -5 0 0 0 0 1 0 @6:1",
        "Camera perspective {float fov: 45} @7:1",
        "Film rgb {integer xresolution: 64} {integer yresolution: 48} {string filename: \"out.exr\"} @8:1",
        "PixelFilter gaussian @9:1",
        "Sampler zsobol {integer pixelsamples: 16} @10:1",
        "Integrator volpath {integer maxdepth: 5} @11:1",
        "Accelerator bvh @12:1",
        "TransformTimes 0 1 @13:1",
        "ActiveTransform StartTime @14:1",
        "ActiveTransform EndTime @15:1",
        "ActiveTransform All @16:1",
        "MakeNamedMedium fog {string type: \"homogeneous\"} {spectrum sigma_a: 400 0.5 700 0.25} @17:1",
        "MediumInterface \"\" \"fog\" @18:1",
        "MediumInterface \"fog\" \"fog\" @19:1",
        "WorldBegin @20:1",
        "Attribute shape {float radius: 0.5} @21:1",
        "AttributeBegin @22:1",
        "Identity @23:3",
        "Translate 1 2 3 @24:3",
        "Scale 2 2 2 @25:3",
        "Rotate 90 0 0 1 @26:3",
        "Transform 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 @27:3",
        "ConcatTransform 1 0 0 0 0 1 0 0 0 0 1 0 4 5 6 1 @28:3",
        "CoordinateSystem mine @29:3",
        "CoordSysTransform camera @30:3",
        "ReverseOrientation @31:3",
        "AttributeEnd @32:1",
        "AttributeBegin @33:1",
        "AttributeEnd @34:1",
        "Texture checks spectrum checkerboard {float uscale: 8} {rgb tex1: 1 1 1} {rgb tex2: 0 0 0} @35:1",
        "Material diffuse {texture reflectance: \"checks\"} @36:1",
        "MakeNamedMaterial gold {string type: \"conductor\"} {spectrum eta: \"metal-Au-eta\"} {spectrum k: "
        "\"metal-Au-k\"} @37:1",
        "NamedMaterial gold @38:1",
        "LightSource distant {blackbody L: 5500} {point3 from: 0 0 0} {point3 to: 0 0 1} @39:1",
        "AreaLightSource diffuse {rgb L: 4 4 4} {bool twosided: false} @40:1",
        "Shape trianglemesh {point3 P: 0 0 0 1 0 0 0 1 0} {integer indices: 0 1 2} {normal N: 0 0 1 0 0 1 0 0 1} "
        "{point2 uv: 0 0 1 0 0 1} @41:1",
        "ObjectBegin tree @43:1",
        "Shape sphere @44:3",
        "ObjectEnd @45:1",
        "ObjectInstance tree @46:1",
    };
    EXPECT_EQ(target.log, expected);
    // TransformBegin/End are read as attributes, with one warning; WorldEnd is ignored, with one.
    EXPECT_EQ(target.warnings,
              std::vector<std::string>(
                  {"every_directive.pbrt:33:1: TransformBegin/TransformEnd are deprecated in pbrt-v4; read as "
                   "AttributeBegin/AttributeEnd",
                   "every_directive.pbrt:47:1: WorldEnd is pbrt-v3's and means nothing in pbrt-v4; ignored"}));
    EXPECT_TRUE(target.ended);
}

// Any chunk size gives the same calls at the same places: tokens straddle the chunks.
TEST(PbrtParser, ChunkSizeChangesNothing) {
    const std::string text = candela::test::read_fixture("pbrt/every_directive.pbrt");
    const std::vector<std::string> whole = parse(text).log;
    for (size_t chunk : {1, 2, 3, 5, 7, 11, 16, 64, 1000}) {
        ParseOptions options;
        options.chunk_size = chunk;
        EXPECT_EQ(parse(text, options).log, whole) << chunk;
    }
}

TEST(PbrtParser, ParametersKeepTheirLocations) {
    const RecordingTarget t = parse("\n  Film \"rgb\" \"integer xresolution\" [ 64 ]\r\n\t\"integer yresolution\" 48");
    ASSERT_EQ(t.parameter_lists.size(), 1u);
    const ParameterList& p = t.parameter_lists[0];
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0].location.line, 2);
    EXPECT_EQ(p[0].location.column, 14);
    EXPECT_EQ(p[1].location.line, 3);
    EXPECT_EQ(p[1].location.column, 2);  // a tab is one byte
    EXPECT_EQ(p[1].location.file, "s.pbrt");
    EXPECT_EQ(t.locations[0].line, 2);
    EXPECT_EQ(t.locations[0].column, 3);
    EXPECT_FALSE(p[0].used);
}

TEST(PbrtParser, EveryParameterTypeHoldsItsValues) {
    const RecordingTarget t = parse(
        "Shape \"x\" \"integer a\" [ -3 +4 2147483647 -2147483648 ] \"float b\" [ 1.5 -2e-3 +.25 1e-999 ]"
        " \"point2 c\" [ 1 2 ] \"vector2 d\" [ 3 4 ] \"point3 e\" [ 1 2 3 ] \"vector3 f\" [ 4 5 6 ]"
        " \"normal g\" [ 0 0 1 ] \"normal3 h\" [ 0 1 0 ] \"point i\" [ 7 8 9 ] \"vector j\" [ 1 1 1 ]"
        " \"color k\" [ .1 .2 .3 ] \"rgb l\" [ .4 .5 .6 ] \"blackbody m\" 6500"
        " \"spectrum n\" [ 300 .3 800 .8 ] \"spectrum o\" \"glass-BK7\" \"spectrum p\" [ \"data/my.spd\" ]"
        " \"bool q\" [ true false ] \"bool r\" \"true\" \"bool s\" [ \"false\" true ]"
        " \"string t\" [ \"a\" \"b\" ] \"texture u\" \"checks\" \"float v\" []");
    ASSERT_EQ(t.log.size(), 1u);
    EXPECT_EQ(t.log[0],
              "Shape x {integer a: -3 4 2147483647 -2147483648} {float b: 1.5 -0.002 0.25 0} {point2 c: 1 2}"
              " {vector2 d: 3 4} {point3 e: 1 2 3} {vector3 f: 4 5 6} {normal g: 0 0 1} {normal3 h: 0 1 0}"
              " {point i: 7 8 9} {vector j: 1 1 1} {color k: 0.1 0.2 0.3} {rgb l: 0.4 0.5 0.6} {blackbody m: 6500}"
              " {spectrum n: 300 0.3 800 0.8} {spectrum o: \"glass-BK7\"} {spectrum p: \"data/my.spd\"}"
              " {bool q: true false} {bool r: true} {bool s: false true} {string t: \"a\" \"b\"}"
              " {texture u: \"checks\"} {float v:} @1:1");
}

TEST(PbrtParser, BareValuesAreOneValueLists) {
    const RecordingTarget t =
        parse("Shape \"x\" \"float r\" 2 \"string s\" \"a b\" \"bool c\" false \"rgb k\" [ 1 2 3 ] \"integer n\" 5");
    EXPECT_EQ(t.log[0], "Shape x {float r: 2} {string s: \"a b\"} {bool c: false} {rgb k: 1 2 3} {integer n: 5} @1:1");
}

TEST(PbrtParser, OptionsTakeTheirTypeFromTheValueUnlessDeclared) {
    const RecordingTarget t = parse(
        "Option \"a\" true Option \"b\" 3 Option \"c\" \"x\" Option \"string d\" \"y\""
        " Option \"float e\" [ 2 ]");
    EXPECT_EQ(t.log, std::vector<std::string>({"Option a {bool a: true} @1:1", "Option b {float b: 3} @1:17",
                                               "Option c {string c: \"x\"} @1:30", "Option d {string d: \"y\"} @1:45",
                                               "Option e {float e: 2} @1:67"}));
}

TEST(PbrtParser, TransformsTakeSixteenNumbersWithOrWithoutBrackets) {
    const RecordingTarget t = parse(
        "Transform 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\nConcatTransform [1 2 3 4 5 6 7 8 9 10 "
        "11 12 13 14 15 16]");
    EXPECT_EQ(t.log, std::vector<std::string>({"Transform 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 @1:1",
                                               "ConcatTransform 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 @2:1"}));
}

TEST(PbrtParser, TransformBeginWarnsOnce) {
    const RecordingTarget t = parse("TransformBegin TransformEnd TransformBegin TransformEnd");
    EXPECT_EQ(t.log.size(), 4u);
    EXPECT_EQ(t.warnings.size(), 1u);
}

// The parser only forwards AttributeBegin: a million nested ones cost no stack.
TEST(PbrtParser, AMillionNestedAttributesAreForwarded) {
    struct Counter : NullTarget {
        int begins = 0;
        void attribute_begin(const Location&) override { ++begins; }
    } counter;
    std::string text;
    for (int i = 0; i < 1000000; ++i) text += "AttributeBegin\n";
    parse_string(text, "deep.pbrt", counter);
    EXPECT_EQ(counter.begins, 1000000);
}

TEST(PbrtParser, NumbersOutOfRangeOrNotFiniteAreErrorsAtTheNumber) {
    EXPECT_EQ(error_of("Translate 1 1e999 2"), "s.pbrt:1:13: Translate: \"1e999\" is beyond the range of a double");
    EXPECT_EQ(error_of("Shape \"x\" \"float r\" -1e999"),
              "s.pbrt:1:21: \"float r\": \"-1e999\" is beyond the range of a double");
    EXPECT_EQ(error_of("Shape \"x\" \"float r\" [ 1 nan ]"),
              "s.pbrt:1:25: \"float r\": expected a finite number, got \"nan\"");
    EXPECT_EQ(error_of("Scale inf 1 1"), "s.pbrt:1:7: Scale: expected a finite number, got \"inf\"");
    EXPECT_EQ(error_of("Scale 1 -infinity 1"), "s.pbrt:1:9: Scale: expected a finite number, got \"-infinity\"");
    EXPECT_EQ(error_of("Scale 1 1 1.5x"), "s.pbrt:1:11: Scale: expected a number, got \"1.5x\"");
    EXPECT_EQ(error_of("Scale 1 1 --1"), "s.pbrt:1:11: Scale: expected a number, got \"--1\"");
    EXPECT_EQ(error_of("Scale 1 1 +"), "s.pbrt:1:11: Scale: expected a number, got \"+\"");
    EXPECT_EQ(parse("Scale 1e-999 +2 -0").log[0], "Scale 0 2 -0 @1:1");
}

TEST(PbrtParser, ValuesMustFitTheirType) {
    EXPECT_EQ(error_of("Shape \"sphere\" \"float radius\" \"big\""),
              "s.pbrt:1:31: \"float radius\": expected a number, got the string \"big\"");
    EXPECT_EQ(error_of("Shape \"sphere\" \"float radius\" true"),
              "s.pbrt:1:31: \"float radius\": expected a number, got \"true\"");
    EXPECT_EQ(error_of("Shape \"sphere\" \"string name\" 3"),
              "s.pbrt:1:30: \"string name\": expected a quoted string, got \"3\"");
    EXPECT_EQ(error_of("Shape \"sphere\" \"texture t\" [ \"a\" b ]"),
              "s.pbrt:1:34: \"texture t\": expected a quoted string, got \"b\"");
    EXPECT_EQ(error_of("Shape \"sphere\" \"bool b\" [ true 1 ]"),
              "s.pbrt:1:32: \"bool b\": expected true or false, got \"1\"");
    EXPECT_EQ(error_of("Shape \"sphere\" \"bool b\" \"yes\""),
              "s.pbrt:1:25: \"bool b\": expected true or false, got the string \"yes\"");
    EXPECT_EQ(error_of("Shape \"x\" \"integer n\" 1.5"),
              "s.pbrt:1:23: \"integer n\": expected a 32-bit integer, got \"1.5\"");
    EXPECT_EQ(error_of("Shape \"x\" \"integer n\" 2147483648"),
              "s.pbrt:1:23: \"integer n\": expected a 32-bit integer, got \"2147483648\"");
    EXPECT_EQ(error_of("Shape \"x\" \"integer n\" abc"), "s.pbrt:1:23: \"integer n\": expected a number, got \"abc\"");
    EXPECT_EQ(error_of("Shape \"x\" \"point3 P\" [ 1 2 3 4 ]"),
              "s.pbrt:1:22: \"point3 P\" has 4 numbers; expected a multiple of 3");
    EXPECT_EQ(error_of("Shape \"x\" \"point2 uv\" 1"),
              "s.pbrt:1:23: \"point2 uv\" has 1 numbers; expected a multiple of 2");
    EXPECT_EQ(error_of("Shape \"x\" \"normal N\" [ 1 2 ]"),
              "s.pbrt:1:22: \"normal N\" has 2 numbers; expected a multiple of 3");
    EXPECT_EQ(error_of("Shape \"x\" \"rgb L\" [ 1 2 3 4 ]"),
              "s.pbrt:1:19: \"rgb L\" has 4 numbers; expected a multiple of 3");
    EXPECT_EQ(error_of("Shape \"x\" \"spectrum s\" [ 400 1 500 ]"),
              "s.pbrt:1:24: \"spectrum s\" has 3 numbers; a spectrum needs (lambda, value) pairs");
    EXPECT_TRUE(starts_with(error_of("Shape \"x\" \"spectrum s\" [ 400 1 \"a\" ]"),
                            "s.pbrt:1:32: \"spectrum s\": a spectrum is (lambda, value) pairs or one name or file"));
    EXPECT_TRUE(starts_with(error_of("Shape \"x\" \"spectrum s\" [ \"a\" 1 ]"),
                            "s.pbrt:1:30: \"spectrum s\": a spectrum is one name or file"));
    EXPECT_TRUE(starts_with(error_of("Shape \"x\" \"spectrum s\" [ \"a\" \"b\" ]"), "s.pbrt:1:30: \"spectrum s\":"));
}

TEST(PbrtParser, MalformedDeclarationsAreErrorsAtTheDeclaration) {
    EXPECT_TRUE(
        starts_with(error_of("Shape \"sphere\" \"flaot radius\" 1"),
                    "s.pbrt:1:16: unknown parameter type \"flaot\" in \"flaot radius\" (pbrt-v4 knows integer,"));
    EXPECT_EQ(error_of("Shape \"sphere\" \"radius\" 1"),
              "s.pbrt:1:16: parameter \"radius\" has no type (expected \"type name\", e.g. \"float radius\")");
    EXPECT_EQ(error_of("Shape \"sphere\" \"float radius extra\" 1"),
              "s.pbrt:1:16: malformed parameter declaration \"float radius extra\" (expected \"type name\", e.g. "
              "\"float radius\")");
    EXPECT_EQ(error_of("Shape \"sphere\" \" \t \" 1"),
              "s.pbrt:1:16: an empty parameter declaration (expected \"type name\", e.g. \"float radius\")");
    // Extra spaces and tabs around the words are allowed, as in pbrt-v4.
    EXPECT_EQ(parse("Shape \"x\" \"  float\t r \" 1").log[0], "Shape x {float r: 1} @1:1");
}

TEST(PbrtParser, ListSyntaxErrors) {
    EXPECT_EQ(error_of("Shape \"x\" \"float r\" [ 1 2"),
              "s.pbrt:1:21: \"float r\": missing ] (the list runs to the end of the file)");
    EXPECT_EQ(error_of("Shape \"x\" \"float r\" [ 1 2\nShape \"y\""),
              "s.pbrt:1:21: \"float r\": missing ] (the list runs into Shape at 2:1)");
    EXPECT_EQ(error_of("Shape \"x\" \"float r\" ]"), "s.pbrt:1:21: \"float r\": unexpected ] (no [ opened a list)");
    EXPECT_EQ(error_of("Shape \"x\" \"float r\" [ 1 [ 2 ] ]"), "s.pbrt:1:25: \"float r\": unexpected [ inside a list");
    EXPECT_EQ(error_of("Shape \"x\" \"float r\""), "s.pbrt:1:11: \"float r\" has no value (the file ends)");
}

TEST(PbrtParser, DirectiveSyntaxErrors) {
    EXPECT_EQ(error_of("Shape \"sphere\"\n  Sphere \"x\""), "s.pbrt:2:3: unknown directive \"Sphere\"");
    EXPECT_EQ(error_of("shape \"sphere\""), "s.pbrt:1:1: unknown directive \"shape\"");
    EXPECT_EQ(error_of("WorldBegin \"float radius\" 1"),
              "s.pbrt:1:12: expected a directive, got the string \"float radius\"");
    EXPECT_EQ(error_of("  ]"), "s.pbrt:1:3: expected a directive, got ]");
    EXPECT_EQ(error_of("Shape"),
              "s.pbrt:1:1: Shape: expected the shape's type as a quoted string, got the end of the file");
    EXPECT_EQ(error_of("Shape sphere"),
              "s.pbrt:1:7: Shape: expected the shape's type as a quoted string, got \"sphere\"");
    EXPECT_EQ(error_of("Translate 1 2"), "s.pbrt:1:1: Translate: expected a number, got the end of the file");
    EXPECT_EQ(error_of("Translate 1 2 ["), "s.pbrt:1:15: Translate: expected a number, got [");
    EXPECT_EQ(error_of("Transform [ 1 2 3 ]"), "s.pbrt:1:11: Transform: expected 16 numbers, got 3");
    EXPECT_EQ(error_of("Transform [ 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 ]"),
              "s.pbrt:1:45: Transform: expected ] after 16 numbers, got \"1\"");
    EXPECT_EQ(error_of("ActiveTransform Sometimes"),
              "s.pbrt:1:17: ActiveTransform: expected All, StartTime or EndTime, got \"Sometimes\"");
    EXPECT_EQ(error_of("Option 3 4"),
              "s.pbrt:1:8: Option: expected the option's \"name\" as a quoted string, got \"3\"");
    EXPECT_EQ(error_of("Texture \"t\" \"spectrum\""),
              "s.pbrt:1:1: Texture: expected the texture's class as a quoted string, got the end of the file");
    EXPECT_EQ(error_of("NamedMaterial [ \"a\" ]"),
              "s.pbrt:1:15: NamedMaterial: expected a material's name as a quoted string, got [");
    EXPECT_EQ(error_of("Shape \"x\"\n\"float r\" \"unterminated\n"),
              "s.pbrt:2:11: unterminated string (a line break inside it)");
}

}  // namespace
}  // namespace candela::pbrt
