#include "candela/formats/pbrt/pbrt_token_stream.h"

#include <cerrno>
#include <cstring>
#include <utility>

namespace candela::pbrt {

namespace fs = std::filesystem;

namespace {

fs::path identity_of(const fs::path& path) {
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(path, ec);
    if (ec) canonical = fs::absolute(path, ec).lexically_normal();
    return canonical;
}

// Reads what is left of `stream` (a whole compressed file, which is far smaller than its text).
std::string read_rest(std::FILE* stream, const Location& origin) {
    std::string bytes;
    char chunk[1 << 16];
    size_t got = 0;
    while ((got = std::fread(chunk, 1, sizeof chunk, stream)) > 0) bytes.append(chunk, got);
    if (std::ferror(stream)) {
        const int error = errno;
        std::fclose(stream);
        fail(origin, std::string("cannot read the file: ") + std::strerror(error));
    }
    std::fclose(stream);
    return bytes;
}

}  // namespace

std::unique_ptr<Tokenizer> TokenStream::tokenizer(std::FILE* stream, const Location* origin) const {
    unsigned char magic[2] = {0, 0};
    const size_t got = std::fread(magic, 1, sizeof magic, stream);
    const bool gzip = got == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
    if (!gzip) {
        // Back to the start; a stream that cannot seek was read to no more than its two bytes.
        if (std::fseek(stream, 0, SEEK_SET) != 0) {
            const int error = errno;
            std::fclose(stream);
            fail(*origin, std::string("cannot read the file: ") + std::strerror(error));
        }
        return std::make_unique<Tokenizer>(stream, origin, options_.chunk_size, options_.max_token_bytes);
    }
    std::string compressed(reinterpret_cast<const char*>(magic), 2);
    compressed += read_rest(stream, *origin);
    return std::make_unique<Tokenizer>(Tokenizer::Gzip{std::move(compressed)}, origin, options_.chunk_size,
                                       options_.max_token_bytes);
}

const Location* TokenStream::add_origin(std::string display_name, std::shared_ptr<const IncludeSite> from) {
    auto origin = std::make_unique<Location>();
    origin->file = std::move(display_name);
    origin->included_from = std::move(from);
    origins_.push_back(std::move(origin));
    return origins_.back().get();
}

void TokenStream::open_main_file(const fs::path& name) {
    const Location* origin = add_origin(name.generic_string(), nullptr);
    std::error_code ec;
    if (fs::is_directory(name, ec)) fail(*origin, "is a folder, not a pbrt-v4 scene file");
    std::FILE* stream = std::fopen(name.c_str(), "rb");
    if (!stream) {
        const int error = errno;
        fail(*origin, std::string("cannot open the scene: ") + std::strerror(error));
    }
    files_.push_back({tokenizer(stream, origin), origin, identity_of(name)});
}

void TokenStream::open_main_text(std::string_view text, const fs::path& name) {
    const Location* origin = add_origin(name.generic_string(), nullptr);
    files_.push_back({std::make_unique<Tokenizer>(text, origin, options_.chunk_size, options_.max_token_bytes), origin,
                      identity_of(name)});
}

void TokenStream::include(const std::string& name, const Token& directive) {
    const Location at = directive.location();
    if (name.empty()) fail(at, "an empty file name");
    // Relative to the including file's folder; where nothing is there, relative to the main
    // file's folder, which is where pbrt-v4 looks (its ResolveFilename), so scenes written for
    // pbrt-v4 whose nested includes name paths from the main folder open too.
    fs::path path = fs::path(name).is_absolute() ? fs::path(name) : fs::path(at.file).parent_path() / name;
    if (!fs::path(name).is_absolute() && files_.size() > 1) {
        std::error_code exists_ec;
        const fs::path from_main = fs::path(files_.front().origin->file).parent_path() / name;
        if (!fs::exists(path, exists_ec) && fs::exists(from_main, exists_ec)) path = from_main;
    }
    const std::string display_name = path.lexically_normal().generic_string();
    if (files_.size() >= size_t(options_.max_include_depth))
        fail(at,
             "\"" + name + "\": includes nest deeper than " + std::to_string(options_.max_include_depth) + " files");
    const fs::path identity = identity_of(path);
    for (size_t i = 0; i < files_.size(); ++i) {
        if (files_[i].identity != identity) continue;
        std::string chain;
        for (size_t j = i; j < files_.size(); ++j) chain += files_[j].origin->file + " -> ";
        fail(at, "include cycle: " + chain + display_name);
    }
    // Only regular files: a device (/dev/stdin, /dev/zero) would block or never end.
    std::error_code ec;
    if (fs::is_directory(path, ec)) fail(at, "\"" + display_name + "\" is a folder, not a file");
    if (fs::exists(path, ec) && !fs::is_regular_file(path, ec))
        fail(at, "\"" + display_name + "\" is not a regular file");
    std::FILE* stream = std::fopen(path.c_str(), "rb");
    if (!stream) {
        const int error = errno;
        fail(at, "cannot open \"" + display_name + "\": " + std::strerror(error));
    }
    const Location* origin = add_origin(display_name, std::make_shared<const IncludeSite>(IncludeSite{at}));
    files_.push_back({tokenizer(stream, origin), origin, identity});
}

bool TokenStream::read(Token& out) {
    while (!files_.empty()) {
        if (files_.back().tokens->next(out)) return true;
        files_.pop_back();
    }
    return false;
}

bool TokenStream::next(Token& out) {
    if (has_lookahead_) {
        std::swap(out, lookahead_);
        has_lookahead_ = false;
        return true;
    }
    return read(out);
}

const Token* TokenStream::peek() {
    if (!has_lookahead_) has_lookahead_ = read(lookahead_);
    return has_lookahead_ ? &lookahead_ : nullptr;
}

}  // namespace candela::pbrt
