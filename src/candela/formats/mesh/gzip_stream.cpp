#include "candela/formats/mesh/gzip_stream.h"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <limits>

#include "candela/core/error.h"

namespace candela {

bool is_gzip(std::string_view bytes) {
    return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
           static_cast<unsigned char>(bytes[1]) == 0x8b;
}

struct GzipStream::State {
    z_stream z{};
    std::string_view compressed;
    std::string file_name;
    bool ended = false;

    [[noreturn]] void fail(const std::string& message) const {
        throw SceneError(SourceLocation{file_name, 0, 0, {}}, message);
    }
    size_t consumed() const { return compressed.size() - z.avail_in; }
};

GzipStream::GzipStream(std::string_view compressed, std::string file_name) : state_(std::make_unique<State>()) {
    state_->compressed = compressed;
    state_->file_name = std::move(file_name);
    if (!is_gzip(compressed)) state_->fail("not gzip-compressed data (no gzip header)");
    state_->z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
    state_->z.avail_in = 0;
    // 16 + MAX_WBITS: a gzip wrapper (header and CRC-32 trailer, both checked), not raw zlib.
    if (inflateInit2(&state_->z, 16 + MAX_WBITS) != Z_OK) state_->fail("cannot start inflating gzip data (zlib)");
}

GzipStream::~GzipStream() { inflateEnd(&state_->z); }

bool GzipStream::inflate_some(std::string& out, size_t max_bytes) {
    State& s = *state_;
    // zlib's counters are 32-bit: input goes in pieces of at most 1 GiB; output comes in pieces of
    // 1 MiB, so that `out` grows (geometrically) by what arrives rather than by what was asked.
    constexpr size_t kMaxPiece = size_t{1} << 30, kOutputPiece = size_t{1} << 20;
    size_t produced = 0;
    while (!s.ended && produced < max_bytes) {
        if (s.z.avail_in == 0) {
            const size_t offset = static_cast<size_t>(reinterpret_cast<const char*>(s.z.next_in) - s.compressed.data());
            s.z.avail_in = static_cast<uInt>(std::min(kMaxPiece, s.compressed.size() - offset));
        }
        const size_t want = std::min(max_bytes - produced, kOutputPiece);
        const size_t old_size = out.size();
        out.resize(old_size + want);
        s.z.next_out = reinterpret_cast<Bytef*>(out.data() + old_size);
        s.z.avail_out = static_cast<uInt>(want);
        const bool had_input = s.z.avail_in > 0;
        const int status = inflate(&s.z, Z_NO_FLUSH);
        const size_t got = want - s.z.avail_out;
        out.resize(old_size + got);
        produced += got;
        if (status == Z_STREAM_END) {
            // Another member may follow (RFC 1952 2.2); anything else after a member is ignored.
            const std::string_view rest = s.compressed.substr(s.consumed());
            if (is_gzip(rest)) {
                if (inflateReset(&s.z) != Z_OK) s.fail("cannot restart inflating gzip data (zlib)");
            } else {
                s.ended = true;
            }
            continue;
        }
        if (status == Z_DATA_ERROR || status == Z_NEED_DICT)
            s.fail(fmt::format("corrupt gzip data ({}) near compressed byte {}",
                               s.z.msg ? s.z.msg : "invalid data", s.consumed()));
        if (status == Z_MEM_ERROR) s.fail("out of memory while inflating gzip data");
        // Z_BUF_ERROR (no progress possible) or Z_OK without output: with all the input given and
        // the member not ended, the stream was cut short.
        if ((status == Z_BUF_ERROR || got == 0) && !had_input && s.consumed() == s.compressed.size())
            s.fail("the gzip data ends before the stream does (file truncated?)");
        if (status != Z_OK && status != Z_BUF_ERROR)
            s.fail(fmt::format("cannot inflate gzip data (zlib status {})", status));
    }
    return !s.ended;
}

void GzipStream::inflate_rest(std::string& out) {
    while (inflate_some(out, std::numeric_limits<size_t>::max())) {
    }
}

}  // namespace candela
