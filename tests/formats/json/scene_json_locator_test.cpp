// Mapping JSON pointers and byte offsets back to line:column, as error messages need.
#include "candela/formats/json/json_locator.h"

#include <gtest/gtest.h>

#include <string>

#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

TEST(TextPosition, CountsLinesAndColumnsFromOne) {
    const std::string text = "ab\ncd\n\nef";
    EXPECT_EQ(text_position(text, 0).line, 1);
    EXPECT_EQ(text_position(text, 0).column, 1);
    EXPECT_EQ(text_position(text, 1).column, 2);
    EXPECT_EQ(text_position(text, 3).line, 2);  // 'c'
    EXPECT_EQ(text_position(text, 3).column, 1);
    EXPECT_EQ(text_position(text, 7).line, 4);  // 'e'
    EXPECT_EQ(text_position(text, 8).column, 2);
    // Past the end: clamped to the end of the text.
    EXPECT_EQ(text_position(text, 1000).line, 4);
    EXPECT_EQ(text_position(text, 1000).column, 3);
}

TEST(TextPosition, CrLfEndsALine) {
    const std::string text = "{\r\n  \"a\": 1\r\n}";
    TextPosition p = text_position(text, text.find('1'));
    EXPECT_EQ(p.line, 2);
    EXPECT_EQ(p.column, 8);
}

TEST(TextPosition, ColumnsCountCharactersNotBytes) {
    // "é" is two bytes of UTF-8 and "😀" four; each is one column.
    const std::string text = "{\"\xC3\xA9\xF0\x9F\x98\x80\": 1}";
    EXPECT_EQ(text_position(text, text.find('1')).column, 8);
}

TEST(TextPosition, ByteOrderMarkIsNotAColumn) {
    const std::string text = "\xEF\xBB\xBF{\"a\": 1}";
    EXPECT_EQ(text_position(text, 3).column, 1);
    EXPECT_EQ(text_position(text, text.find('1')).column, 7);
}

TEST(FindJsonPointer, FindsValuesInNestedArraysAndObjects) {
    const std::string text =
        "{\n"
        "  \"a\": [1, [2, {\"b\": [3, 4]}]],\n"
        "  \"c\": {\"d\": {\"e\": \"x\"}}\n"
        "}\n";
    auto four = find_json_pointer(text, "/a/1/1/b/1");
    ASSERT_TRUE(four);
    EXPECT_EQ(four->value_offset, text.find("4]"));
    EXPECT_EQ(four->key_offset, four->value_offset);  // array elements have no key
    TextPosition p = text_position(text, four->value_offset);
    EXPECT_EQ(p.line, 2);
    EXPECT_EQ(p.column, 26);

    auto b = find_json_pointer(text, "/a/1/1/b");
    ASSERT_TRUE(b);
    EXPECT_EQ(b->key_offset, text.find("\"b\""));
    EXPECT_EQ(b->value_offset, text.find("[3, 4]"));

    auto e = find_json_pointer(text, "/c/d/e");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->value_offset, text.find("\"x\""));
    EXPECT_EQ(text_position(text, e->value_offset).line, 3);
    EXPECT_EQ(text_position(text, e->value_offset).column, 20);

    auto root = find_json_pointer(text, "");
    ASSERT_TRUE(root);
    EXPECT_EQ(root->value_offset, 0u);
}

TEST(FindJsonPointer, IsNotFooledByBracesAndQuotesInStrings) {
    const std::string text = R"({"s": "}{][,:\"", "t": "\\\"{", "u": [{"v": "]"}, 5]})";
    auto u1 = find_json_pointer(text, "/u/1");
    ASSERT_TRUE(u1);
    EXPECT_EQ(u1->value_offset, text.find("5]"));
    auto v = find_json_pointer(text, "/u/0/v");
    ASSERT_TRUE(v);
    EXPECT_EQ(v->value_offset, text.find("\"]\""));
}

TEST(FindJsonPointer, MatchesDecodedAndEscapedKeys) {
    const std::string text =
        R"({"a\"b": 1, "c/d": 2, "e~f": 3, "\u00e9t\u00e9": 4, "\ud83d\ude00": 5})";
    EXPECT_EQ(find_json_pointer(text, "/a\"b")->value_offset, text.find('1'));
    EXPECT_EQ(find_json_pointer(text, "/c~1d")->value_offset, text.find('2'));
    EXPECT_EQ(find_json_pointer(text, "/e~0f")->value_offset, text.find('3'));
    EXPECT_EQ(find_json_pointer(text, "/\xC3\xA9t\xC3\xA9")->value_offset, text.find('4'));
    EXPECT_EQ(find_json_pointer(text, "/\xF0\x9F\x98\x80")->value_offset, text.find('5'));
    EXPECT_EQ(escape_pointer_token("c/d~e"), "c~1d~0e");
}

TEST(FindJsonPointer, MissingPointersAndBrokenTextFindNothing) {
    const std::string text = R"({"a": [1, 2], "b": {"c": 3}})";
    EXPECT_FALSE(find_json_pointer(text, "/a/2"));
    EXPECT_FALSE(find_json_pointer(text, "/b/d"));
    EXPECT_FALSE(find_json_pointer(text, "/a/0/x"));
    EXPECT_FALSE(find_json_pointer("{\"a\": [1, 2", "/b"));
    EXPECT_FALSE(find_json_pointer("", ""));
    // What precedes the break is still found.
    EXPECT_TRUE(find_json_pointer("{\"a\": [1, 2", "/a/1"));
}

