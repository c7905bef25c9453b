// Include and Import: paths relative to the including file, locations carrying the chain of
// includes, cycles, missing files and the nesting limit (fixtures in tests/data/pbrt/; the tests
// run in tests/, so the scenes are named data/pbrt/...).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_parser.h"
#include "recording_target.h"

namespace candela::pbrt {
namespace CANDELA_UNITY_ID {

using test::RecordingTarget;

std::string error_of_file(const std::string& file, const ParseOptions& options = {}) {
    RecordingTarget target;
    try {
        parse_file(file, target, options);
    } catch (const SceneError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected a SceneError for " << file;
    return "";
}

TEST(PbrtInclude, PathsAreRelativeToTheIncludingFileAndLocationsNameTheChain) {
    RecordingTarget t;
    parse_file("data/pbrt/include_main.pbrt", t);
    EXPECT_EQ(t.log, std::vector<std::string>({"Camera perspective @2:1", "WorldBegin @3:1", "Shape trianglemesh @2:1",
                                               "Shape disk {float radius: 2} @1:1", "LightSource point @2:1",
                                               "Shape sphere @6:1"}));
    ASSERT_EQ(t.locations.size(), 6u);
    EXPECT_EQ(describe(t.locations[0]), "data/pbrt/include_main.pbrt:2:1");
    EXPECT_EQ(describe(t.locations[2]),
              "data/pbrt/geometry/shapes.pbrt:2:1 (included from data/pbrt/include_main.pbrt:4:3)");
    EXPECT_EQ(describe(t.locations[3]),
              "data/pbrt/geometry/nested/leaf.pbrt:1:1 (included from data/pbrt/geometry/shapes.pbrt:3:5) "
              "(included from data/pbrt/include_main.pbrt:4:3)");
    EXPECT_EQ(describe(t.parameter_lists[3][0].location),
              "data/pbrt/geometry/nested/leaf.pbrt:1:14 (included from data/pbrt/geometry/shapes.pbrt:3:5) "
              "(included from data/pbrt/include_main.pbrt:4:3)");
    // Import reads as Include.
    EXPECT_EQ(describe(t.locations[4]),
              "data/pbrt/geometry/imported.pbrt:2:1 (included from data/pbrt/include_main.pbrt:5:1)");
    EXPECT_EQ(describe(t.locations[5]), "data/pbrt/include_main.pbrt:6:1");
    EXPECT_EQ(t.locations[5].included_from, nullptr);
}

TEST(PbrtInclude, ANameNotFoundBesideTheIncludingFileIsLookedForBesideTheMainFile) {
    // parts/a.pbrt includes "parts/b.pbrt", a name relative to the main file's folder (pbrt-v4's
    // rule), not to its own (where parts/parts/b.pbrt does not exist).
    RecordingTarget t;
    parse_file("data/pbrt/main_relative/main.pbrt", t);
    ASSERT_EQ(t.locations.size(), 2u);
    EXPECT_EQ(describe(t.locations[1]),
              "data/pbrt/main_relative/parts/b.pbrt:1:1 (included from data/pbrt/main_relative/parts/a.pbrt:2:1) "
              "(included from data/pbrt/main_relative/main.pbrt:2:1)");
}

TEST(PbrtInclude, ChunkSizeChangesNothingAcrossFiles) {
    RecordingTarget whole;
    parse_file("data/pbrt/include_main.pbrt", whole);
    for (size_t chunk : {1, 2, 7}) {
        ParseOptions options;
        options.chunk_size = chunk;
        RecordingTarget t;
        parse_file("data/pbrt/include_main.pbrt", t, options);
        EXPECT_EQ(t.log, whole.log) << chunk;
    }
}

TEST(PbrtInclude, ErrorsInAnIncludedFileNameTheChain) {
    EXPECT_EQ(error_of_file("data/pbrt/include_error_main.pbrt"),
              "data/pbrt/geometry/bad_leaf.pbrt:2:39: \"float radius\": expected a number, got \"oops\" "
              "(included from data/pbrt/include_error_main.pbrt:3:1)");
}

TEST(PbrtInclude, ACycleIsAnErrorNamingIt) {
    EXPECT_EQ(error_of_file("data/pbrt/cycle_a.pbrt"),
              "data/pbrt/cycle_b.pbrt:2:1: include cycle: data/pbrt/cycle_a.pbrt -> data/pbrt/cycle_b.pbrt -> "
              "data/pbrt/cycle_a.pbrt (included from data/pbrt/cycle_a.pbrt:2:1)");
}

TEST(PbrtInclude, AMissingFileIsAnErrorAtTheInclude) {
    EXPECT_EQ(error_of_file("data/pbrt/include_missing.pbrt"),
              "data/pbrt/include_missing.pbrt:2:1: cannot open \"data/pbrt/geometry/absent.pbrt\": No such file or "
              "directory");
    EXPECT_EQ(error_of_file("data/pbrt/absent.pbrt"),
              "data/pbrt/absent.pbrt: cannot open the scene: No such file or directory");
    EXPECT_EQ(error_of_file("data/pbrt"), "data/pbrt: is a folder, not a pbrt-v4 scene file");
}

TEST(PbrtInclude, FoldersAndDevicesAreNotIncluded) {
    RecordingTarget t;
    try {
        parse_string("Include \"geometry\"", "data/pbrt/virtual.pbrt", t);
        ADD_FAILURE();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "data/pbrt/virtual.pbrt:1:1: \"data/pbrt/geometry\" is a folder, not a file");
    }
    try {
        parse_string("Include \"/dev/zero\"", "s.pbrt", t);
        ADD_FAILURE();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "s.pbrt:1:1: \"/dev/zero\" is not a regular file");
    }
}

TEST(PbrtInclude, TextInMemoryIncludesRelativeToItsName) {
    RecordingTarget t;
    parse_string("Include \"geometry/nested/leaf.pbrt\"", "data/pbrt/virtual.pbrt", t);
    ASSERT_EQ(t.locations.size(), 1u);
    EXPECT_EQ(describe(t.locations[0]),
              "data/pbrt/geometry/nested/leaf.pbrt:1:1 (included from data/pbrt/virtual.pbrt:1:1)");
}

TEST(PbrtInclude, NestingIsLimited) {
    RecordingTarget t;
    parse_file("data/pbrt/chain/1.pbrt", t);
    EXPECT_EQ(t.log, std::vector<std::string>({"Shape sphere @1:1"}));
    ParseOptions options;
    options.max_include_depth = 3;
    EXPECT_EQ(error_of_file("data/pbrt/chain/1.pbrt", options),
              "data/pbrt/chain/3.pbrt:1:1: \"4.pbrt\": includes nest deeper than 3 files (included from "
              "data/pbrt/chain/2.pbrt:1:1) (included from data/pbrt/chain/1.pbrt:1:1)");
}

TEST(PbrtInclude, GzipFilesAreReadInflatedWhateverTheirName) {
    RecordingTarget t;
    parse_file("data/pbrt/gzip_main.pbrt", t);
    EXPECT_EQ(t.log, std::vector<std::string>({"Camera perspective @2:1", "WorldBegin @3:1", "Shape trianglemesh @2:1",
                                               "Shape disk {float radius: 2} @1:1", "LightSource point @3:1",
                                               "Shape sphere @6:1"}));
    ASSERT_EQ(t.locations.size(), 6u);
    EXPECT_EQ(describe(t.locations[3]),
              "data/pbrt/geometry/nested/leaf.pbrt:1:1 (included from data/pbrt/geometry/gzipped.pbrt.gz:3:5) "
              "(included from data/pbrt/gzip_main.pbrt:4:1)");
    // geometry/gzipped_unnamed.pbrt is gzip data under a plain name.
    EXPECT_EQ(describe(t.locations[4]),
              "data/pbrt/geometry/gzipped_unnamed.pbrt:3:1 (included from data/pbrt/gzip_main.pbrt:5:1)");
    // Inflated in chunks as small as a byte, the tokens are the same.
    for (size_t chunk : {1, 3}) {
        ParseOptions options;
        options.chunk_size = chunk;
        RecordingTarget small;
        parse_file("data/pbrt/gzip_main.pbrt", small, options);
        EXPECT_EQ(small.log, t.log) << chunk;
    }
}

TEST(PbrtInclude, AGzipMainFileIsReadInflated) {
    RecordingTarget t;
    parse_file("data/pbrt/gzip_whole.pbrt.gz", t);
    EXPECT_EQ(t.log, std::vector<std::string>({"Camera perspective @2:1", "WorldBegin @3:1", "Shape sphere @4:1"}));
}

TEST(PbrtInclude, ErrorsInAGzipFileNameItsLine) {
    EXPECT_EQ(error_of_file("data/pbrt/gzip_error_main.pbrt"),
              "data/pbrt/geometry/gzipped_bad.pbrt.gz:3:29: \"float radius\": expected a number, got the string "
              "\"oops\" (included from data/pbrt/gzip_error_main.pbrt:3:1)");
    EXPECT_EQ(error_of_file("data/pbrt/gzip_corrupt_main.pbrt"),
              "data/pbrt/geometry/gzipped_truncated.pbrt.gz: the gzip data ends before the stream does (file "
              "truncated?) (included from data/pbrt/gzip_corrupt_main.pbrt:3:1)");
}

TEST(PbrtInclude, ABinaryFileIsOneErrorAtTheFileNotItsBytesAsWords) {
    EXPECT_EQ(error_of_file("data/pbrt/binary_main.pbrt"),
              "data/pbrt/binary_main.pbrt: is a binary file, not pbrt-v4 scene text (a control byte 0x00 at byte 6)");
    EXPECT_EQ(error_of_file("data/pbrt/binary_include_main.pbrt"),
              "data/pbrt/geometry/binary.pbrt: is a binary file, not pbrt-v4 scene text (ill-formed UTF-8 (0x89 at "
              "byte 1)) (included from data/pbrt/binary_include_main.pbrt:3:1)");
    EXPECT_EQ(error_of_file("data/pbrt/bad_utf8_main.pbrt"),
              "data/pbrt/bad_utf8_main.pbrt: is a binary file, not pbrt-v4 scene text (ill-formed UTF-8 (0xC3 at byte "
              "17))");
    // The same with the text in memory and in chunks of a byte.
    ParseOptions options;
    options.chunk_size = 1;
    RecordingTarget t;
    try {
        parse_string(std::string("Shape \"sphere\"\n\x01", 16), "memory.pbrt", t, options);
        ADD_FAILURE() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "memory.pbrt: is a binary file, not pbrt-v4 scene text (a control byte 0x01 at byte 16)");
    }
}

