#include "candela/formats/pbrt/pbrt_tokenizer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "candela/core/error.h"

namespace candela::pbrt {
namespace CANDELA_UNITY_ID {

// Every token of `text` as "kind:text@line:col", read in chunks of `chunk` bytes.
std::vector<std::string> tokens(const std::string& text, size_t chunk = 1 << 20, size_t max_token = 1 << 20) {
    Location file;
    file.file = "t.pbrt";
    Tokenizer tokenizer(text, &file, chunk, max_token);
    std::vector<std::string> out;
    Token t;
    while (tokenizer.next(t)) {
        const char* kind = t.kind == Token::Kind::Word     ? "w"
                           : t.kind == Token::Kind::String ? "s"
                           : t.kind == Token::Kind::Open   ? "["
                                                           : "]";
        out.push_back(std::string(kind) + ":" + t.text + "@" + std::to_string(t.line) + ":" + std::to_string(t.column));
    }
    return out;
}

std::string error_of(const std::string& text, size_t chunk = 1 << 20, size_t max_token = 1 << 20) {
    try {
        tokens(text, chunk, max_token);
    } catch (const SceneError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected a SceneError for " << text;
    return "";
}

TEST(PbrtTokenizer, WordsStringsBracketsWithTheirLinesAndColumns) {
    EXPECT_EQ(
        tokens("Shape \"sphere\" \"float radius\" [ 2.5 ]\n\t-1e-3\ntrue][\"\"\"x\"\n"),
        std::vector<std::string>({"w:Shape@1:1", "s:sphere@1:7", "s:float radius@1:16", "[:[@1:31", "w:2.5@1:33",
                                  "]:]@1:37", "w:-1e-3@2:2", "w:true@3:1", "]:]@3:5", "[:[@3:6", "s:@3:7", "s:x@3:9"}));
}

TEST(PbrtTokenizer, CommentsRunToTheEndOfTheLine) {
    EXPECT_EQ(tokens("# a comment \"with a quote\n  A # after [ ]\n#\nB#not-a-comment # end"),
              std::vector<std::string>({"w:A@2:3", "w:B#not-a-comment@4:1"}));
    EXPECT_EQ(tokens("# only a comment, no line break"), std::vector<std::string>{});
    EXPECT_EQ(tokens(""), std::vector<std::string>{});
}

TEST(PbrtTokenizer, CarriageReturnsAreSpace) {
    EXPECT_EQ(tokens("A\r\n  B\r\n"), std::vector<std::string>({"w:A@1:1", "w:B@2:3"}));
}

TEST(PbrtTokenizer, StringEscapesAreDecoded) {
    EXPECT_EQ(tokens(R"("a\"b\\c\nd\te\'f\bg\fh\ri")"), std::vector<std::string>({"s:a\"b\\c\nd\te'f\bg\fh\ri@1:1"}));
    EXPECT_EQ(tokens(R"("path with spaces/and#hash")"), std::vector<std::string>({"s:path with spaces/and#hash@1:1"}));
}

TEST(PbrtTokenizer, AnUnknownEscapeIsAnErrorAtTheBackslash) {
    EXPECT_EQ(error_of("\n  \"ab\\qc\""),
              "t.pbrt:2:6: unknown escape \\q in a string (pbrt-v4 knows \\b \\f \\n \\r "
              "\\t \\\\ \\' \\\")");
}

TEST(PbrtTokenizer, UnterminatedStringsAreErrorsAtTheirOpeningQuote) {
    EXPECT_EQ(error_of("Shape \"sphere\n\"x\""), "t.pbrt:1:7: unterminated string (a line break inside it)");
    EXPECT_EQ(error_of("A\n   \"sphere"), "t.pbrt:2:4: unterminated string (the file ends inside it)");
    EXPECT_EQ(error_of("\"abc\\"), "t.pbrt:1:1: unterminated string (the file ends inside it)");
}

// A string's text goes into candela's JSON document, which must be UTF-8 (found by the pbrt fuzz
// target: a filename of 0xFF bytes made the document's dump throw nlohmann's type_error).
TEST(PbrtTokenizer, AStringThatIsNotUtf8IsAnErrorAtItsOpeningQuote) {
    EXPECT_EQ(error_of("Shape \"plymesh\"\n  \"string filename\" \"model\xff.ply\""),
              "t.pbrt:2:21: a string with an ill-formed UTF-8 byte (0xFF at byte 6 of the string); scene files "
              "must be UTF-8");
    EXPECT_NE(error_of("\"\xc0\xaf\""), "");      // overlong '/'
    EXPECT_NE(error_of("\"\xed\xa0\x80\""), "");  // a surrogate
    EXPECT_NE(error_of("\"\xe2\x82\""), "");      // cut short
    EXPECT_EQ(tokens("\"caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80\""),
              std::vector<std::string>({"s:caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80@1:1"}));
}

// The same text in chunks of every size from 1 byte up gives the same tokens at the same places:
// tokens, escapes, comments and line breaks straddle chunk boundaries.
TEST(PbrtTokenizer, TokensStraddlingChunksAreWhole) {
    const std::string text =
        "# comment [ \"\nLookAt 0.125 1e-3 -7\n\t\"point3 P\" [ 1.5 2.25 3 ]\r\n\"a\\\"b\\nc\" true\n"
        "   Shape\"sphere\"#tail\nAttributeEnd";
    const std::vector<std::string> whole = tokens(text);
    ASSERT_EQ(whole.size(), 15u);
    for (size_t chunk = 1; chunk <= text.size() + 1; ++chunk) EXPECT_EQ(tokens(text, chunk), whole) << chunk;
    for (size_t chunk = 1; chunk <= 12; ++chunk)
        EXPECT_EQ(error_of("A B\n  \"no end", chunk), "t.pbrt:2:3: unterminated string (the file ends inside it)");
}

// A token is held whole, so its length is bounded: words, strings and escapes count.
TEST(PbrtTokenizer, TokensLongerThanTheLimitAreErrors) {
    EXPECT_EQ(tokens("abcdefgh \"12345678\" \"\\n\\n\"", 3, 8).size(), 3u);
    EXPECT_EQ(error_of("x\n abcdefghi", 3, 8), "t.pbrt:2:2: a token longer than 8 bytes");
    EXPECT_EQ(error_of("\"123456789\"", 3, 8), "t.pbrt:1:1: a token longer than 8 bytes");
    EXPECT_EQ(error_of("\"12345678\\n\"", 3, 8), "t.pbrt:1:1: a token longer than 8 bytes");
}

}  // namespace
}  // namespace candela::pbrt
