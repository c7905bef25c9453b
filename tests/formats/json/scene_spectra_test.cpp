// The spectrum forms of a colour value (formats/json/scene_spectra.h): each of the four forms reads as
// the spectrum it names, anything else is left to the RGB reader, and every mistake is a located
// error (in the scene file, or at file:line in a .spd file with the scene key that names it).
#include "candela/formats/json/scene_spectra.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

#include "candela/formats/json/json_cursor.h"
#include "candela/spectrum/blackbody.h"
#include "candela/spectrum/named_spectra.h"
#include "image/test_files.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;
using test::scenes_dir;

// The spectrum of the value `value`, read as the key "c" of a scene file in `dir`.
std::optional<DenseSpectrum> spectrum_of(const std::string& value, const fs::path& dir = scenes_dir()) {
    const JsonDocument doc(R"({"c": )" + value + "}", (dir / "scene.json").string());
    JsonCursor root = doc.root();
    return read_spectrum(root.require("c"), dir);
}

SceneError spectrum_error(const std::string& value, const fs::path& dir = scenes_dir()) {
    try {
        spectrum_of(value, dir);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "expected a SceneError reading " << value;
    return SceneError(SourceLocation{}, "no error");
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// ---- the four forms

TEST(SceneSpectra, OtherValuesAreLeftToTheRgbReader) {
    for (const char* value : {"0.5", "[1, 0.5, 0.2]", R"("metal-Au-eta")", R"({"texture": "t"})",
                              R"({"type": "checkerboard"})", "{}", "true"})
        EXPECT_FALSE(spectrum_of(value).has_value()) << value;
}

TEST(SceneSpectra, ANameGivesTheNamedSpectrum) {
    const std::optional<DenseSpectrum> s = spectrum_of(R"({"spectrum": "metal-Au-eta"})");
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->v, named_spectrum("metal-Au-eta")->v);
    EXPECT_EQ(spectrum_of(R"({"spectrum": "stdillum-D65"})")->v, d65_illuminant().v);
}

// Piecewise linear through the pairs, constant beyond the ends (dense_spectrum.h).
TEST(SceneSpectra, PairsArePiecewiseLinear) {
    const std::optional<DenseSpectrum> s = spectrum_of(R"({"spectrum": [400, 0.1, 500, 0.4, 700, 0.9]})");
    ASSERT_TRUE(s.has_value());
    EXPECT_FLOAT_EQ((*s)(400.0f), 0.1f);
    EXPECT_FLOAT_EQ((*s)(450.0f), 0.25f);
    EXPECT_FLOAT_EQ((*s)(600.0f), 0.65f);
    EXPECT_FLOAT_EQ((*s)(360.0f), 0.1f);
    EXPECT_FLOAT_EQ((*s)(830.0f), 0.9f);
}

TEST(SceneSpectra, ABlackbodyIsNormalizedToPeakOne) {
    const std::optional<DenseSpectrum> s = spectrum_of(R"({"blackbody": 3200})");
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->v, blackbody_spectrum(3200.0f).v);
}

// pbrt-v4's .spd format: whitespace-separated numbers, nm and value in turn, '#' comments to the
// end of a line; a leading '+', exponents and CRLF line ends are fine.
TEST(SceneSpectra, ASpectrumFileIsReadRelativeToTheScene) {
    testing::TempDir dir;
    fs::create_directories(dir / "spd");
    testing::write_test_file(dir / "spd/Au.eta.spd",
                             "# gold, made up\r\n400 1.5\r\n500   2.5 # a comment right after a value\n"
                             "+6e2\t+3.5#and one without a space\n");
    const std::optional<DenseSpectrum> s = spectrum_of(R"({"spectrum_file": "spd/Au.eta.spd"})", dir.path());
    ASSERT_TRUE(s.has_value());
    EXPECT_FLOAT_EQ((*s)(400.0f), 1.5f);
    EXPECT_FLOAT_EQ((*s)(450.0f), 2.0f);
    EXPECT_FLOAT_EQ((*s)(550.0f), 3.0f);
    EXPECT_FLOAT_EQ((*s)(700.0f), 3.5f);
}

// ---- errors in the scene file

struct ErrorCase {
    const char* value;
    const char* pointer;
    const char* message;  // a part of it
};

