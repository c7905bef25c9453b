#include "candela/core/error.h"

#include <string_view>

namespace candela {

namespace {

// The length of the well-formed UTF-8 sequence at the start of `s` (RFC 3629: no overlong forms,
// no surrogates, nothing above U+10FFFF), or 0.
size_t utf8_sequence_length(std::string_view s) {
    const auto byte = [&](size_t i) { return static_cast<unsigned char>(s[i]); };
    const unsigned char lead = byte(0);
    size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
    if (lead >= 0xC2 && lead <= 0xDF) {
        n = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        n = 3;
        if (lead == 0xE0) lo = 0xA0;
        if (lead == 0xED) hi = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        n = 4;
        if (lead == 0xF0) lo = 0x90;
        if (lead == 0xF4) hi = 0x8F;
    } else {
        return 0;
    }
    if (s.size() < n || byte(1) < lo || byte(1) > hi) return 0;
    for (size_t i = 2; i < n; ++i)
        if (byte(i) < 0x80 || byte(i) > 0xBF) return 0;
    return n;
}

// Messages quote user text (keys, words from mesh headers, bytes a parser stopped at). A line
// break would split the CLI's one error line, and bytes that are not UTF-8 garble a terminal, so
// control characters and malformed UTF-8 are shown as escapes (\n, \xFF).
std::string printable(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c >= 0x20 && c < 0x7F) {
            out += char(c);
            ++i;
        } else if (size_t n = c >= 0x80 ? utf8_sequence_length(s.substr(i)) : 0; n > 0) {
            out.append(s.substr(i, n));
            i += n;
        } else {
            constexpr char kHex[] = "0123456789ABCDEF";
            switch (c) {
                case '\n': out += "\\n"; break;
                case '\t': out += "\\t"; break;
                case '\r': out += "\\r"; break;
                default: out += {'\\', 'x', kHex[c >> 4], kHex[c & 15]};
            }
            ++i;
        }
    }
    return out;
}

std::string format_location(const SourceLocation& w, const std::string& message) {
    std::string out;
    if (!w.file.empty()) {
        out += printable(w.file);
        if (w.line > 0) {
            out += ":" + std::to_string(w.line);
            if (w.column > 0) out += ":" + std::to_string(w.column);
        }
        out += ": ";
    }
    if (!w.json_pointer.empty()) out += printable(w.json_pointer) + ": ";
    return out + message;
}
}  // namespace

SceneError::SceneError(SourceLocation where, std::string message)
    : std::runtime_error(format_location(where, printable(message))),
      where_(std::move(where)),
      message_(printable(message)) {}

std::string SceneError::formatted() const { return what(); }

void fail_in_file(const std::string& file, const std::string& message) {
    throw SceneError(SourceLocation{file, 0, 0, {}}, message);
}

void fail_in_file(const std::string& file, int line, const std::string& message) {
    throw SceneError(SourceLocation{file, line, 0, {}}, message);
}

}  // namespace candela
