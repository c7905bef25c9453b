#pragma once
// Reading a JSON scene with located errors (STYLE.md). A JsonDocument owns the text and the parsed
// tree; a JsonCursor is a position in the tree that knows its JSON pointer, remembers which keys it
// was asked for (so the others can be reported as unknown), and reads typed values, throwing
// SceneError "file:line:col: /pointer: expected ..., got ..." on anything else. Line and column
// are found only when an error is raised, by re-scanning the text (json_locator.h).
//
// Locations: an error about a value points at the value's first character; an error about a key
// (unknown key) points at the key's opening quote and names the object's pointer; a missing key
// points at the object's opening brace.
//
// Internal to scene/: only json_cursor.cpp sees nlohmann-json, the rest uses the forward
// declaration.
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "candela/core/error.h"
#include "candela/math/rgb.h"
#include "candela/math/vec.h"

namespace candela {

class JsonCursor;

class JsonDocument {
  public:
    // Parses `text`. A syntax error, a repeated key or a number beyond the range of a double
    // throws SceneError located in `file` (the name messages show).
    JsonDocument(std::string text, std::string file);
    ~JsonDocument();
    JsonDocument(const JsonDocument&) = delete;
    JsonDocument& operator=(const JsonDocument&) = delete;

    JsonCursor root() const;
    const std::string& file() const { return file_; }

    // For a document translated from another scene file: where the value at a JSON pointer came
    // from (the pointer itself or the nearest enclosing one the map knows). locate() then answers
    // with that file, line and column, keeping the pointer.
    using SourceMap = std::function<std::optional<SourceLocation>(const std::string& pointer)>;
    void set_source_map(SourceMap map) { source_map_ = std::move(map); }

    // Where the value at `pointer` is (or the key naming it, when at_key), filled as far as found.
    SourceLocation locate(const std::string& pointer, bool at_key = false) const;
    // Throws SceneError at the value `pointer`, or at the key `key` of the object `pointer`.
    [[noreturn]] void fail(const std::string& pointer, std::string message) const;
    [[noreturn]] void fail_at_key(const std::string& object_pointer, std::string_view key,
                                  std::string message) const;

  private:
    std::string text_;
    std::string file_;
    std::unique_ptr<nlohmann::ordered_json> root_;
    SourceMap source_map_;
};

// The allowed range of a number: lo and hi, each inclusive or not; infinite means unbounded.
struct Bounds {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false;
    bool hi_open = false;

    static constexpr Bounds above(double lo) {
        return {lo, std::numeric_limits<double>::infinity(), true, false};
    }
    static constexpr Bounds at_least(double lo) {
        return {lo, std::numeric_limits<double>::infinity(), false, false};
    }
    static constexpr Bounds closed(double lo, double hi) { return {lo, hi, false, false}; }
    static constexpr Bounds open(double lo, double hi) { return {lo, hi, true, true}; }
    static constexpr Bounds closed_open(double lo, double hi) { return {lo, hi, false, true}; }

    bool contains(double v) const;
    // "> 0", ">= 1", "in [0, 1)", or "" when unbounded.
    std::string describe() const;
};

class JsonCursor {
  public:
    JsonCursor(const JsonDocument& document, const nlohmann::ordered_json& value,
               std::string pointer);

    const std::string& pointer() const { return pointer_; }
    const JsonDocument& document() const { return *document_; }

    bool is_object() const;
    bool is_array() const;
    bool is_number() const;
    bool is_string() const;
    // "3", "\"abc\"", "an array of 2 elements", "an object": what a message says it got.
    std::string describe() const;

    // Throws SceneError at this value: `message`, or "expected <what>, got <describe()>".
    [[noreturn]] void fail(std::string message) const;
    [[noreturn]] void fail_expected(std::string_view what) const;

    // --- objects: every key asked for is remembered for reject_unknown_keys.
    void expect_object() const;
    bool has(std::string_view key);
    std::optional<JsonCursor> get(std::string_view key);
    // Fails "missing required key" at the object, or as an unknown key when an unread key is a
    // near miss of `key` (the likelier mistake).
    JsonCursor require(std::string_view key);
    // All members in file order (for maps such as `materials`); marks every key as read.
    std::vector<std::pair<std::string, JsonCursor>> members();
    // Fails at the first key (in file order) not asked for: with a "did you mean" for a near miss
    // of an asked key, else listing the keys asked for.
    void reject_unknown_keys() const;
    // The keys of the object, in file order.
    std::vector<std::string> keys() const;

    // --- arrays
    std::vector<JsonCursor> elements() const;
    // Exactly n elements; else fails "expected <what>, got ...".
    std::vector<JsonCursor> elements(size_t n, std::string_view what) const;
    // The number of elements; fails unless this is an array.
    size_t array_size() const;
    // An array of numbers as floats, each as number_f(bounds) reads it; fails at the first that
    // is not. For arrays of millions (medium grids): no cursor is made per element.
    std::vector<float> float_array(const Bounds& bounds) const;

    // --- scalars (all numbers finite)
    double number(const Bounds& bounds = {}) const;
    // A number stored as a float: also within float range.
    float number_f(const Bounds& bounds = {}) const;
    // An integer (a number with no fractional part, so 16.0 counts) within bounds and int range.
    int integer(const Bounds& bounds = {}) const;
    uint64_t unsigned_integer() const;
    bool boolean() const;
    std::string string() const;
    // A string that must be one of `names`; else "unknown <what> "x"; expected one of: a, b".
    std::string_view choice(std::string_view what, std::span<const std::string_view> names) const;
    // [x, y, z] of finite numbers (float range for vec3f).
    Vec3d vec3() const;
    Vec3f vec3f() const;
    // A colour: one number (grey) or [r, g, b], every component within bounds.
    Rgb colour(const Bounds& bounds) const;

  private:
    const JsonDocument* document_;
    const nlohmann::ordered_json* value_;
    std::string pointer_;
    std::vector<std::string> asked_;
};

// A string as a JSON literal, quotes and escapes included, for messages.
std::string json_quoted(std::string_view s);

}  // namespace candela