TEST(FindJsonPointer, LastOfDuplicateKeysWins) {
    const std::string text = R"({"k": 1, "k": 2})";
    EXPECT_EQ(find_json_pointer(text, "/k")->value_offset, text.find('2'));
}

TEST(FindJsonPointer, FindsValuesAtAnyDepthWithoutRecursing) {
    // 100000 levels would overflow the stack of a reader that recursed per level.
    constexpr size_t kDepth = 100000;
    const std::string text = "{\"a\": " + std::string(kDepth, '[') + "7" + std::string(kDepth, ']') + ", \"b\": 8}";
    std::string deepest = "/a";
    for (size_t i = 0; i < kDepth; ++i) deepest += "/0";
    auto seven = find_json_pointer(text, deepest);
    ASSERT_TRUE(seven);
    EXPECT_EQ(seven->value_offset, 6 + kDepth);
    auto after = find_json_pointer(text, "/b");
    ASSERT_TRUE(after);
    EXPECT_EQ(text[after->value_offset], '8');
}

TEST(FindDuplicateKey, ReportsTheRepeatedKeyWithItsObject) {
    const std::string text = R"({"a": {"x": 1, "y": 2}, "b": [{"x": 1, "y": 2, "x": 3}]})";
    auto dup = find_duplicate_key(text);
    ASSERT_TRUE(dup);
    EXPECT_EQ(dup->pointer, "/b/0/x");
    EXPECT_EQ(dup->span.key_offset, text.rfind("\"x\""));
    EXPECT_FALSE(find_duplicate_key(R"({"a": {"x": 1}, "b": {"x": 1}})"));
}

TEST(FindOverflowingNumber, FindsNumbersBeyondDoubleRangeOnly) {
    const std::string text = "[1, 1e-400, 0.0000001, [2, -1.5e309]]";
    auto big = find_overflowing_number(text);
    ASSERT_TRUE(big);
    EXPECT_EQ(big->pointer, "/3/1");
    EXPECT_EQ(big->span.value_offset, text.find("-1.5e309"));
    EXPECT_FALSE(find_overflowing_number("[1e-400, 1.7e308, 123456789012345678901234567890]"));
    EXPECT_TRUE(find_overflowing_number("[" + std::string("1") + std::string(400, '0') + "]"));
    EXPECT_TRUE(find_overflowing_number("{\"a\": 0.001e312}"));
    EXPECT_FALSE(find_overflowing_number("{\"a\": 0.001e310}"));
}

// The whole path: an error deep inside nested values, after strings full of JSON punctuation, is
// reported at the right line and column.
TEST(SceneErrorLocation, SurvivesNestingAndPunctuationInStrings) {
    const std::string json =
        "{\n"
        "  \"materials\": {\n"
        "    \"a {[\\\"]}\": {\"type\": \"diffuse\"},\n"
        "    \"b\": {\"type\": \"mirror\", \"albedo\": [1, [0.5], 1]}\n"
        "  }\n"
        "}\n";
    SceneError e = test::load_error(json);
    EXPECT_EQ(e.where().json_pointer, "/materials/b/albedo/1");
    EXPECT_EQ(e.where().line, 4);
    EXPECT_EQ(e.where().column, 43);
    EXPECT_EQ(e.message(), "expected a number in [0, 1], got [0.5]");
}

TEST(SceneErrorLocation, UnknownKeyPointsAtTheKeyOfAnEscapedName) {
    const std::string json = "{\"materials\": {\"x/y~\": {\"type\": \"diffuse\",\n  \"tnit\": 1}}}";
    SceneError e = test::load_error(json);
    EXPECT_EQ(e.where().json_pointer, "/materials/x~1y~0");
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().column, 3);
    EXPECT_EQ(e.message(), "unknown key \"tnit\"; expected one of: albedo, alpha, bump_map, normal_map, normal_map_convention, type");
}

TEST(SceneErrorLocation, DuplicateKeyIsReportedAtItsSecondOccurrence) {
    const std::string json = "{\"materials\": {\"a/b\": {\"type\": \"diffuse\"},\n"
                             "                \"a/b\": {\"type\": \"mirror\"}}}";
    SceneError e = test::load_error(json);
    EXPECT_EQ(e.where().json_pointer, "/materials");
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().column, 17);
    EXPECT_EQ(e.message(), "duplicate key \"a/b\"");
}

TEST(SceneErrorLocation, SyntaxErrorInALaterLine) {
    const std::string json = "{\n  \"sampler\": {\"spp\": 4},\n  \"camera\": {\"fov\": 40,}\n}";
    SceneError e = test::load_error(json);
    EXPECT_EQ(e.where().json_pointer, "");
    EXPECT_EQ(e.where().line, 3);
    EXPECT_EQ(e.where().column, 24);
    EXPECT_NE(e.message().find("JSON syntax error"), std::string::npos) << e.message();
}

}  // namespace
}  // namespace candela