TEST(PbrtInclude, ALatin1CommentIsNotBinary) {
    RecordingTarget t;
    parse_file("data/pbrt/latin1_comment.pbrt", t);
    EXPECT_EQ(t.log, std::vector<std::string>({"Shape sphere @2:1"}));
}

// The pbrt-v4 cases of the bad-input corpus give these messages from the parser (the CLI's
// checks of them live with the other bad inputs in tests/app/bad_inputs_test.cpp).
TEST(PbrtInclude, BadInputCorpusMessages) {
    const std::string dir = "data/bad_inputs/";
    const std::pair<const char*, const char*> cases[] = {
        {"pbrt_unterminated_string.pbrt",
         "pbrt_unterminated_string.pbrt:8:7: unterminated string (a line break inside it)"},
        {"pbrt_unknown_directive.pbrt", "pbrt_unknown_directive.pbrt:8:1: unknown directive \"AttributeBeginn\""},
        {"pbrt_wrong_parameter_type.pbrt",
         "pbrt_wrong_parameter_type.pbrt:7:31: \"float radius\": expected a number, got the string \"one\""},
        {"pbrt_missing_include.pbrt",
         "pbrt_missing_include.pbrt:7:1: cannot open \"data/bad_inputs/pbrt_missing_include_geometry.pbrt\": No such "
         "file or directory"},
        {"pbrt_include_cycle.pbrt",
         "pbrt_include_cycle.pbrt:8:1: include cycle: data/bad_inputs/pbrt_include_cycle.pbrt -> "
         "data/bad_inputs/pbrt_include_cycle.pbrt"},
        {"pbrt_number_overflow.pbrt",
         "pbrt_number_overflow.pbrt:7:31: \"float radius\": \"1e999\" is beyond the range of a double"},
        {"pbrt_malformed_parameter.pbrt",
         "pbrt_malformed_parameter.pbrt:7:16: parameter \"radius\" has no type (expected \"type name\", e.g. \"float "
         "radius\")"},
    };
    for (const auto& [file, message] : cases) EXPECT_EQ(error_of_file(dir + file), dir + message);
}

}  // namespace
}  // namespace candela::pbrt
