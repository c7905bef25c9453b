#include "candela/render/job/checkpoint_codec.h"

#include <fmt/format.h>

#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "candela/core/atomic_file.h"
#include "candela/core/error.h"
#include "candela/core/hash64.h"

namespace candela::checkpoint_codec {

namespace fs = std::filesystem;

namespace {

uint64_t checksum(std::string_view bytes) {
    Hash64 hash;
    hash.add(bytes.data(), bytes.size());
    return hash.value();
}

}  // namespace

void fail(const fs::path& file, const std::string& message) {
    throw SceneError(SourceLocation{file.string(), 0, 0, ""}, message);
}

void Writer::f64(double v) { u64(std::bit_cast<uint64_t>(v)); }

double Reader::f64() { return std::bit_cast<double>(u64()); }

std::string Reader::string() {
    uint32_t n = u32();
    if (n > kMaxString) overlong_ = true;
    if (overlong_ || data_.size() - at_ < n) return fail_string();
    std::string s(data_.substr(at_, n));
    at_ += n;
    return s;
}

uint64_t Reader::bytes(size_t n) {
    if (truncated_ || overlong_ || data_.size() - at_ < n) {
        truncated_ = !overlong_;
        return 0;
    }
    uint64_t v = 0;
    for (size_t i = 0; i < n; ++i) v |= uint64_t(static_cast<unsigned char>(data_[at_ + i])) << (8 * i);
    at_ += n;
    return v;
}

void write_common_header(Writer& w, uint32_t format, const RenderIdentity& identity, uint32_t samples_done,
                         uint64_t dropped_samples) {
    w.out.append(kMagic);
    w.u32(format);
    write_identity_start(w, identity);
    w.u32(uint32_t(identity.width));
    w.u32(uint32_t(identity.height));
    w.u32(samples_done);
    w.u64(dropped_samples);
}

void write_identity_start(Writer& w, const RenderIdentity& identity) {
    w.string(identity.candela_version);
    w.string(identity.integrator);
    w.string(identity.sampler);
    w.u64(identity.content_hash);
    w.u64(identity.seed);
}

void read_identity_start(Reader& r, RenderIdentity& identity) {
    identity.candela_version = r.string();
    identity.integrator = r.string();
    identity.sampler = r.string();
    identity.content_hash = r.u64();
    identity.seed = r.u64();
}

CommonHeader read_common_header(const fs::path& file, Reader& r, uint64_t size) {
    CommonHeader h;
    h.format = r.u32();
    if (!r.truncated() && (h.format < kFormatVersion || h.format > kFilmValuesFormatVersion))
        fail(file, fmt::format("checkpoint format version {}; this candela reads versions {} to {}", h.format,
                               kFormatVersion, kFilmValuesFormatVersion));
    RenderIdentity& id = h.identity;
    read_identity_start(r, id);
    const uint32_t width = r.u32(), height = r.u32();
    h.samples_done = r.u32();
    h.dropped_samples = r.u64();
    if (r.overlong()) fail(file, "corrupt checkpoint header: a name longer than any candela writes");
    if (r.truncated())
        fail(file, fmt::format("truncated checkpoint: {} bytes, the header alone is longer", size));
    if (width < 1 || height < 1 || width > uint32_t(kMaxResolution) || height > uint32_t(kMaxResolution))
        fail(file, fmt::format("corrupt checkpoint header: resolution {}x{}", width, height));
    id.width = int(width);
    id.height = int(height);
    return h;
}

uint64_t file_size_of(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) fail(file, "checkpoint not found");
    if (fs::is_directory(file, ec)) fail(file, "is a folder, not a checkpoint file");
    const uintmax_t size = fs::file_size(file, ec);
    if (ec) fail(file, "cannot read checkpoint: " + ec.message());
    return size;
}

std::string read_bytes(const fs::path& file, uint64_t size) {
    std::ifstream in(file, std::ios::binary);
    if (!in) fail(file, fmt::format("cannot open checkpoint: {}", std::strerror(errno)));
    std::string data(size, '\0');
    in.read(data.data(), std::streamsize(size));
    if (uint64_t(in.gcount()) != size) fail(file, "cannot read checkpoint: it changed while being read");
    return data;
}

std::string read_file_start(const fs::path& file, uint64_t size, uint64_t bytes) {
    std::string data = read_bytes(file, std::min(size, bytes));
    if (data.compare(0, kMagic.size(), kMagic) != 0) {
        if (data.size() < kMagic.size() && !data.empty() && kMagic.starts_with(data))
            fail(file, fmt::format("truncated checkpoint: {} bytes", data.size()));
        fail(file, data.empty() ? "not a candela checkpoint: the file is empty"
                                : "not a candela checkpoint: it does not start with \"CNDLCKPT\"");
    }
    return data;
}

void check_checksum(const fs::path& file, std::string_view data) {
    const std::string_view contents = data.substr(0, data.size() - 8);
    if (Reader(data.substr(data.size() - 8)).u64() != checksum(contents))
        fail(file, "corrupt checkpoint: the checksum does not match its contents (the file was damaged or edited)");
}

void write_checksummed(const fs::path& file, Writer& w,
                       const std::function<void(Writer& w, const std::function<void()>& flush)>& body) {
    // Streamed in blocks, hashed on the way: no second copy of the values in memory.
    write_file_atomically(file, [&](const fs::path& temporary) {
        std::FILE* out = std::fopen(temporary.c_str(), "wb");
        if (!out) throw std::runtime_error(std::string("cannot create a temporary file: ") + std::strerror(errno));
        Hash64 hash;
        int error = 0;  // the first failure's errno
        auto put = [&](const std::string& bytes) {
            if (error == 0 && std::fwrite(bytes.data(), 1, bytes.size(), out) != bytes.size())
                error = errno != 0 ? errno : EIO;
        };
        auto flush = [&] {
            hash.add(w.out.data(), w.out.size());
            put(w.out);
            w.out.clear();
        };
        body(w, [&] {
            if (w.out.size() >= (1 << 16)) flush();
        });
        flush();
        w.u64(hash.value());
        put(w.out);
        if (std::fclose(out) != 0 && error == 0) error = errno;
        if (error != 0) throw std::runtime_error(std::string("write failed: ") + std::strerror(error));
    });
}

}  // namespace candela::checkpoint_codec
