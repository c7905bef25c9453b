// Reads a NanoVDB file's table of contents: segment by segment, each a FileHeader, one
// FileMetaData and name per grid, then the grids' buffers (nanovdb_layout.h); or raw grid buffers,
// whose GridData says their size, name and type. Only headers are read here; a grid's buffer is
// read by nanovdb_reader.cpp once it is chosen.
#include "candela/formats/vdb/nanovdb_file.h"

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <cstring>

#include "candela/core/error.h"
#include "candela/formats/vdb/nanovdb_layout.h"

namespace candela {
namespace {

namespace L = nanovdb_layout;

uint64_t byte_swapped(uint64_t v) {
    uint64_t r = 0;
    for (int i = 0; i < 8; ++i) r = (r << 8) | ((v >> (8 * i)) & 0xff);
    return r;
}

// Reads `count` bytes at `offset` of the file, or fails saying what was expected there.
std::string read_at(NanoVdbFile& f, uint64_t offset, uint64_t count, std::string_view what) {
    if (offset > f.size || count > f.size - offset)
        fail_in_file(f.file,
                     fmt::format("truncated NanoVDB file: expected {} ({} bytes) at byte {}, but the file has {} bytes",
                                 what, count, offset, f.size));
    std::string bytes(count, '\0');
    f.in.clear();
    f.in.seekg(std::streamoff(offset));
    f.in.read(bytes.data(), std::streamsize(count));
    if (!f.in) fail_in_file(f.file, fmt::format("cannot read {} at byte {}: {}", what, offset, std::strerror(errno)));
    return bytes;
}

// The text up to the first NUL of `bytes` (all of it when there is none).
std::string c_string(std::string_view bytes) { return std::string(bytes.substr(0, bytes.find('\0'))); }

void check_version(const NanoVdbFile& f, uint32_t version, uint64_t offset) {
    const uint32_t major = version >> 21, minor = (version >> 10) & 0x7ff, patch = version & 0x3ff;
    if (major != L::kMajorVersion)
        fail_in_file(f.file, fmt::format("NanoVDB version {}.{}.{} at byte {}; candela reads version {}.x (the file "
                                         "format of NanoVDB 32.3 to 32.9)",
                                         major, minor, patch, offset, L::kMajorVersion));
}

// A segment at `offset`: its header, metadata and names; returns where the next one starts.
uint64_t read_segment(NanoVdbFile& f, uint64_t offset) {
    const std::string header = read_at(f, offset, L::kFileHeaderSize, "a segment header");
    const L::Bytes h(header);
    check_version(f, h.at<uint32_t>(L::kHeaderVersion), offset);
    const uint16_t count = h.at<uint16_t>(L::kHeaderGridCount);
    const uint16_t codec = h.at<uint16_t>(L::kHeaderCodec);
    uint64_t at = offset + L::kFileHeaderSize;
    std::vector<NanoVdbGridEntry> entries;
    for (uint16_t i = 0; i < count; ++i) {
        const std::string meta =
            read_at(f, at, L::kFileMetaSize, fmt::format("the metadata of grid {}", f.grids.size() + i));
        const L::Bytes m(meta);
        NanoVdbGridEntry e;
        e.grid_size = m.at<uint64_t>(L::kMetaGridSize);
        e.file_size = m.at<uint64_t>(L::kMetaFileSize);
        e.grid_type = m.at<uint32_t>(L::kMetaGridType);
        e.codec = codec;
        const uint32_t name_size = m.at<uint32_t>(L::kMetaNameSize);
        at += L::kFileMetaSize;
        e.name = c_string(read_at(f, at, name_size, fmt::format("the name of grid {}", f.grids.size() + i)));
        at += name_size;
        entries.push_back(std::move(e));
    }
    // The grids' buffers follow the metadata, in the same order.
    for (NanoVdbGridEntry& e : entries) {
        if (at > f.size || e.file_size > f.size - at)
            fail_in_file(
                f.file,
                fmt::format("truncated NanoVDB file: grid \"{}\" needs {} bytes at byte {}, but the file has {} bytes",
                            e.name, e.file_size, at, f.size));
        if (e.codec == L::kCodecNone && e.file_size != e.grid_size)
            fail_in_file(f.file,
                         fmt::format("corrupt NanoVDB file: grid \"{}\" is uncompressed but takes {} bytes in the file "
                                     "and {} in memory",
                                     e.name, e.file_size, e.grid_size));
        e.offset = at;
        at += e.file_size;
        f.grids.push_back(std::move(e));
    }
    return at;
}

// A raw grid buffer at `offset` (no segment header): its GridData says the rest.
uint64_t read_raw_grid(NanoVdbFile& f, uint64_t offset) {
    const std::string data = read_at(f, offset, L::kGridDataSize, "a grid header");
    const L::Bytes g(data);
    check_version(f, g.at<uint32_t>(L::kGridVersion), offset);
    NanoVdbGridEntry e;
    e.grid_size = e.file_size = g.at<uint64_t>(L::kGridSize);
    e.grid_type = g.at<uint32_t>(L::kGridType);
    e.name = c_string(g.view(L::kGridName, L::kGridNameSize));
    e.offset = offset;
    if (e.grid_size < L::kGridDataSize || e.grid_size > f.size - offset)
        fail_in_file(
            f.file,
            fmt::format("truncated NanoVDB file: grid \"{}\" at byte {} says it has {} bytes, but the file has {}",
                        e.name, offset, e.grid_size, f.size));
    f.grids.push_back(std::move(e));
    return offset + f.grids.back().grid_size;
}

}  // namespace

NanoVdbFile open_nanovdb_file(const std::filesystem::path& path) {
    NanoVdbFile f;
    f.file = path.string();
    f.in.open(path, std::ios::binary);
    if (!f.in) fail_in_file(f.file, fmt::format("cannot open NanoVDB file: {}", std::strerror(errno)));
    f.in.seekg(0, std::ios::end);
    const std::streamoff end = f.in.tellg();
    if (end < 0) fail_in_file(f.file, "cannot read NanoVDB file: it has no size");
    f.size = uint64_t(end);
    if (f.size == 0) fail_in_file(f.file, "empty file; expected a NanoVDB file (.nvdb)");

    uint64_t offset = 0;
    while (offset < f.size) {
        const std::string head = read_at(f, offset, 8, "a NanoVDB magic number (\"NanoVDB0\" or \"NanoVDB2\")");
        const uint64_t magic = L::Bytes(head).at<uint64_t>(0);
        bool raw = magic == L::kMagicGrid;
        if (magic == L::kMagicFileOld && f.size - offset >= L::kGridDataSize) {
            // Before 32.7, grids and files shared "NanoVDB0"; a 32.6 grid also has "NanoVDB1" last.
            const std::string last = read_at(f, offset + L::kGridLastWord, 8, "a grid header");
            raw = L::Bytes(last).at<uint64_t>(0) == L::kMagicGrid;
        }
        if (raw) {
            offset = read_raw_grid(f, offset);
        } else if (magic == L::kMagicFile || magic == L::kMagicFileOld) {
            offset = read_segment(f, offset);
        } else if (byte_swapped(magic) == L::kMagicFile || byte_swapped(magic) == L::kMagicFileOld ||
                   byte_swapped(magic) == L::kMagicGrid) {
            fail_in_file(f.file, "big-endian NanoVDB file; candela reads little-endian ones only");
        } else if (offset == 0 && uint32_t(magic) == L::kOpenVdbMagic) {
            fail_in_file(f.file, "this is an OpenVDB file, not a NanoVDB one; name it .vdb to read it as OpenVDB");
        } else {
            fail_in_file(f.file,
                         fmt::format("not a NanoVDB file: expected the magic number \"NanoVDB0\" or \"NanoVDB2\" at "
                                     "byte {}",
                                     offset));
        }
    }
    return f;
}

std::string read_nanovdb_grid_bytes(NanoVdbFile& f, const NanoVdbGridEntry& entry) {
    return read_at(f, entry.offset, entry.file_size, fmt::format("grid \"{}\"", entry.name));
}

std::string nanovdb_type_name(uint32_t grid_type) {
    static constexpr std::array<const char*, 27> names = {
        "unknown", "float",  "double",   "int16",      "int32",         "int64",       "Vec3f",  "Vec3d",   "mask",
        "half",    "uint32", "bool",     "RGBA8",      "Fp4",           "Fp8",         "Fp16",   "FpN",     "Vec4f",
        "Vec4d",   "index",  "on-index", "index-mask", "on-index-mask", "point-index", "Vec3u8", "Vec3u16", "uint8"};
    if (grid_type < names.size()) return names[grid_type];
    return fmt::format("type {}", grid_type);
}

std::string nanovdb_codec_name(uint16_t codec) {
    switch (codec) {
        case 0: return "none";
        case 1: return "zip";
        case 2: return "blosc";
        default: return fmt::format("codec {}", codec);
    }
}

}  // namespace candela
