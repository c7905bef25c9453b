#include "candela/formats/json/json_cursor.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <climits>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "candela/scene/enum_names.h"
#include "candela/formats/json/json_locator.h"

namespace candela {

using Json = nlohmann::ordered_json;

namespace {

// nlohmann's parse_error text is "[json.exception.parse_error.101] parse error at line 1, column
// 6: syntax error while parsing value - unexpected ']'; ...": we print our own location, so keep
// only what follows it.
std::string syntax_error_message(const std::string& what) {
    size_t at = what.find("parse error");
    size_t colon = at == std::string::npos ? std::string::npos : what.find(": ", at);
    return colon == std::string::npos ? what : what.substr(colon + 2);
}

// The character before `offset`, skipping whitespace ('\0' at the start).
char previous_token_char(std::string_view text, size_t offset) {
    while (offset > 0) {
        char c = text[--offset];
        if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return c;
    }
    return '\0';
}

// The key a pointer token names: "~1" stands for "/" and "~0" for "~" (RFC 6901).
std::string unescape_pointer_token(std::string_view token) {
    std::string key;
    for (size_t i = 0; i < token.size(); ++i) {
        if (token[i] == '~' && i + 1 < token.size()) {
            key += token[++i] == '1' ? '/' : '~';
        } else {
            key += token[i];
        }
    }
    return key;
}

bool is_literal_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-';
}

// Words for the syntax errors people make most: comments, single quotes and numbers JSON does not
// have, and text in another encoding than UTF-8 (nlohmann's message shows only where it stopped).
std::string syntax_hint(std::string_view text, size_t offset, std::string_view message) {
    std::string_view rest = text.substr(std::min(offset, text.size()));
    if (rest.starts_with("//") || rest.starts_with("/*")) return " (JSON allows no comments)";
    if (rest.starts_with('\'')) return " (JSON strings take double quotes)";
    if (rest.starts_with('-') || rest.starts_with('+')) rest.remove_prefix(1);
    for (std::string_view word : {"NaN", "nan", "Infinity", "infinity", "inf", "Inf"})
        if (rest.starts_with(word)) return " (JSON has no NaN or Infinity; give a finite number)";
    if (message.find("UTF-8") != std::string_view::npos) return " (scene files must be UTF-8)";
    return "";
}

// UTF-16 text (Windows editors write it) fails on its first byte with an unhelpful message.
bool looks_like_utf16(std::string_view text) {
    return text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF") ||
           (text.size() >= 2 && (text[0] == '\0' || text[1] == '\0'));
}

std::string_view number_at(std::string_view text, size_t offset) {
    size_t end = text.find_first_not_of("0123456789+-.eE", offset);
    return text.substr(offset, end == std::string_view::npos ? end : end - offset);
}

}  // namespace

std::string json_quoted(std::string_view s) { return Json(std::string(s)).dump(); }

// ---------------------------------------------------------------------------------------------
// JsonDocument

