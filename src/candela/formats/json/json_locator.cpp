#include "candela/formats/json/json_locator.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <functional>
#include <set>
#include <system_error>
#include <vector>

namespace candela {

namespace {

constexpr size_t kNoOffset = size_t(-1);

// One value met by the scanner: its pointer, where it is, its raw text when it is a number, and
// whether its key repeats an earlier key of the same object. Returning false stops the scan.
using Visitor = std::function<bool(const std::string& pointer, JsonSpan span,
                                   std::string_view number, bool duplicate_key)>;

// A walk over JSON text that reports every value, pre-order. It validates only what it needs to
// find its way; it runs on error paths only, so it favours clarity over speed. It keeps the open
// objects and arrays on a heap stack rather than recursing, so no nesting depth (a hostile file
// of 100000 '[') can exhaust the call stack.
class Scanner {
  public:
    Scanner(std::string_view text, Visitor visit) : text_(text), visit_(std::move(visit)) {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
    }

    void run() {
        Member next{kNoOffset, false};
        for (;;) {
            const Read read = value(next);
            if (read == Read::kFailed) return;
            if (read == Read::kOpened) continue;  // `next` is the new container's first member
            // A complete value: leave every container it completes, then find the next member.
            for (;;) {
                if (open_.empty()) return;  // the root value is complete
                Container& c = open_.back();
                pointer_.resize(c.pointer_size);
                skip_whitespace();
                if (peek(c.is_object ? '}' : ']')) {
                    ++pos_;
                    open_.pop_back();
                    continue;
                }
                if (!peek(',')) return;
                ++pos_;
                ++c.index;
                if (!begin_member(c, next)) return;
                break;
            }
        }
    }

  private:
    // An object or array being read: where its members' pointers start, how many came before.
    struct Container {
        bool is_object;
        size_t pointer_size;
        size_t index = 0;
        std::set<std::string> keys;
    };
    // What is known of the value about to be read: its key's offset and whether it repeats.
    struct Member {
        size_t key_offset;
        bool duplicate_key;
    };

    void skip_whitespace() {
        while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                       text_[pos_] == '\n' || text_[pos_] == '\r'))
            ++pos_;
    }

    bool peek(char c) const { return pos_ < text_.size() && text_[pos_] == c; }

    enum class Read { kFailed, kComplete, kOpened };

    // Reads one value at pos_: a scalar or an empty container whole (kComplete); of a non-empty
    // object or array only the opening, pushing it and setting `next` to its first member
    // (kOpened). kFailed stops the scan.
    Read value(Member& next) {
        skip_whitespace();
        if (pos_ >= text_.size()) return Read::kFailed;
        JsonSpan span{next.key_offset == kNoOffset ? pos_ : next.key_offset, pos_};
        char c = text_[pos_];
        std::string_view number;
        if (c == '-' || (c >= '0' && c <= '9')) number = number_token();
        if (!visit_(pointer_, span, number, next.duplicate_key)) return Read::kFailed;
        if (!number.empty()) return Read::kComplete;
        if (c == '{' || c == '[') {
            ++pos_;
            skip_whitespace();
            if (peek(c == '{' ? '}' : ']')) return ++pos_, Read::kComplete;
            open_.push_back(Container{c == '{', pointer_.size(), 0, {}});
            return begin_member(open_.back(), next) ? Read::kOpened : Read::kFailed;
        }
        if (c == '"') return string(nullptr) ? Read::kComplete : Read::kFailed;
        for (std::string_view literal : {"true", "false", "null"}) {
            if (text_.substr(pos_, literal.size()) == literal) {
                pos_ += literal.size();
                return Read::kComplete;
            }
        }
        return Read::kFailed;
    }

    // Extends the pointer to member `c.index` of `c`; for an object reads its key and colon.
    bool begin_member(Container& c, Member& next) {
        pointer_ += '/';
        if (!c.is_object) {
            pointer_ += std::to_string(c.index);
            next = {kNoOffset, false};
            return true;
        }
        skip_whitespace();
        const size_t key_offset = pos_;
        std::string key;
        if (!peek('"') || !string(&key)) return false;
        skip_whitespace();
        if (!peek(':')) return false;
        ++pos_;
        next = {key_offset, !c.keys.insert(key).second};
        pointer_ += escape_pointer_token(key);
        return true;
    }

