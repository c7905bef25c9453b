#include "candela/render/checkpoint.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "candela/core/atomic_file.h"
#include "candela/core/error.h"
#include "candela/core/hash64.h"
#include "candela/render/renderer.h"
#include "candela/scene/enum_names.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kMagic = "CNDLCKPT";
constexpr uint32_t kFormatVersion = 1;
constexpr uint32_t kWeightedFormatVersion = 2;  // with weight sums
constexpr uint32_t kMaxString = 64;
constexpr int kMaxSide = 32768;  // the scene loader's limit
constexpr size_t kBytesPerPixel = 3 * 8;
constexpr size_t kWeightedBytesPerPixel = 4 * 8;
// The longest header: magic, format version, three names of kMaxString bytes, hash, seed, width,
// height, samples done, dropped samples.
constexpr uint64_t kMaxHeaderBytes = 8 + 4 + 3 * (4 + kMaxString) + 8 + 8 + 4 + 4 + 4 + 8;

[[noreturn]] void fail(const fs::path& file, const std::string& message) {
    throw SceneError(SourceLocation{file.string(), 0, 0, ""}, message);
}

// Little-endian encoding into a byte string.
class Writer {
  public:
    void u32(uint32_t v) { bytes(v, 4); }
    void u64(uint64_t v) { bytes(v, 8); }
    void f64(double v) { u64(std::bit_cast<uint64_t>(v)); }
    void string(std::string_view s) {
        u32(uint32_t(s.size()));
        out.append(s);
    }
    std::string out;

  private:
    void bytes(uint64_t v, int n) {
        for (int i = 0; i < n; ++i) out.push_back(char((v >> (8 * i)) & 0xff));
    }
};

// Little-endian decoding. Reading past the end, or a string longer than kMaxString, fails the
// reader: it then returns zeros and empty strings, and says why once the header is read.
class Reader {
  public:
    explicit Reader(std::string_view data) : data_(data) {}
    uint32_t u32() { return uint32_t(bytes(4)); }
    uint64_t u64() { return bytes(8); }
    std::string string() {
        uint32_t n = u32();
        if (n > kMaxString) overlong_ = true;
        if (overlong_ || data_.size() - at_ < n) return fail_string();
        std::string s(data_.substr(at_, n));
        at_ += n;
        return s;
    }
    bool truncated() const { return truncated_; }
    bool overlong() const { return overlong_; }
    size_t position() const { return at_; }

  private:
    uint64_t bytes(size_t n) {
        if (truncated_ || overlong_ || data_.size() - at_ < n) {
            truncated_ = !overlong_;
            return 0;
        }
        uint64_t v = 0;
        for (size_t i = 0; i < n; ++i) v |= uint64_t(static_cast<unsigned char>(data_[at_ + i])) << (8 * i);
        at_ += n;
        return v;
    }
    std::string fail_string() {
        truncated_ = !overlong_;
        return {};
    }
    std::string_view data_;
    size_t at_ = 0;
    bool truncated_ = false;
    bool overlong_ = false;
};

// The file's size, after checking that it is a readable file.
uint64_t checkpoint_size(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) fail(file, "checkpoint not found");
    if (fs::is_directory(file, ec)) fail(file, "is a folder, not a checkpoint file");
    const uintmax_t size = fs::file_size(file, ec);
    if (ec) fail(file, "cannot read checkpoint: " + ec.message());
    return size;
}

// The first `size` bytes of the file.
std::string read_bytes(const fs::path& file, uint64_t size) {
    std::ifstream in(file, std::ios::binary);
    if (!in) fail(file, fmt::format("cannot open checkpoint: {}", std::strerror(errno)));
    std::string data(size, '\0');
    in.read(data.data(), std::streamsize(size));
    if (uint64_t(in.gcount()) != size) fail(file, "cannot read checkpoint: it changed while being read");
    return data;
}

uint64_t checksum(std::string_view bytes) {
    Hash64 hash;
    hash.add(bytes.data(), bytes.size());
    return hash.value();
}

}  // namespace

RenderIdentity render_identity(const Scene& scene, uint64_t content_hash) {
    RenderIdentity id;
    id.candela_version = CANDELA_VERSION;
    id.integrator = integrator_type_name(scene.integrator.type);
    id.sampler = sampler_type_name(scene.sampler.type);
    id.content_hash = content_hash;
    id.seed = scene.sampler.seed;
    const PixelBounds bounds = render_pixel_bounds(scene);
    id.width = bounds.width();
    id.height = bounds.height();
    return id;
}

void write_checkpoint(const fs::path& file, const RenderIdentity& identity, const RenderState& state) {
    const Film& film = state.film;
    Writer w;
    w.out.append(kMagic);
    w.u32(film.weighted() ? kWeightedFormatVersion : kFormatVersion);
    w.string(identity.candela_version);
    w.string(identity.integrator);
    w.string(identity.sampler);
    w.u64(identity.content_hash);
    w.u64(identity.seed);
    w.u32(uint32_t(film.width()));
    w.u32(uint32_t(film.height()));
    w.u32(state.samples_done);
    w.u64(state.dropped_samples);
    // Streamed in blocks, hashed on the way: no second copy of the sums in memory.
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
        for (size_t i = 0; i < film.sums().size(); ++i) {
            for (double v : film.sums()[i]) w.f64(v);
            if (film.weighted()) w.f64(film.weights()[i]);
            if (w.out.size() >= (1 << 16)) flush();
        }
        flush();
        w.u64(hash.value());
        put(w.out);
        if (std::fclose(out) != 0 && error == 0) error = errno;
        if (error != 0) throw std::runtime_error(std::string("write failed: ") + std::strerror(error));
    });
}