JsonDocument::JsonDocument(std::string text, std::string file)
    : text_(std::move(text)), file_(std::move(file)) {
    // nlohmann keeps the last of two equal keys; a repeated key is a typo waiting to render the
    // wrong scene, so note it while parsing (the callback sees every key with its object depth).
    bool duplicate = false;
    std::vector<std::set<std::string>> open_objects;
    auto note_keys = [&](int, Json::parse_event_t event, Json& parsed) {
        if (event == Json::parse_event_t::object_start) {
            open_objects.emplace_back();
        } else if (event == Json::parse_event_t::object_end) {
            open_objects.pop_back();
        } else if (event == Json::parse_event_t::key) {
            if (!open_objects.back().insert(parsed.get<std::string>()).second) duplicate = true;
        }
        return true;
    };
    if (looks_like_utf16(text_))
        throw SceneError(SourceLocation{file_, 1, 1, ""},
                         "the file is UTF-16 text (it starts with a byte order mark or a NUL byte); "
                         "scene files must be UTF-8");
    try {
        root_ = std::make_unique<Json>(Json::parse(text_, note_keys));
    } catch (const Json::parse_error& e) {
        // e.byte is the 1-based index of the last character read: the one that broke the syntax,
        // or the end of an unexpected number or literal, which is better shown at its start.
        size_t offset = e.byte > 0 ? e.byte - 1 : 0;
        while (offset > 0 && offset < text_.size() && is_literal_char(text_[offset]) &&
               is_literal_char(text_[offset - 1]))
            --offset;
        TextPosition p = text_position(text_, offset);
        std::string message = syntax_error_message(e.what());
        char bad = offset < text_.size() ? text_[offset] : '\0';
        if ((bad == ']' || bad == '}') && previous_token_char(text_, offset) == ',')
            message += " (JSON allows no comma after the last element)";
        message += syntax_hint(text_, offset, message);
        throw SceneError(SourceLocation{file_, p.line, p.column, ""}, "JSON " + message);
    } catch (const Json::out_of_range& e) {
        // The parser throws out_of_range only for a number that overflows a double (1e400).
        if (auto found = find_overflowing_number(text_)) {
            fail(found->pointer, fmt::format("expected a finite number, got {}",
                                             number_at(text_, found->span.value_offset)));
        }
        throw SceneError(SourceLocation{file_, 0, 0, ""}, e.what());
    }
    if (duplicate) {
        if (auto found = find_duplicate_key(text_)) {
            size_t slash = found->pointer.rfind('/');
            TextPosition p = text_position(text_, found->span.key_offset);
            throw SceneError(
                SourceLocation{file_, p.line, p.column, found->pointer.substr(0, slash)},
                "duplicate key " +
                    json_quoted(unescape_pointer_token(found->pointer.substr(slash + 1))));
        }
        throw SceneError(SourceLocation{file_, 0, 0, ""}, "duplicate key in a JSON object");
    }
}

JsonDocument::~JsonDocument() = default;

JsonCursor JsonDocument::root() const { return JsonCursor(*this, *root_, ""); }

SourceLocation JsonDocument::locate(const std::string& pointer, bool at_key) const {
    if (source_map_) {
        if (std::optional<SourceLocation> origin = source_map_(pointer)) {
            origin->json_pointer = pointer;
            return *origin;
        }
    }
    SourceLocation where{file_, 0, 0, pointer};
    if (auto span = find_json_pointer(text_, pointer)) {
        TextPosition p = text_position(text_, at_key ? span->key_offset : span->value_offset);
        where.line = p.line;
        where.column = p.column;
    }
    return where;
}

void JsonDocument::fail(const std::string& pointer, std::string message) const {
    throw SceneError(locate(pointer), std::move(message));
}

void JsonDocument::fail_at_key(const std::string& object_pointer, std::string_view key,
                               std::string message) const {
    SourceLocation where = locate(object_pointer + "/" + escape_pointer_token(key), true);
    where.json_pointer = object_pointer;
    throw SceneError(std::move(where), std::move(message));
}

// ---------------------------------------------------------------------------------------------
// Bounds

bool Bounds::contains(double v) const {
    bool above_lo = lo_open ? v > lo : v >= lo;
    bool below_hi = hi_open ? v < hi : v <= hi;
    return above_lo && below_hi;
}

std::string Bounds::describe() const {
    bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
    if (has_lo && has_hi)
        return fmt::format("in {}{}, {}{}", lo_open ? '(' : '[', lo, hi, hi_open ? ')' : ']');
    if (has_lo) return fmt::format("{} {}", lo_open ? ">" : ">=", lo);
    if (has_hi) return fmt::format("{} {}", hi_open ? "<" : "<=", hi);
    return "";
}

namespace {
std::string with_bounds(std::string_view what, const Bounds& b) {
    std::string range = b.describe();
    return range.empty() ? std::string(what) : fmt::format("{} {}", what, range);
}
}  // namespace

// ---------------------------------------------------------------------------------------------
// JsonCursor: kinds and failures

JsonCursor::JsonCursor(const JsonDocument& document, const Json& value, std::string pointer)
    : document_(&document), value_(&value), pointer_(std::move(pointer)) {}

bool JsonCursor::is_object() const { return value_->is_object(); }
bool JsonCursor::is_array() const { return value_->is_array(); }
bool JsonCursor::is_number() const { return value_->is_number(); }
bool JsonCursor::is_string() const { return value_->is_string(); }