    std::string_view number_token() {
        size_t start = pos_;
        while (pos_ < text_.size()) {
            char c = text_[pos_];
            if (!((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' ||
                  c == 'E'))
                break;
            ++pos_;
        }
        return text_.substr(start, pos_ - start);
    }

    // Reads a string literal at pos_; decodes it into `out` when given (keys are compared decoded,
    // so "\u0061" matches the pointer token "a").
    bool string(std::string* out) {
        ++pos_;
        while (pos_ < text_.size()) {
            char c = text_[pos_++];
            if (c == '"') return true;
            if (c != '\\') {
                if (out) *out += c;
                continue;
            }
            if (pos_ >= text_.size()) return false;
            char e = text_[pos_++];
            if (e == 'u') {
                uint32_t cp = 0;
                if (!hex4(cp)) return false;
                // A high surrogate followed by an escaped low surrogate encodes one code point.
                if (cp >= 0xD800 && cp < 0xDC00 && text_.substr(pos_, 2) == "\\u") {
                    pos_ += 2;
                    uint32_t low = 0;
                    if (!hex4(low)) return false;
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                }
                if (out) append_utf8(*out, cp);
                continue;
            }
            const std::string_view from = "\"\\/bfnrt", to = "\"\\/\b\f\n\r\t";
            size_t k = from.find(e);
            if (k == std::string_view::npos) return false;
            if (out) *out += to[k];
        }
        return false;
    }

    bool hex4(uint32_t& cp) {
        if (pos_ + 4 > text_.size()) return false;
        auto [end, ec] = std::from_chars(text_.data() + pos_, text_.data() + pos_ + 4, cp, 16);
        if (ec != std::errc() || end != text_.data() + pos_ + 4) return false;
        pos_ += 4;
        return true;
    }

    static void append_utf8(std::string& out, uint32_t cp) {
        if (cp < 0x80) {
            out += char(cp);
        } else if (cp < 0x800) {
            out += char(0xC0 | (cp >> 6));
            out += char(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += char(0xE0 | (cp >> 12));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        } else {
            out += char(0xF0 | (cp >> 18));
            out += char(0x80 | ((cp >> 12) & 0x3F));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        }
    }

    std::string_view text_;
    Visitor visit_;
    size_t pos_ = 0;
    std::string pointer_;          // of the value being read
    std::vector<Container> open_;  // the objects and arrays around it, outermost first
};


// The decimal order of magnitude of a JSON number token (1e400 -> 400, 0.002 -> -3), for telling
// overflow from underflow: from_chars reports both as out of range, but nlohmann-json only
// refuses overflow (an underflow reads as 0).
long long decimal_magnitude(std::string_view token) {
    size_t i = token.starts_with('-') ? 1 : 0;
    long long integer_digits = 0;  // mantissa digits before the point
    long long first_nonzero = -1;  // index of the first nonzero mantissa digit
    long long digit_index = 0;
    bool fraction = false;
    for (; i < token.size() && token[i] != 'e' && token[i] != 'E'; ++i) {
        if (token[i] == '.') {
            fraction = true;
            continue;
        }
        if (first_nonzero < 0 && token[i] != '0') first_nonzero = digit_index;
        if (!fraction) ++integer_digits;
        ++digit_index;
    }
    if (first_nonzero < 0) return 0;
    long long exponent = 0;
    if (i < token.size()) {
        ++i;
        bool negative = i < token.size() && token[i] == '-';
        if (i < token.size() && (token[i] == '-' || token[i] == '+')) ++i;
        // Saturate: an exponent of a trillion digits is as out of range as one of four.
        for (; i < token.size(); ++i)
            exponent = std::min(exponent * 10 + (token[i] - '0'), 1LL << 40);
        if (negative) exponent = -exponent;
    }
    return integer_digits - 1 - first_nonzero + exponent;
}

}  // namespace

TextPosition text_position(std::string_view text, size_t offset) {
    offset = std::min(offset, text.size());
    size_t start = text.substr(0, 3) == "\xEF\xBB\xBF" && offset >= 3 ? 3 : 0;
    TextPosition p;
    for (size_t i = start; i < offset; ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++p.line;
            p.column = 1;
        } else if ((c & 0xC0) != 0x80) {
            ++p.column;
        }
    }
    return p;
}

std::optional<JsonSpan> find_json_pointer(std::string_view text, std::string_view pointer) {
    std::optional<JsonSpan> found;
    Scanner(text, [&](const std::string& p, JsonSpan span, std::string_view, bool) {
        if (p == pointer) found = span;
        return true;
    }).run();
    return found;
}

std::optional<JsonFinding> find_duplicate_key(std::string_view text) {
    std::optional<JsonFinding> found;
    Scanner(text, [&](const std::string& p, JsonSpan span, std::string_view, bool duplicate) {
        if (duplicate) found = JsonFinding{p, span};
        return !duplicate;
    }).run();
    return found;
}

std::optional<JsonFinding> find_overflowing_number(std::string_view text) {
    std::optional<JsonFinding> found;
    Scanner(text, [&](const std::string& p, JsonSpan span, std::string_view number, bool) {
        if (number.empty()) return true;
        double v = 0.0;
        auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), v);
        if (ec == std::errc::result_out_of_range && decimal_magnitude(number) > 0) {
            found = JsonFinding{p, span};
            return false;
        }
        return true;
    }).run();
    return found;
}

std::string escape_pointer_token(std::string_view key) {
    std::string out;
    for (char c : key) {
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else {
            out += c;
        }
    }
    return out;
}

}  // namespace candela
