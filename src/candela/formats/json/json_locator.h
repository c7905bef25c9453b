#pragma once
// Maps places in a JSON document back to its text, for error messages only. nlohmann-json keeps no
// source positions, so when the scene loader reports an error it re-scans the raw text (lazily, as
// Tungsten's JsonDocument does): a JSON pointer becomes a byte offset, an offset becomes
// line:column. The scanner is tolerant: on text that is not valid JSON it stops and finds nothing.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace candela {

// A 1-based line and column. Columns count characters (UTF-8 code points), a tab as one.
struct TextPosition {
    int line = 1;
    int column = 1;
};

// Where one JSON value lies in the text: the opening quote of its key (for a member of an object;
// otherwise the value's own first character) and the value's first character.
struct JsonSpan {
    size_t key_offset = 0;
    size_t value_offset = 0;
};

// A JSON value the scanner flagged, with its RFC 6901 pointer.
struct JsonFinding {
    std::string pointer;
    JsonSpan span;
};

// The line and column of byte `offset` (clamped to the text; a leading UTF-8 byte order mark is not
// counted).
TextPosition text_position(std::string_view text, size_t offset);

// The value that `pointer` names. With duplicate keys the last one wins, as in nlohmann-json.
std::optional<JsonSpan> find_json_pointer(std::string_view text, std::string_view pointer);

// The first key that repeats an earlier key of the same object (pointer: the repeated member).
std::optional<JsonFinding> find_duplicate_key(std::string_view text);

// The first number too large for a double (e.g. 1e400), which nlohmann-json refuses to parse.
std::optional<JsonFinding> find_overflowing_number(std::string_view text);

// The escaped pointer token for an object key: "~" becomes "~0" and "/" becomes "~1".
std::string escape_pointer_token(std::string_view key);

}  // namespace candela
