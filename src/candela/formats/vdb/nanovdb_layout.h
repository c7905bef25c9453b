#pragma once
// The byte layout of NanoVDB files (ABI major version 32: NanoVDB 32.3, which pbrt-v4 pins,
// through 32.9), as our own reader needs it: sizes and offsets of the structures for float grids,
// and bounds-checked little-endian reads from a byte buffer. Everything is little-endian and the
// grid buffer is one block in which every node is addressed by a byte offset, so nothing here is
// read through a cast: each field is copied out of the bytes after its range is checked.
//
// A file is a sequence of segments (NanoVDB's io::writeGrid(s) write one per handle):
//   FileHeader (16 B): magic u64 ("NanoVDB0", or "NanoVDB2" since 32.7), version u32 (major<<21 |
//     minor<<10 | patch), grid count u16, codec u16 (0 none, 1 zip, 2 blosc);
//   per grid, FileMetaData (176 B) followed by its name (name size bytes, with the final NUL);
//   then each grid's buffer, file size bytes on disk (= grid size when uncompressed).
// Since 32.6 a file may also be raw grid buffers one after another (GridHandle::write): each
// starts with GridData, magic "NanoVDB1" (or "NanoVDB0" with "NanoVDB1" in its last field).
//
// A grid buffer, 32-byte aligned: GridData (672 B), TreeData (64 B), then the root (RootData and
// its tiles), the upper internal nodes (32^3 slots, each a child of 128^3 voxels or a tile), the
// lower internal nodes (16^3 slots of 8^3 voxels), the leaves (8^3 voxels), blind data. A slot n
// of a node of 2^L per side holds local coordinates (n >> 2L, (n >> L) & (2^L - 1), n & (2^L - 1)):
// x slowest, z fastest. Child offsets are signed byte offsets from the parent node's start.
#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>

namespace candela::nanovdb_layout {

static_assert(std::endian::native == std::endian::little, "the NanoVDB reader assumes a little-endian host");

constexpr uint64_t kMagicFileOld = 0x304244566f6e614eULL;  // "NanoVDB0": a file (or, before 32.7, a grid)
constexpr uint64_t kMagicGrid = 0x314244566f6e614eULL;     // "NanoVDB1": a grid buffer
constexpr uint64_t kMagicFile = 0x324244566f6e614eULL;     // "NanoVDB2": a file
constexpr uint32_t kMajorVersion = 32;
constexpr uint32_t kOpenVdbMagic = 0x56444220;  // the first 4 bytes of a .vdb file

// FileHeader
constexpr uint64_t kFileHeaderSize = 16;
constexpr uint64_t kHeaderVersion = 8, kHeaderGridCount = 12, kHeaderCodec = 14;
// FileMetaData
constexpr uint64_t kFileMetaSize = 176;
constexpr uint64_t kMetaGridSize = 0, kMetaFileSize = 8, kMetaGridType = 32, kMetaNameSize = 136, kMetaCodec = 168;
// GridData
constexpr uint64_t kGridDataSize = 672;
constexpr uint64_t kGridMagic = 0, kGridVersion = 16, kGridSize = 32, kGridName = 40, kGridNameSize = 256;
constexpr uint64_t kGridMapMatD = 384, kGridMapVecD = 528;  // Map: 3x3 row-major matrix, translation (doubles)
constexpr uint64_t kGridWorldBBox = 560;                    // min xyz, max xyz (doubles)
constexpr uint64_t kGridType = 636, kGridLastWord = 664;
// TreeData, right after GridData
constexpr uint64_t kTreeDataSize = 64;
constexpr uint64_t kTreeNodeOffset = 0;  // 4 x i64, from the TreeData: leaves, lower, upper, root
constexpr uint64_t kTreeNodeCount = 32;  // 3 x u32: leaves, lower, upper
// RootData<float> and its tiles
constexpr uint64_t kRootDataSize = 64;
constexpr uint64_t kRootTableSize = 24, kRootBackground = 28;
constexpr uint64_t kRootTileSize = 32;
constexpr uint64_t kTileKey = 0, kTileChild = 8, kTileState = 16, kTileValue = 20;
// Internal nodes (InternalData<float, L>): bbox, flags, value mask, child mask, stats, then the
// slot table of 8-byte unions (a float value or an i64 child offset).
struct InternalLayout {
    int log2dim;          // 5 for upper, 4 for lower nodes
    int child_log2;       // log2 of the voxels per side of a slot: 7 for upper, 3 for lower
    uint64_t value_mask;  // offset of the value (active) mask
    uint64_t child_mask;  // offset of the child mask
    uint64_t table;       // offset of the slot table
    uint64_t size;        // bytes per node
};
constexpr InternalLayout kUpper{5, 7, 32, 32 + 4096, 8256, 270400};
constexpr InternalLayout kLower{4, 3, 32, 32 + 512, 1088, 33856};
// LeafData<float>: origin (3 x i32), bbox extent, flags, value mask (64 B), stats, 512 floats.
constexpr uint64_t kLeafValueMask = 16, kLeafValues = 96, kLeafSize = 2144;

constexpr uint32_t kGridTypeFloat = 1;
constexpr uint16_t kCodecNone = 0;

// Reads fixed-size little-endian values at byte offsets of a buffer, or nothing past its end.
class Bytes {
  public:
    explicit Bytes(std::string_view bytes) : bytes_(bytes) {}
    uint64_t size() const { return bytes_.size(); }
    // True when [offset, offset + count) lies in the buffer (no overflow for any inputs).
    bool holds(uint64_t offset, uint64_t count) const { return offset <= size() && count <= size() - offset; }
    template <class T>
    std::optional<T> get(uint64_t offset) const {
        if (!holds(offset, sizeof(T))) return std::nullopt;
        T value;
        std::memcpy(&value, bytes_.data() + offset, sizeof(T));
        return value;
    }
    // Only for ranges already checked with holds().
    template <class T>
    T at(uint64_t offset) const {
        T value;
        std::memcpy(&value, bytes_.data() + offset, sizeof(T));
        return value;
    }
    std::string_view view(uint64_t offset, uint64_t count) const { return bytes_.substr(offset, count); }

  private:
    std::string_view bytes_;
};

}  // namespace candela::nanovdb_layout
