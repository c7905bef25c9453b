#include "candela/image/exr_attributes.h"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include "candela/image/image_formats.h"

namespace candela::image_formats {

namespace {

// The value sizes of the attribute types OpenEXR's C++ reader reads as fixed-size records,
// ignoring the declared size (TypedAttribute<T>::readValueFrom over Xdr). Other known types
// (string, stringvector, floatvector, idmanifest) and unknown (opaque) ones are read at the
// declared size; chlist and preview by their content, checked below.
struct FixedType {
    std::string_view name;
    int64_t bytes;
};
constexpr std::array<FixedType, 24> kFixedTypes = {{
    {"box2i", 16},         {"box2f", 16},         {"chromaticities", 32}, {"compression", 1},
    {"deepImageState", 1}, {"double", 8},         {"envmap", 1},          {"float", 4},
    {"int", 4},            {"keycode", 28},       {"lineOrder", 1},       {"m33d", 72},
    {"m33f", 36},          {"m44d", 128},         {"m44f", 64},           {"rational", 8},
    {"tiledesc", 9},       {"timecode", 8},       {"v2d", 16},            {"v2f", 8},
    {"v2i", 8},            {"v3d", 24},           {"v3f", 12},            {"v3i", 12},
}};

// The file, read by position from the start of its headers (the rest is never read here).
class HeaderReader {
  public:
    explicit HeaderReader(const std::filesystem::path& file) : in_(file, std::ios::binary) {
        std::error_code ec;
        size_ = int64_t(std::filesystem::file_size(file, ec));
        if (ec || !in_) size_ = 0;
    }
    int64_t left(int64_t at) const { return size_ - at; }

    // A NUL-terminated name of at most 255 characters (OpenEXR's Name::MAX_LENGTH), unprintable
    // characters replaced for messages. Moves `at` past it.
    std::optional<std::string> name(int64_t& at) {
        std::string s;
        in_.seekg(at);
        for (char c; at < size_ && in_.get(c);) {
            ++at;
            if (c == '\0') return s;
            if (s.size() == 255) return std::nullopt;
            s += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
        }
        return std::nullopt;
    }
    // A little-endian 32-bit integer. Moves `at` past it.
    std::optional<uint32_t> u32(int64_t& at) {
        unsigned char b[4];
        in_.seekg(at);
        if (left(at) < 4 || !in_.read(reinterpret_cast<char*>(b), 4)) return std::nullopt;
        at += 4;
        return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
    }

  private:
    std::ifstream in_;
    int64_t size_ = 0;
};

// The bytes the C++ reader takes for a chlist value at `at`, reading by content: channel records
// (name, int type, uchar pLinear, 3 reserved bytes, int xSampling, int ySampling) up to an empty
// name. nullopt when that runs off the file.
std::optional<int64_t> channel_list_bytes(HeaderReader& in, int64_t at) {
    const int64_t start = at;
    for (;;) {
        const std::optional<std::string> name = in.name(at);
        if (!name) return std::nullopt;
        if (name->empty()) return at - start;
        if (in.left(at) < 16) return std::nullopt;
        at += 16;
    }
}

// The bytes of a preview value at `at`: width and height, then 4 bytes per pixel. nullopt when
// they do not fit in 2^62 bytes.
std::optional<int64_t> preview_bytes(HeaderReader& in, int64_t at) {
    const std::optional<uint32_t> w = in.u32(at);
    const std::optional<uint32_t> h = w ? in.u32(at) : std::nullopt;
    if (!h) return std::nullopt;
    const uint64_t pixels = uint64_t(*w) * uint64_t(*h);  // < 2^64
    if (pixels > (uint64_t(1) << 60)) return std::nullopt;
    return 8 + 4 * int64_t(pixels);
}

// The bytes the C++ reader takes for a value of `type` at `at` when it reads that type by its
// content: kBySize for the types it reads at the declared size, kNoEnd when the content does not
// end within the file.
constexpr int64_t kBySize = -1, kNoEnd = -2;
int64_t content_bytes(HeaderReader& in, std::string_view type, int64_t at) {
    for (const FixedType& t : kFixedTypes)
        if (type == t.name) return t.bytes;
    if (type == "chlist") return channel_list_bytes(in, at).value_or(kNoEnd);
    if (type == "preview") return preview_bytes(in, at).value_or(kNoEnd);
    return kBySize;
}

}  // namespace

void check_exr_attributes(const std::filesystem::path& file, bool multi_part) {
    HeaderReader in(file);
    int64_t at = 8;  // past the magic number and the version field, which the caller checked
    for (;;) {       // headers: one, or a list ended by an empty one in a multi-part file
        bool empty_header = true;
        for (;;) {
            const std::optional<std::string> name = in.name(at);
            if (!name) return;
            if (name->empty()) break;
            empty_header = false;
            const std::optional<std::string> type = in.name(at);
            const std::optional<uint32_t> declared = type ? in.u32(at) : std::nullopt;
            if (!declared) return;
            const int64_t size = int32_t(*declared);
            auto refuse = [&](const std::string& why) {
                fail(file, fmt::format("corrupt OpenEXR header: attribute \"{}\" of type \"{}\" {}", *name, *type, why));
            };
            if (size < 0 || size > in.left(at))
                refuse(fmt::format("declares {} bytes, but the file has {} left", size, in.left(at)));
            // What the C++ reader would take, where that is not the declared size.
            const int64_t held = content_bytes(in, *type, at);
            if (held == kNoEnd) refuse(fmt::format("declares {} bytes, but its value does not end within the file", size));
            if (held != kBySize && held != size) refuse(fmt::format("declares {} bytes, but its value takes {}", size, held));
            at += size;
        }
        if (!multi_part || empty_header) return;
    }
}

}  // namespace candela::image_formats
