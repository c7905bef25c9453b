#pragma once
// The tokens of a pbrt-v4 scene and the files it includes, as one stream: Include and Import
// push a file (its path relative to the including file's folder), and the end of an included
// file continues the file that included it, as in pbrt-v4. Holds one token of lookahead, the
// open files (each a bounded chunk buffer), and the names of every file opened, which tokens
// point to. A file whose first bytes are gzip's magic number is read inflated, whatever its name
// (pbrt-v4 inflates files named .gz).
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "candela/formats/pbrt/pbrt_parser.h"
#include "candela/formats/pbrt/pbrt_tokenizer.h"

namespace candela::pbrt {

class TokenStream {
  public:
    explicit TokenStream(const ParseOptions& options) : options_(options) {}

    // The main file: `name` as the user gave it. A file that cannot be opened is an error.
    void open_main_file(const std::filesystem::path& name);
    void open_main_text(std::string_view text, const std::filesystem::path& name);
    // Include/Import `name` at `directive`: an error there if the file cannot be opened, if it
    // is already open (a cycle) or if the includes nest deeper than the options allow.
    void include(const std::string& name, const Token& directive);

    // The next token into `out`; false after the last token of the main file.
    bool next(Token& out);
    // The next token without taking it; null at the end.
    const Token* peek();

  private:
    struct OpenFile {
        std::unique_ptr<Tokenizer> tokens;
        const Location* origin;          // its name and include chain
        std::filesystem::path identity;  // the canonical path, to find cycles
    };
    const Location* add_origin(std::string display_name, std::shared_ptr<const IncludeSite> from);
    // The tokenizer of the open file `stream` (it takes it), inflating it if it is gzip data.
    std::unique_ptr<Tokenizer> tokenizer(std::FILE* stream, const Location* origin) const;
    bool read(Token& out);

    ParseOptions options_;
    std::vector<OpenFile> files_;                     // innermost last
    std::vector<std::unique_ptr<Location>> origins_;  // every file opened: tokens point here
    Token lookahead_;
    bool has_lookahead_ = false;
};

}  // namespace candela::pbrt