TEST(SceneSpectra, MistakesAreLocatedErrors) {
    const ErrorCase cases[] = {
        {R"({"spectrum": "metal-Xx-eta"})", "/c/spectrum",
         R"(unknown spectrum "metal-Xx-eta"; expected one of: glass-BAF10, glass-BK7,)"},
        {R"({"spectrum": 3})", "/c/spectrum", "expected a spectrum name or an array of (nm, value) pairs, got 3"},
        {R"({"spectrum": [400, 0.1, 500]})", "/c/spectrum", "an even number of at least 4 numbers"},
        {R"({"spectrum": [400, 0.1]})", "/c/spectrum", "an even number of at least 4 numbers"},
        {R"({"spectrum": []})", "/c/spectrum", "an even number of at least 4 numbers"},
        {R"({"spectrum": [400, 0.1, 400, 0.2]})", "/c/spectrum/2",
         "wavelength 400 nm is not above the one before it, 400 nm"},
        {R"({"spectrum": [400, 0.1, 500, 0.2, 450, 0.3]})", "/c/spectrum/4",
         "wavelength 450 nm is not above the one before it, 500 nm"},
        {R"({"spectrum": [-5, 0.1, 400, 0.2]})", "/c/spectrum/0", "expected a number > 0, got -5"},
        {R"({"spectrum": [400, "a", 500, 0.2]})", "/c/spectrum/1", "expected a number"},
        {R"({"spectrum": [400, 1e39, 500, 0.2]})", "/c/spectrum/1", "within float range"},
        {R"({"blackbody": 0})", "/c/blackbody", "expected a number > 0, got 0"},
        {R"({"blackbody": -3000})", "/c/blackbody", "expected a number > 0, got -3000"},
        {R"({"blackbody": "hot"})", "/c/blackbody", "expected a number > 0"},
        {R"({"spectrum_file": 3})", "/c/spectrum_file", "expected a string"},
        {R"({"spectrum_file": "no_such.spd"})", "/c/spectrum_file",
         R"(spectrum file "no_such.spd" not found)"},
        {R"({"spectrum_file": "meshes"})", "/c/spectrum_file", "is a folder, not a file"},
        {R"({"blackbody": 3000, "scale": 2})", "/c", R"(unknown key "scale")"},
        {R"({"spectrum": "stdillum-A", "blackbody": 3000})", "/c",
         R"(a spectrum is one of "spectrum", "spectrum_file" and "blackbody"; this object also has "spectrum")"},
    };
    for (const ErrorCase& c : cases) {
        const SceneError e = spectrum_error(c.value);
        EXPECT_EQ(e.where().json_pointer, c.pointer) << c.value;
        EXPECT_TRUE(contains(e.message(), c.message)) << c.value << "\n  " << e.message();
        EXPECT_EQ(e.where().file, (scenes_dir() / "scene.json").string()) << c.value;
        EXPECT_EQ(e.where().line, 1) << c.value;
    }
}

// An unknown name lists every name, sorted.
TEST(SceneSpectra, AnUnknownNameListsTheNames) {
    const SceneError e = spectrum_error(R"({"spectrum": "gold"})");
    for (std::string_view name : named_spectrum_names())
        EXPECT_TRUE(contains(e.message(), std::string(name))) << name;
}

// The error is at the value's own line and column.
TEST(SceneSpectra, AnErrorPointsAtTheValue) {
    const SceneError e = spectrum_error("{\n  \"spectrum\": [400, 0.1,\n               300, 0.2]}");
    EXPECT_EQ(e.where().json_pointer, "/c/spectrum/2");
    EXPECT_EQ(e.where().line, 3);
    EXPECT_EQ(e.where().column, 16);
}

// ---- errors in a .spd file: at file:line, naming the scene key that refers to it

struct SpdCase {
    const char* text;
    int line;
    const char* message;
};

TEST(SceneSpectra, SpectrumFileMistakesNameTheFileAndLine) {
    const SpdCase cases[] = {
        {"400 1\n500 2\n6x0 3\n", 3, R"(expected a number, got "6x0")"},
        {"400 1\n500 2,\n", 2, R"(expected a number, got "2,")"},
        {"400 1\n500 nan\n", 2, R"(expected a number, got "nan")"},
        {"400 inf\n500 2\n", 1, R"(expected a number, got "inf")"},
        {"400 1 500 1e39\n", 1, R"(expected a number, got "1e39")"},
        {"400 1\n\n500\n", 3, "3 numbers, an odd count"},
        {"# comment\n500 1\n400 2\n", 3, "wavelength 400 nm is not above the one before it, 500 nm"},
        {"0 1\n400 2\n", 1, "expected a wavelength > 0 nm, got 0"},
        {"400 1\n", 1, "1 (nm, value) pairs; a spectrum file needs at least 2"},
        {"# nothing but a comment\n", 1, "0 (nm, value) pairs"},
    };
    for (const SpdCase& c : cases) {
        testing::TempDir dir;
        testing::write_test_file(dir / "s.spd", c.text);
        const SceneError e = spectrum_error(R"({"spectrum_file": "s.spd"})", dir.path());
        EXPECT_EQ(e.where().file, (dir / "s.spd").string()) << c.text;
        EXPECT_EQ(e.where().line, c.line) << c.text;
        EXPECT_TRUE(contains(e.message(), c.message)) << c.text << "\n  " << e.message();
        EXPECT_TRUE(contains(e.message(), "(referenced by /c/spectrum_file at " + (dir / "scene.json").string() + ":1:"))
            << e.message();
    }
}

}  // namespace
}  // namespace candela