Checkpoint read_checkpoint(const fs::path& file) {
    // The header first: a damaged or foreign file of any size is refused before it is read whole.
    const uint64_t size = checkpoint_size(file);
    std::string data = read_bytes(file, std::min<uint64_t>(size, kMaxHeaderBytes));
    if (data.compare(0, kMagic.size(), kMagic) != 0) {
        if (data.size() < kMagic.size() && !data.empty() && kMagic.starts_with(data))
            fail(file, fmt::format("truncated checkpoint: {} bytes", data.size()));
        fail(file, data.empty() ? "not a candela checkpoint: the file is empty"
                                : "not a candela checkpoint: it does not start with \"CNDLCKPT\"");
    }
    Reader r(std::string_view(data).substr(kMagic.size()));
    const uint32_t format = r.u32();
    if (!r.truncated() && format != kFormatVersion && format != kWeightedFormatVersion)
        fail(file, fmt::format("checkpoint format version {}; this candela reads versions {} and {}", format,
                               kFormatVersion, kWeightedFormatVersion));
    const bool weighted = format == kWeightedFormatVersion;
    const size_t bytes_per_pixel = weighted ? kWeightedBytesPerPixel : kBytesPerPixel;
    Checkpoint c;
    RenderIdentity& id = c.identity;
    id.candela_version = r.string();
    id.integrator = r.string();
    id.sampler = r.string();
    id.content_hash = r.u64();
    id.seed = r.u64();
    const uint32_t width = r.u32(), height = r.u32(), samples = r.u32();
    const uint64_t dropped = r.u64();
    if (r.overlong()) fail(file, "corrupt checkpoint header: a name longer than any candela writes");
    if (r.truncated())
        fail(file, fmt::format("truncated checkpoint: {} bytes, the header alone is longer", size));
    if (width < 1 || height < 1 || width > uint32_t(kMaxSide) || height > uint32_t(kMaxSide))
        fail(file, fmt::format("corrupt checkpoint header: resolution {}x{}", width, height));
    id.width = int(width);
    id.height = int(height);

    const size_t pixels = size_t(width) * size_t(height);
    const size_t header = kMagic.size() + r.position();
    const size_t expected = header + pixels * bytes_per_pixel + 8;
    if (size < expected)
        fail(file, fmt::format("truncated checkpoint: {} bytes, a {}x{} checkpoint has {}", size, width, height,
                               expected));
    if (size > expected)
        fail(file, fmt::format("corrupt checkpoint: {} bytes, {} more than a {}x{} checkpoint has", size,
                               size - expected, width, height));
    data = read_bytes(file, size);
    const std::string_view contents = std::string_view(data).substr(0, expected - 8);
    if (Reader(std::string_view(data).substr(expected - 8)).u64() != checksum(contents))
        fail(file, "corrupt checkpoint: the checksum does not match its contents (the file was damaged or edited)");

    Reader body(std::string_view(data).substr(header, pixels * bytes_per_pixel));
    std::vector<PixelSum> sums(pixels);
    std::vector<double> weights(weighted ? pixels : 0);
    auto finite = [&](double v, size_t i) {
        if (!std::isfinite(v))
            fail(file, fmt::format("corrupt checkpoint: pixel ({}, {}) has a non-finite sum", i % width, i / width));
        return v;
    };
    for (size_t i = 0; i < pixels; ++i) {
        for (double& v : sums[i]) v = finite(std::bit_cast<double>(body.u64()), i);
        if (weighted) weights[i] = finite(std::bit_cast<double>(body.u64()), i);
    }
    c.state = RenderState{Film(id.width, id.height, std::move(sums), std::move(weights)), samples, dropped};
    return c;
}

void check_checkpoint_matches(const fs::path& file, const RenderIdentity& checkpoint, const RenderIdentity& render) {
    auto refuse = [&](const std::string& what) { fail(file, "cannot resume: " + what); };
    if (checkpoint.candela_version != render.candela_version)
        refuse(fmt::format("the checkpoint was written by candela {}, this is candela {}; another version may "
                           "compute different samples (render again, or resume with candela {})",
                           checkpoint.candela_version, render.candela_version, checkpoint.candela_version));
    if (checkpoint.width != render.width || checkpoint.height != render.height)
        refuse(fmt::format("the checkpoint is {}x{}, this render {}x{} (give the same --resolution)", checkpoint.width,
                           checkpoint.height, render.width, render.height));
    if (checkpoint.seed != render.seed)
        refuse(fmt::format("the checkpoint has seed {}, this render seed {} (give the same --seed)", checkpoint.seed,
                           render.seed));
    if (checkpoint.sampler != render.sampler)
        refuse(fmt::format("the checkpoint used sampler {}, this render {} (give the same --sampler)",
                           checkpoint.sampler, render.sampler));
    if (checkpoint.integrator != render.integrator)
        refuse(fmt::format("the checkpoint used integrator {}, this render {} (give the same --integrator)",
                           checkpoint.integrator, render.integrator));
    if (checkpoint.content_hash != render.content_hash)
        refuse(fmt::format("the checkpoint is of a different scene: its content hash is {:016x}, this scene's {:016x} "
                           "(the scene file or a file it names changed; only the sample count may)",
                           checkpoint.content_hash, render.content_hash));
}

}  // namespace candela
