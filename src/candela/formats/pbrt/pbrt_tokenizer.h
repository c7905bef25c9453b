#pragma once
// The tokens of one pbrt-v4 scene file (pbrt-v4's src/pbrt/parser.cpp, Tokenizer): quoted strings
// (escapes \b \f \n \r \t \\ \' \"; a line break or the end of the file inside one is an error),
// '[' and ']', and bare words (directives, numbers, true/false), separated by white space; '#'
// starts a comment that runs to the end of the line. The file is read in fixed-size chunks, so
// memory stays bounded however large the file; a token may straddle two chunks. gzip-compressed
// text is inflated chunk by chunk as it is read. A file whose first bytes are not text (a NUL or
// another control byte, or ill-formed UTF-8 outside a comment) is an error at the file: a binary
// file is never read as words.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "candela/formats/pbrt/pbrt_location.h"

namespace candela {
class GzipStream;
}

namespace candela::pbrt {

struct Token {
    enum class Kind { Word, String, Open, Close };
    Kind kind = Kind::Word;
    std::string text;                // a string's text without quotes, escapes decoded
    const Location* file = nullptr;  // the file (line and column 0) and its include chain
    int line = 0;
    int column = 0;
    Location location() const;
};

class Tokenizer {
  public:
    // Reads the open file `stream` (closed by the tokenizer) in chunks of `chunk_size` bytes.
    // `file` names it in locations; it must outlive the tokens. A token longer than
    // `max_token_bytes` is an error: a bound on memory, since a token is held whole.
    Tokenizer(std::FILE* stream, const Location* file, size_t chunk_size, size_t max_token_bytes);
    // Reads text held in memory, in the same chunks (so tests can make tokens straddle them).
    Tokenizer(std::string_view text, const Location* file, size_t chunk_size, size_t max_token_bytes);
    // Reads the text that gzip data `compressed` (a whole .gz file) inflates to.
    struct Gzip {
        std::string compressed;
    };
    Tokenizer(Gzip compressed, const Location* file, size_t chunk_size, size_t max_token_bytes);
    ~Tokenizer();
    Tokenizer(const Tokenizer&) = delete;
    Tokenizer& operator=(const Tokenizer&) = delete;

    // The next token into `out` (its string keeps its capacity); false at the end of the file.
    bool next(Token& out);

  private:
    bool refill();  // discards the buffer, reads the next chunk; false at the end of the input
    size_t read_chunk();
    // Looks at the first bytes as they arrive (`head_`): an error unless they are text.
    void check_text(bool at_end);
    // The byte at the read position, refilling as needed; -1 at the end of the input.
    int peek() { return pos_ < end_ || refill() ? static_cast<unsigned char>(buffer_[pos_]) : -1; }
    void skip_comment();
    void read_word(Token& out);
    void read_string(Token& out);
    void append(Token& out, size_t from);
    void check_length(const Token& out, size_t more) const;
    [[noreturn]] void fail_at(int line, int column, const std::string& message) const;
    // Saturated: a line over 2 GiB long (or a file of over 2^31 lines) gives wrong numbers, not UB.
    int column_at_pos() const {
        return int(std::min<uint64_t>(offset_ + pos_ - line_start_, uint64_t(std::numeric_limits<int>::max() - 1))) + 1;
    }

    std::FILE* stream_ = nullptr;
    std::string_view text_;  // the rest of the in-memory text
    std::string compressed_;  // gzip input: the compressed file, and its inflater
    std::unique_ptr<GzipStream> gzip_;
    std::string inflated_;     // a chunk from the inflater
    std::string head_;         // the first bytes, until check_text has seen enough
    bool checked_text_ = false;
    const Location* file_;
    size_t max_token_bytes_;
    std::vector<char> buffer_;
    size_t pos_ = 0;       // read position in buffer_
    size_t end_ = 0;       // bytes held in buffer_
    uint64_t offset_ = 0;  // the file offset of buffer_[0]
    int line_ = 1;
    uint64_t line_start_ = 0;  // the file offset of the current line's first byte
};

}  // namespace candela::pbrt
