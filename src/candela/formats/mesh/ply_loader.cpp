#include "candela/formats/mesh/ply_loader.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "candela/core/error.h"
#include "candela/formats/mesh/ply_header.h"

namespace candela {
namespace {

// Where the vertex attributes we read are among the vertex element's properties.
enum VertexSlot : int { kX, kY, kZ, kNx, kNy, kNz, kU, kV, kSlotCount };

struct VertexLayout {
    std::vector<int> slot;  // per property: a VertexSlot, or -1 to skip it
    bool has_normals = false;
    bool has_uvs = false;
};

VertexLayout vertex_layout(const PlyElement& e, const std::string& file) {
    constexpr size_t kMissing = std::numeric_limits<size_t>::max();
    VertexLayout layout;
    layout.slot.assign(e.properties.size(), -1);
    auto find = [&](std::string_view name) {
        for (size_t i = 0; i < e.properties.size(); ++i)
            if (e.properties[i].name == name) return i;
        return kMissing;
    };
    auto assign = [&](size_t property, int slot) {
        if (e.properties[property].list_count)
            fail_in_file(file, e.line,
                    fmt::format("vertex property \"{}\" must be a scalar, not a list",
                                e.properties[property].name));
        layout.slot[property] = slot;
    };
    for (const int slot : {kX, kY, kZ}) {
        const std::string_view name = std::array{"x", "y", "z"}[static_cast<size_t>(slot - kX)];
        const size_t p = find(name);
        if (p == kMissing)
            fail_in_file(file, e.line, fmt::format("the vertex element has no \"{}\" property", name));
        assign(p, slot);
    }
    const std::array<size_t, 3> normal = {find("nx"), find("ny"), find("nz")};
    const auto normal_parts =
        std::count_if(normal.begin(), normal.end(), [](size_t p) { return p != kMissing; });
    if (normal_parts == 3) {
        for (size_t i = 0; i < 3; ++i) assign(normal[i], kNx + static_cast<int>(i));
        layout.has_normals = true;
    } else if (normal_parts > 0) {
        fail_in_file(file, e.line, "the vertex element has only some of the normal properties nx, ny, nz");
    }
    // A lone "u" or "t" may be something else (a time, say), so only a complete pair is a uv.
    constexpr std::array<std::array<std::string_view, 2>, 4> kUvNames = {
        {{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}};
    for (const auto& [u_name, v_name] : kUvNames) {
        const size_t u = find(u_name), v = find(v_name);
        if (u != kMissing && v != kMissing) {
            assign(u, kU);
            assign(v, kV);
            layout.has_uvs = true;
            break;
        }
    }
    return layout;
}

struct FaceLayout {
    size_t indices = 0;  // the property holding the vertex index list
};

FaceLayout face_layout(const PlyElement& e, const std::string& file) {
    for (const std::string_view name : {"vertex_indices", "vertex_index"}) {
        for (size_t i = 0; i < e.properties.size(); ++i) {
            const PlyProperty& p = e.properties[i];
            if (p.name != name) continue;
            if (!p.list_count)
                fail_in_file(file, e.line, fmt::format("face property \"{}\" must be a list", p.name));
            if (!is_integer(p.type))
                fail_in_file(file, e.line,
                        fmt::format("face property \"{}\" must list integers, got {}", p.name,
                                    type_name(p.type)));
            return FaceLayout{i};
        }
    }
    fail_in_file(file, e.line, "the face element has no \"vertex_indices\" (or \"vertex_index\") list");
}

// Names the record being read, for errors.
class RecordContext {
  public:
    void begin(const PlyElement& e, uint64_t record) {
        element_ = &e;
        record_ = record;
    }
    std::string describe(const std::string& message) const {
        if (!element_) return message;
        return fmt::format("element \"{}\", record {} of {}: {}", element_->name, record_ + 1,
                           element_->count, message);
    }

  private:
    const PlyElement* element_ = nullptr;
    uint64_t record_ = 0;
};

template <class T>
T byte_swapped(T value) {
    if constexpr (sizeof(T) == 1) {
        return value;
    } else {
        using U = std::conditional_t<sizeof(T) == 2, uint16_t,
                                     std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>;
        U u = std::bit_cast<U>(value);
        if constexpr (sizeof(T) == 2)
            u = __builtin_bswap16(u);
        else if constexpr (sizeof(T) == 4)
            u = __builtin_bswap32(u);
        else
            u = __builtin_bswap64(u);
        return std::bit_cast<T>(u);
    }
}

// Reads binary values by copying them from their offsets (never through a misaligned pointer),
// swapping bytes when the file's byte order is not the machine's.
class BinaryCursor {
  public:
    BinaryCursor(std::string_view data, bool swap, const std::string& file)
        : p_(data.data()), begin_(data.data()), end_(data.data() + data.size()), swap_(swap), file_(file) {}

    void begin_record(const PlyElement& e, uint64_t record) { context_.begin(e, record); }

    float read_float(PlyType t) {
        switch (t) {
            case PlyType::kFloat32: return load<float>();
            case PlyType::kFloat64: return static_cast<float>(load<double>());
            default: return static_cast<float>(read_integer(t));
        }
    }
    int64_t read_integer(PlyType t) {
        switch (t) {
            case PlyType::kInt8: return load<int8_t>();
            case PlyType::kUInt8: return load<uint8_t>();
            case PlyType::kInt16: return load<int16_t>();
            case PlyType::kUInt16: return load<uint16_t>();
            case PlyType::kInt32: return load<int32_t>();
            case PlyType::kUInt32: return load<uint32_t>();
            case PlyType::kFloat32:
            case PlyType::kFloat64: break;  // the header parser admits only integer types here
        }
        fail("expected an integer value");
    }
    void skip(PlyType t) { skip_bytes(type_size(t)); }
    void skip_list(PlyType count_type, PlyType item_type) {
        const int64_t n = read_integer(count_type);
        if (n < 0) fail(fmt::format("negative list length {}", n));
        const size_t item = type_size(item_type);
        if (static_cast<uint64_t>(n) > static_cast<uint64_t>(end_ - p_) / item) fail_truncated();
        p_ += static_cast<size_t>(n) * item;
    }
    // Skips a whole element whose records all have `record_bytes` bytes.
    void skip_records(uint64_t count, size_t record_bytes) {
        if (count > static_cast<uint64_t>(end_ - p_) / record_bytes) fail_truncated();
        p_ += static_cast<size_t>(count) * record_bytes;
    }
    [[noreturn]] void fail(const std::string& message) const {
        fail_in_file(file_, 0,
                context_.describe(message) +
                    fmt::format(" (at byte {} of the data after the header)", p_ - begin_));
    }

  private:
    template <class T>
    T load() {
        if (static_cast<size_t>(end_ - p_) < sizeof(T)) fail_truncated();
        T value;
        std::memcpy(&value, p_, sizeof(T));
        p_ += sizeof(T);
        return swap_ ? byte_swapped(value) : value;
    }
    void skip_bytes(size_t n) {
        if (static_cast<size_t>(end_ - p_) < n) fail_truncated();
        p_ += n;
    }
    [[noreturn]] void fail_truncated() const { fail("unexpected end of file (file truncated?)"); }

    const char* p_;
    const char* begin_;
    const char* end_;
    bool swap_;
    const std::string& file_;
    RecordContext context_;
};

// Reads ascii values as whitespace-separated words, counting lines for errors.
class AsciiCursor {
  public:
    AsciiCursor(std::string_view data, int first_line, const std::string& file)
        : p_(data.data()), end_(data.data() + data.size()), line_(first_line), file_(file) {}

    void begin_record(const PlyElement& e, uint64_t record) { context_.begin(e, record); }

    float read_float(PlyType t) {
        if (is_integer(t)) return static_cast<float>(read_integer(t));
        std::string_view w = word();
        if (!w.empty() && w.front() == '+') w.remove_prefix(1);  // from_chars takes no '+'
        double value = 0.0;
        auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
        if (ec != std::errc() || end != w.data() + w.size())
            fail(fmt::format("expected a value of type {}, got \"{}\"", type_name(t), w));
        return static_cast<float>(value);
    }
    int64_t read_integer(PlyType t) {
        std::string_view w = word();
        if (!w.empty() && w.front() == '+') w.remove_prefix(1);
        int64_t value = 0;
        auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
        if (ec != std::errc() || end != w.data() + w.size() || !fits(value, t))
            fail(fmt::format("expected a value of type {}, got \"{}\"", type_name(t), w));
        return value;
    }
    void skip(PlyType) { word(); }
    void skip_list(PlyType count_type, PlyType) {
        const int64_t n = read_integer(count_type);
        if (n < 0) fail(fmt::format("negative list length {}", n));
        // Each word takes at least a byte, so a false count ends at the end of the file.
        for (int64_t i = 0; i < n; ++i) word();
    }
    [[noreturn]] void fail(const std::string& message) const {
        fail_in_file(file_, line_, context_.describe(message));
    }

  private:
    static bool fits(int64_t v, PlyType t) {
        switch (t) {
            case PlyType::kInt8: return v >= INT8_MIN && v <= INT8_MAX;
            case PlyType::kUInt8: return v >= 0 && v <= UINT8_MAX;
            case PlyType::kInt16: return v >= INT16_MIN && v <= INT16_MAX;
            case PlyType::kUInt16: return v >= 0 && v <= UINT16_MAX;
            case PlyType::kInt32: return v >= INT32_MIN && v <= INT32_MAX;
            case PlyType::kUInt32: return v >= 0 && v <= static_cast<int64_t>(UINT32_MAX);
            case PlyType::kFloat32:
            case PlyType::kFloat64: return false;
        }
        return false;
    }
    std::string_view word() {
        while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n')) {
            if (*p_ == '\n') ++line_;
            ++p_;
        }
        if (p_ == end_) fail("unexpected end of file (file truncated?)");
        const char* start = p_;
        while (p_ < end_ && *p_ != ' ' && *p_ != '\t' && *p_ != '\r' && *p_ != '\n') ++p_;
        return {start, static_cast<size_t>(p_ - start)};
    }

    const char* p_;
    const char* end_;
    int line_;
    const std::string& file_;
    RecordContext context_;
};

template <class Cursor>
void read_vertices(Cursor& c, const PlyElement& e, const VertexLayout& layout, TriangleMesh& mesh) {
    mesh.positions.resize(e.count);
    if (layout.has_normals) mesh.normals.resize(e.count);
    if (layout.has_uvs) mesh.uvs.resize(e.count);
    std::array<float, kSlotCount> v{};
    for (uint64_t i = 0; i < e.count; ++i) {
        c.begin_record(e, i);
        for (size_t k = 0; k < e.properties.size(); ++k) {
            const PlyProperty& p = e.properties[k];
            if (p.list_count)
                c.skip_list(*p.list_count, p.type);
            else if (layout.slot[k] >= 0)
                v[static_cast<size_t>(layout.slot[k])] = c.read_float(p.type);
            else
                c.skip(p.type);
        }
        mesh.positions[i] = {v[kX], v[kY], v[kZ]};
        // Here, where the record is known: a NaN or an overflow (1e300 read as a float) would
        // otherwise surface as a NaN image far from its cause.
        if (!is_finite(mesh.positions[i]))
            c.fail(fmt::format("the vertex position ({}, {}, {}) is not finite", v[kX], v[kY], v[kZ]));
        if (layout.has_normals) mesh.normals[i] = {v[kNx], v[kNy], v[kNz]};
        if (layout.has_uvs) mesh.uvs[i] = {v[kU], v[kV]};
    }
}

template <class Cursor>
void read_faces(Cursor& c, const PlyElement& e, const FaceLayout& layout, uint64_t vertex_count,
                size_t data_bytes, TriangleMesh& mesh) {
    // Reserve for triangles of the smallest plausible size, so a false count cannot over-allocate.
    const PlyProperty& list = e.properties[layout.indices];
    const uint64_t triangle_bytes = type_size(*list.list_count) + 3 * type_size(list.type);
    mesh.indices.reserve(3 * static_cast<size_t>(std::min<uint64_t>(e.count, data_bytes / triangle_bytes)));
    std::vector<uint32_t> polygon;
    for (uint64_t i = 0; i < e.count; ++i) {
        c.begin_record(e, i);
        for (size_t k = 0; k < e.properties.size(); ++k) {
            const PlyProperty& p = e.properties[k];
            if (k != layout.indices) {
                if (p.list_count)
                    c.skip_list(*p.list_count, p.type);
                else
                    c.skip(p.type);
                continue;
            }
            const int64_t n = c.read_integer(*p.list_count);
            if (n < 3) c.fail(fmt::format("a face has {} vertices; expected at least 3", n));
            polygon.clear();
            for (int64_t j = 0; j < n; ++j) {
                const int64_t index = c.read_integer(p.type);
                if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
                    c.fail(fmt::format("vertex index {} is out of range; the file has {} vertices", index,
                                       vertex_count));
                polygon.push_back(static_cast<uint32_t>(index));
            }
            // A fan keeps every triangle's winding equal to the polygon's.
            for (size_t j = 1; j + 1 < polygon.size(); ++j) {
                mesh.indices.push_back(polygon[0]);
                mesh.indices.push_back(polygon[j]);
                mesh.indices.push_back(polygon[j + 1]);
            }
        }
    }
}

template <class Cursor>
void skip_element(Cursor& c, const PlyElement& e) {
    if (e.properties.empty()) return;
    if constexpr (std::is_same_v<Cursor, BinaryCursor>) {
        const bool fixed = std::none_of(e.properties.begin(), e.properties.end(),
                                        [](const PlyProperty& p) { return p.list_count.has_value(); });
        if (fixed) {
            c.begin_record(e, 0);
            return c.skip_records(e.count, min_record_bytes(e, PlyFormat::kBinaryLittleEndian));
        }
    }
    for (uint64_t i = 0; i < e.count; ++i) {
        c.begin_record(e, i);
        for (const PlyProperty& p : e.properties) {
            if (p.list_count)
                c.skip_list(*p.list_count, p.type);
            else
                c.skip(p.type);
        }
    }
}

template <class Cursor>
TriangleMesh read_data(Cursor& c, const PlyHeader& header, const PlyElement& vertices,
                       const VertexLayout& vertex, const PlyElement& faces, const FaceLayout& face,
                       size_t data_bytes) {
    TriangleMesh mesh;
    for (const PlyElement& e : header.elements) {
        if (&e == &vertices)
            read_vertices(c, e, vertex, mesh);
        else if (&e == &faces)
            read_faces(c, e, face, vertices.count, data_bytes, mesh);
        else
            skip_element(c, e);
    }
    return mesh;
}

const PlyElement& find_element(const PlyHeader& header, std::string_view name, const std::string& file) {
    for (const PlyElement& e : header.elements)
        if (e.name == name) return e;
    fail_in_file(file, header.end_line, fmt::format("the PLY header declares no \"{}\" element", name));
}

// What the header says and how the vertex and face records will be read.
struct PlyPlan {
    PlyHeader header;
    const PlyElement* vertices = nullptr;
    const PlyElement* faces = nullptr;
    VertexLayout vertex;
    FaceLayout face;