std::string JsonCursor::describe() const {
    constexpr size_t kMaxShown = 40;
    switch (value_->type()) {
        case Json::value_t::object:
            return value_->empty() ? "an empty object" : "an object";
        case Json::value_t::array: {
            if (value_->empty()) return "an empty array";
            // A short array of plain values reads best as itself: "got [0, 1]".
            bool plain = std::none_of(value_->begin(), value_->end(),
                                      [](const Json& e) { return e.is_structured(); });
            std::string shown = "[";
            for (size_t i = 0; plain && i < value_->size(); ++i)
                shown += (i > 0 ? ", " : "") + (*value_)[i].dump();
            shown += "]";
            if (plain && shown.size() <= kMaxShown) return shown;
            return fmt::format("an array of {} element{}", value_->size(),
                               value_->size() == 1 ? "" : "s");
        }
        case Json::value_t::string: {
            std::string s = value_->dump();
            return s.size() <= kMaxShown ? s : s.substr(0, kMaxShown - 4) + "...\"";
        }
        default:
            return value_->dump();
    }
}

void JsonCursor::fail(std::string message) const { document_->fail(pointer_, std::move(message)); }

void JsonCursor::fail_expected(std::string_view what) const {
    fail(fmt::format("expected {}, got {}", what, describe()));
}

// ---------------------------------------------------------------------------------------------
// JsonCursor: objects

void JsonCursor::expect_object() const {
    if (!value_->is_object()) fail_expected("an object");
}

bool JsonCursor::has(std::string_view key) {
    expect_object();
    if (std::find(asked_.begin(), asked_.end(), key) == asked_.end()) asked_.emplace_back(key);
    return value_->contains(std::string(key));
}

std::optional<JsonCursor> JsonCursor::get(std::string_view key) {
    if (!has(key)) return std::nullopt;
    const Json& member = value_->at(std::string(key));
    return JsonCursor(*document_, member, pointer_ + "/" + escape_pointer_token(key));
}

JsonCursor JsonCursor::require(std::string_view key) {
    if (auto member = get(key)) return *member;
    const std::string_view wanted[] = {key};
    for (const std::string& k : keys()) {
        bool unread = std::find(asked_.begin(), asked_.end(), k) == asked_.end();
        if (unread && closest_name(k, wanted))
            document_->fail_at_key(
                pointer_, k,
                fmt::format("unknown key {} (did you mean {}?)", json_quoted(k), json_quoted(key)));
    }
    fail(fmt::format("missing required key {}", json_quoted(key)));
}

std::vector<std::pair<std::string, JsonCursor>> JsonCursor::members() {
    expect_object();
    std::vector<std::pair<std::string, JsonCursor>> out;
    for (const auto& [key, member] : value_->items()) {
        if (std::find(asked_.begin(), asked_.end(), key) == asked_.end()) asked_.push_back(key);
        out.emplace_back(
            key, JsonCursor(*document_, member, pointer_ + "/" + escape_pointer_token(key)));
    }
    return out;
}

std::vector<std::string> JsonCursor::keys() const {
    expect_object();
    std::vector<std::string> out;
    for (const auto& item : value_->items()) out.push_back(item.key());
    return out;
}

void JsonCursor::reject_unknown_keys() const {
    std::vector<std::string_view> known(asked_.begin(), asked_.end());
    for (const std::string& k : keys()) {
        if (std::find(asked_.begin(), asked_.end(), k) != asked_.end()) continue;
        std::string message = "unknown key " + json_quoted(k);
        if (auto hint = closest_name(k, known)) {
            message += fmt::format(" (did you mean {}?)", json_quoted(*hint));
        } else if (!known.empty()) {
            message += "; expected one of: " + names_list(known);
        }
        document_->fail_at_key(pointer_, k, std::move(message));
    }
}

// ---------------------------------------------------------------------------------------------
// JsonCursor: arrays

std::vector<JsonCursor> JsonCursor::elements() const {
    if (!value_->is_array()) fail_expected("an array");
    std::vector<JsonCursor> out;
    for (size_t i = 0; i < value_->size(); ++i)
        out.emplace_back(*document_, (*value_)[i], pointer_ + "/" + std::to_string(i));
    return out;
}

std::vector<JsonCursor> JsonCursor::elements(size_t n, std::string_view what) const {
    if (!value_->is_array() || value_->size() != n) fail_expected(what);
    return elements();
}

size_t JsonCursor::array_size() const {
    if (!value_->is_array()) fail_expected("an array");
    return value_->size();
}

