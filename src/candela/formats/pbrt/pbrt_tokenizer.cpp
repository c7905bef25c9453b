#include "candela/formats/pbrt/pbrt_tokenizer.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <limits>
#include <utility>

#include "candela/formats/mesh/gzip_stream.h"

namespace candela::pbrt {

namespace {

constexpr bool is_space(int c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; }

// Bytes that end a bare word (pbrt-v4: white space, a quote, a bracket). '#' does not: "a#b" is
// one word, as in pbrt-v4.
constexpr std::array<bool, 256> kEndsWord = [] {
    std::array<bool, 256> table{};
    for (const unsigned char c : {' ', '\n', '\t', '\r', '"', '[', ']'}) table[c] = true;
    return table;
}();
inline bool ends_word(char c) { return kEndsWord[static_cast<unsigned char>(c)]; }

}  // namespace

Location Token::location() const {
    Location at = *file;
    at.line = line;
    at.column = column;
    return at;
}

Tokenizer::Tokenizer(std::FILE* stream, const Location* file, size_t chunk_size, size_t max_token_bytes)
    : stream_(stream), file_(file), max_token_bytes_(max_token_bytes), buffer_(std::max<size_t>(chunk_size, 1)) {}

Tokenizer::Tokenizer(std::string_view text, const Location* file, size_t chunk_size, size_t max_token_bytes)
    : text_(text),
      file_(file),
      max_token_bytes_(max_token_bytes),
      buffer_(std::clamp<size_t>(text.size(), 1, std::max<size_t>(chunk_size, 1))) {}

Tokenizer::Tokenizer(Gzip compressed, const Location* file, size_t chunk_size, size_t max_token_bytes)
    : compressed_(std::move(compressed.compressed)),
      file_(file),
      max_token_bytes_(max_token_bytes),
      buffer_(std::max<size_t>(chunk_size, 1)) {
    try {
        gzip_ = std::make_unique<GzipStream>(compressed_, file->file);
    } catch (const SceneError& e) {
        fail(*file_, e.message());
    }
}

Tokenizer::~Tokenizer() {
    if (stream_) std::fclose(stream_);
}

bool Tokenizer::refill() {
    offset_ += end_;
    pos_ = 0;
    end_ = read_chunk();
    // Every source fills the whole buffer but at its end.
    if (!checked_text_) check_text(end_ < buffer_.size());
    return end_ > 0;
}

size_t Tokenizer::read_chunk() {
    if (stream_) {
        const size_t got = std::fread(buffer_.data(), 1, buffer_.size(), stream_);
        if (got == 0 && std::ferror(stream_)) {
            const int error = errno;
            fail_at(line_, column_at_pos(), std::string("cannot read the file: ") + std::strerror(error));
        }
        return got;
    }
    if (gzip_) {
        // The inflater's errors (corrupt or truncated data) name the compressed byte offset: they
        // are located at the file, with its include chain.
        inflated_.clear();
        try {
            gzip_->inflate_some(inflated_, buffer_.size());
        } catch (const SceneError& e) {
            fail(*file_, e.message());
        }
        std::copy(inflated_.begin(), inflated_.end(), buffer_.begin());
        return inflated_.size();
    }
    const size_t got = std::min(text_.size(), buffer_.size());
    std::copy_n(text_.data(), got, buffer_.data());
    text_.remove_prefix(got);
    return got;
}

void Tokenizer::fail_at(int line, int column, const std::string& message) const {
    Location at = *file_;
    at.line = line;
    at.column = column;
    fail(at, message);
}

bool Tokenizer::next(Token& out) {
    for (;;) {
        const int c = peek();
        if (c < 0) return false;
        if (c == '\n') {
            ++pos_;
            if (line_ < std::numeric_limits<int>::max()) ++line_;
            line_start_ = offset_ + pos_;
        } else if (is_space(c)) {
            ++pos_;
        } else if (c == '#') {
            skip_comment();
        } else {
            out.file = file_;
            out.line = line_;
            out.column = column_at_pos();
            out.text.clear();
            if (c == '[' || c == ']') {
                out.kind = c == '[' ? Token::Kind::Open : Token::Kind::Close;
                out.text.push_back(char(c));
                ++pos_;
            } else if (c == '"') {
                out.kind = Token::Kind::String;
                ++pos_;
                read_string(out);
            } else {
                out.kind = Token::Kind::Word;
                read_word(out);
            }
            return true;
        }
    }
}

void Tokenizer::skip_comment() {
    // The line break stays, so that next() counts the line.
    for (;;) {
        const char* begin = buffer_.data() + pos_;
        const void* eol = std::memchr(begin, '\n', end_ - pos_);
        if (eol) {
            pos_ += size_t(static_cast<const char*>(eol) - begin);
            return;
        }
        pos_ = end_;
        if (!refill()) return;
    }
}

void Tokenizer::check_length(const Token& out, size_t more) const {
    if (out.text.size() + more > max_token_bytes_)
        fail_at(out.line, out.column, "a token longer than " + std::to_string(max_token_bytes_) + " bytes");
}

void Tokenizer::append(Token& out, size_t from) {
    check_length(out, pos_ - from);
    out.text.append(buffer_.data() + from, pos_ - from);
}

void Tokenizer::read_word(Token& out) {
    for (;;) {
        const size_t from = pos_;
        while (pos_ < end_ && !ends_word(buffer_[pos_])) ++pos_;
        append(out, from);
        if (pos_ < end_ || !refill()) return;
    }
}

namespace {

// The byte offset of the first byte in `s` that is not part of well-formed UTF-8 (RFC 3629: no
// overlong forms, no surrogates, nothing past U+10FFFF), or npos. A string's text goes into the
// JSON document the JSON loader reads, and JSON text is UTF-8.
std::string hex_byte(char c) {
    constexpr const char* kDigits = "0123456789ABCDEF";
    const auto b = static_cast<unsigned char>(c);
    return {kDigits[b >> 4], kDigits[b & 15]};
}

size_t first_ill_formed_utf8(const std::string& s) {
    for (size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        size_t n = 0;
        unsigned char lo = 0x80, hi = 0xBF;  // the range of the byte after the lead
        if (b < 0x80) n = 0;
        else if (b >= 0xC2 && b <= 0xDF) n = 1;
        else if (b >= 0xE0 && b <= 0xEF) n = 2, lo = b == 0xE0 ? 0xA0 : 0x80, hi = b == 0xED ? 0x9F : 0xBF;
        else if (b >= 0xF0 && b <= 0xF4) n = 3, lo = b == 0xF0 ? 0x90 : 0x80, hi = b == 0xF4 ? 0x8F : 0xBF;
        else return i;
        for (size_t k = 1; k <= n; ++k) {
            if (i + k >= s.size()) return i;
            const auto c = static_cast<unsigned char>(s[i + k]);
            if (c < (k == 1 ? lo : 0x80) || c > (k == 1 ? hi : 0xBF)) return i;
        }
        i += n + 1;
    }
    return std::string::npos;
}

// Bytes of text files: white space and everything from ' ' up, but no other control byte.
constexpr bool is_text_byte(unsigned char c) { return c >= 0x20 || (c >= '\t' && c <= '\r'); }

// Why the first bytes of a file, `head`, are not text, or "" when they are: a control byte (a
// NUL above all), or ill-formed UTF-8 outside a comment (pbrt-v4 reads no encoding but UTF-8,
// yet a comment in Latin-1 troubles neither it nor us). `complete` says `head` is the whole file;
// otherwise a character cut at its end is no fault.
std::string not_text(const std::string& head, bool complete) {
    bool in_comment = false;
    for (size_t i = 0; i < head.size();) {
        const auto c = static_cast<unsigned char>(head[i]);
        if (!is_text_byte(c)) return "a control byte 0x" + hex_byte(head[i]) + " at byte " + std::to_string(i + 1);
        if (c == '#') in_comment = true;
        if (c == '\n') in_comment = false;
        if (c < 0x80 || in_comment) {
            ++i;
            continue;
        }
        // One character: its lead byte says how long it is (at most 4 bytes).
        const size_t length = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
        const std::string character = head.substr(i, length);
        const bool cut = i + length > head.size() && !complete;
        if (!cut && first_ill_formed_utf8(character) != std::string::npos)
            return "ill-formed UTF-8 (0x" + hex_byte(head[i]) + " at byte " + std::to_string(i + 1) + ")";
        i += length;
    }
    return "";
}

}  // namespace

void Tokenizer::check_text(bool at_end) {
    // The first KiB decides; it arrives in one chunk but for the tiny chunks of tests.
    constexpr size_t kHeadBytes = 1024;
    head_.append(buffer_.data(), std::min(end_, kHeadBytes - head_.size()));
    if (head_.size() < kHeadBytes && !at_end) return;
    checked_text_ = true;
    const std::string why = not_text(head_, at_end);
    if (!why.empty()) fail(*file_, "is a binary file, not pbrt-v4 scene text (" + why + ")");
    head_ = std::string();
}

void Tokenizer::read_string(Token& out) {
    for (;;) {
        const size_t from = pos_;
        while (pos_ < end_) {
            const char c = buffer_[pos_];
            if (c == '"' || c == '\\' || c == '\n') break;
            ++pos_;
        }
        append(out, from);
        const int c = peek();
        if (c < 0) fail_at(out.line, out.column, "unterminated string (the file ends inside it)");
        if (c == '\n') fail_at(out.line, out.column, "unterminated string (a line break inside it)");
        if (c == '"') {
            ++pos_;
            if (const size_t bad = first_ill_formed_utf8(out.text); bad != std::string::npos)
                fail_at(out.line, out.column,
                        "a string with an ill-formed UTF-8 byte (0x" + hex_byte(out.text[bad]) + " at byte " +
                            std::to_string(bad + 1) + " of the string); scene files must be UTF-8");
            return;
        }
        if (c == '\\') {
            const int escape_column = column_at_pos();
            ++pos_;
            const int e = peek();
            char decoded = 0;
            switch (e) {
                case 'b': decoded = '\b'; break;
                case 'f': decoded = '\f'; break;
                case 'n': decoded = '\n'; break;
                case 'r': decoded = '\r'; break;
                case 't': decoded = '\t'; break;
                case '\\': decoded = '\\'; break;
                case '\'': decoded = '\''; break;
                case '"': decoded = '"'; break;
                case -1: fail_at(out.line, out.column, "unterminated string (the file ends inside it)");
                default:
                    fail_at(line_, escape_column,
                            std::string("unknown escape \\") + char(e) +
                                " in a string (pbrt-v4 knows \\b \\f \\n \\r \\t \\\\ \\' \\\")");
            }
            ++pos_;
            check_length(out, 1);
            out.text.push_back(decoded);
        }
    }
}

}  // namespace candela::pbrt