    // PlyPlan points into its own header: it is never copied or moved once made.
    PlyPlan(std::string_view bytes, const std::string& file_name) : header(parse_ply_header(bytes, file_name)) {
        vertices = &find_element(header, "vertex", file_name);
        faces = &find_element(header, "face", file_name);
        vertex = vertex_layout(*vertices, file_name);
        face = face_layout(*faces, file_name);
        if (vertices->count > std::numeric_limits<uint32_t>::max())
            fail_in_file(file_name, vertices->line,
                    fmt::format("{} vertices are more than the 2^32 - 1 a mesh can index", vertices->count));
    }
    PlyPlan(const PlyPlan&) = delete;
    PlyPlan& operator=(const PlyPlan&) = delete;

    // Embree numbers triangles with 32 bits, and every face makes at least one.
    void check_face_count(const std::string& file_name) const {
        if (faces->count > std::numeric_limits<uint32_t>::max())
            fail_in_file(file_name, faces->line,
                    fmt::format("{} faces are more than the 2^32 - 1 triangles a mesh can index", faces->count));
    }
    MeshSize size() const { return MeshSize{vertices->count, faces->count, 0, vertex.has_normals, vertex.has_uvs}; }
};

}  // namespace

MeshSize ply_mesh_size(std::string_view header_bytes, const std::string& file_name) {
    const PlyPlan plan(header_bytes, file_name);
    plan.check_face_count(file_name);
    return plan.size();
}

TriangleMesh parse_ply(std::string_view bytes, const std::string& file_name, const MeshSizeCheck& check) {
    const PlyPlan plan(bytes, file_name);
    const PlyHeader& header = plan.header;
    const std::string_view data = bytes.substr(header.data_offset);
    check_ply_counts_fit(header, data.size(), file_name);
    plan.check_face_count(file_name);
    if (check) check(plan.size());

    if (header.format == PlyFormat::kAscii) {
        AsciiCursor c(data, header.end_line + 1, file_name);
        return read_data(c, header, *plan.vertices, plan.vertex, *plan.faces, plan.face, data.size());
    }
    const bool file_is_little = header.format == PlyFormat::kBinaryLittleEndian;
    const bool swap = file_is_little != (std::endian::native == std::endian::little);
    BinaryCursor c(data, swap, file_name);
    return read_data(c, header, *plan.vertices, plan.vertex, *plan.faces, plan.face, data.size());
}

}  // namespace candela
