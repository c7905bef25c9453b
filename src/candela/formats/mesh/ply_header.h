#pragma once
// The header of a PLY file: its format and the elements and properties it declares, for
// ply_loader.cpp. Parsing it checks the declarations and that the data can hold the counts.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

enum class PlyType : uint8_t { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kFloat32, kFloat64 };

// The names of the scalar types: the original ones and the sized aliases newer writers use.
struct PlyTypeName {
    std::string_view name;
    PlyType type;
};
inline constexpr PlyTypeName kPlyTypeNames[] = {
    {"char", PlyType::kInt8},      {"uchar", PlyType::kUInt8},    {"short", PlyType::kInt16},
    {"ushort", PlyType::kUInt16},  {"int", PlyType::kInt32},      {"uint", PlyType::kUInt32},
    {"float", PlyType::kFloat32},  {"double", PlyType::kFloat64}, {"int8", PlyType::kInt8},
    {"uint8", PlyType::kUInt8},    {"int16", PlyType::kInt16},    {"uint16", PlyType::kUInt16},
    {"int32", PlyType::kInt32},    {"uint32", PlyType::kUInt32},  {"float32", PlyType::kFloat32},
    {"float64", PlyType::kFloat64}};

// Bytes of one binary value.
constexpr size_t type_size(PlyType t) {
    switch (t) {
        case PlyType::kInt8:
        case PlyType::kUInt8: return 1;
        case PlyType::kInt16:
        case PlyType::kUInt16: return 2;
        case PlyType::kInt32:
        case PlyType::kUInt32:
        case PlyType::kFloat32: return 4;
        case PlyType::kFloat64: return 8;
    }
    return 0;
}

constexpr bool is_integer(PlyType t) { return t != PlyType::kFloat32 && t != PlyType::kFloat64; }

// The type's original name (char, uchar, ..., double), for messages.
constexpr std::string_view type_name(PlyType t) {
    for (const PlyTypeName& n : kPlyTypeNames)
        if (n.type == t) return n.name;
    return "?";
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::kFloat32;   // the value type, or the item type of a list
    std::optional<PlyType> list_count;  // the type of the item count, for list properties
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    int line = 0;  // of its `element` line, for errors about its declaration
    std::vector<PlyProperty> properties;
};

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct PlyHeader {
    PlyFormat format = PlyFormat::kAscii;
    std::vector<PlyElement> elements;
    size_t data_offset = 0;  // first byte after the end_header line
    int end_line = 0;        // the line number of end_header
};

// Parses the header at the start of `bytes`. Throws SceneError naming `file` and the line.
PlyHeader parse_ply_header(std::string_view bytes, const std::string& file);

// The fewest bytes one record of `e` can take in the data section: lists count as empty. In ascii
// every value takes at least one character and one separator.
uint64_t min_record_bytes(const PlyElement& e, PlyFormat format);

// Throws SceneError (at the element's line) when the data after the header cannot hold the
// records the header declares, so that a corrupt or hostile count never reaches an allocation.
void check_ply_counts_fit(const PlyHeader& header, size_t data_bytes, const std::string& file);

}  // namespace candela