std::vector<float> JsonCursor::float_array(const Bounds& bounds) const {
    const size_t n = array_size();
    std::vector<float> out(n);
    for (size_t i = 0; i < n; ++i) {
        const nlohmann::ordered_json& v = (*value_)[i];
        if (v.is_number()) {
            const double d = v.get<double>();
            const auto f = static_cast<float>(d);
            if (std::abs(d) <= double(FLT_MAX) && bounds.contains(d) && bounds.contains(double(f))) {
                out[i] = f;
                continue;
            }
        }
        // The element's own cursor says what is wrong, located at it.
        out[i] = JsonCursor(*document_, v, pointer_ + "/" + std::to_string(i)).number_f(bounds);
    }
    return out;
}

// ---------------------------------------------------------------------------------------------
// JsonCursor: scalars

double JsonCursor::number(const Bounds& bounds) const {
    if (!value_->is_number()) fail_expected(with_bounds("a number", bounds));
    // The parser already refused numbers beyond double range, so every number here is finite.
    double v = value_->get<double>();
    if (!bounds.contains(v)) fail_expected(with_bounds("a number", bounds));
    return v;
}

float JsonCursor::number_f(const Bounds& bounds) const {
    double v = number(bounds);
    if (std::abs(v) > double(FLT_MAX))
        fail_expected(fmt::format("a number within float range (magnitude <= {})", FLT_MAX));
    // Rounding to float may cross a bound (an exposure of 0.9999999999 becomes 1.0f, a tiny
    // positive fov becomes 0): the value used is the float, so check it.
    auto f = static_cast<float>(v);
    if (!bounds.contains(double(f)))
        fail(fmt::format("expected {}, got {} (which is {} as a float)",
                         with_bounds("a number", bounds), describe(), f));
    return f;
}

int JsonCursor::integer(const Bounds& bounds) const {
    std::string what = with_bounds("an integer", bounds);
    if (!value_->is_number()) fail_expected(what);
    double v = value_->get<double>();
    if (std::floor(v) != v) fail_expected(what);
    if (!bounds.contains(v)) fail_expected(what);
    if (v > double(INT_MAX)) fail_expected(fmt::format("an integer <= {}", INT_MAX));
    if (v < double(INT_MIN)) fail_expected(fmt::format("an integer >= {}", INT_MIN));
    return static_cast<int>(v);
}

uint64_t JsonCursor::unsigned_integer() const {
    const std::string what =
        fmt::format("an integer in [0, {}]", std::numeric_limits<uint64_t>::max());
    if (value_->is_number_unsigned()) return value_->get<uint64_t>();
    if (!value_->is_number_float()) fail_expected(what);  // also a negative integer
    // 2^64 is exactly representable as a double; anything below it that is integral fits.
    double v = value_->get<double>();
    if (std::floor(v) != v || v < 0.0 || v >= 18446744073709551616.0) fail_expected(what);
    return static_cast<uint64_t>(v);
}

bool JsonCursor::boolean() const {
    if (!value_->is_boolean()) fail_expected("true or false");
    return value_->get<bool>();
}

std::string JsonCursor::string() const {
    if (!value_->is_string()) fail_expected("a string");
    return value_->get<std::string>();
}

std::string_view JsonCursor::choice(std::string_view what,
                                    std::span<const std::string_view> names) const {
    if (!value_->is_string())
        fail_expected(fmt::format("a {} (one of: {})", what, names_list(names)));
    const std::string& s = value_->get_ref<const std::string&>();
    for (std::string_view n : names)
        if (n == s) return n;
    fail(
        fmt::format("unknown {} {}; expected one of: {}", what, json_quoted(s), names_list(names)));
}

Vec3d JsonCursor::vec3() const {
    std::vector<JsonCursor> e = elements(3, "an array of 3 numbers [x, y, z]");
    return {e[0].number(), e[1].number(), e[2].number()};
}

Vec3f JsonCursor::vec3f() const {
    std::vector<JsonCursor> e = elements(3, "an array of 3 numbers [x, y, z]");
    return {e[0].number_f(), e[1].number_f(), e[2].number_f()};
}

Rgb JsonCursor::colour(const Bounds& bounds) const {
    if (value_->is_number()) return Rgb(number_f(bounds));
    if (!value_->is_array() || value_->size() != 3)
        fail_expected(
            with_bounds("a colour: a number or an array of 3 numbers [r, g, b], each", bounds));
    std::vector<JsonCursor> e = elements();
    return {e[0].number_f(bounds), e[1].number_f(bounds), e[2].number_f(bounds)};
}

}  // namespace candela
