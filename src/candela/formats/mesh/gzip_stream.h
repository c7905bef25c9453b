#pragma once
// gzip-compressed data (RFC 1952) held in memory, inflated with zlib in pieces, so that a reader
// can look at the start of the data (a PLY header) before it decides to inflate the rest.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace candela {

// True when `bytes` start with gzip's magic number (1f 8b).
bool is_gzip(std::string_view bytes);

class GzipStream {
  public:
    // `compressed` must outlive the stream; `file_name` names it in errors.
    GzipStream(std::string_view compressed, std::string file_name);
    ~GzipStream();
    GzipStream(const GzipStream&) = delete;
    GzipStream& operator=(const GzipStream&) = delete;

    // Appends up to `max_bytes` inflated bytes to `out`; returns false once the stream has ended
    // (then nothing more will come). Members concatenated one after another (as `cat a.gz b.gz`
    // makes) inflate as one stream; bytes after the last member that are not a gzip member are
    // ignored, as zlib's gzread and so pbrt-v4 ignore them. Throws SceneError naming the file for
    // corrupt data (with zlib's reason and the compressed byte offset) or a truncated stream.
    bool inflate_some(std::string& out, size_t max_bytes);

    // Inflates everything that is left, appending it to `out`.
    void inflate_rest(std::string& out);

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace candela
