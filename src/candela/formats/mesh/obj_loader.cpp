#include "candela/formats/mesh/obj_loader.h"

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <istream>
#include <streambuf>
#include <unordered_map>
#include <vector>

#include "candela/core/error.h"

namespace candela {
namespace {

// Lets tinyobjloader read the text in place, without copying it into a stringstream.
class MemoryStreamBuf : public std::streambuf {
  public:
    explicit MemoryStreamBuf(std::string_view text) {
        // The get area is only read; std::streambuf merely lacks a const interface.
        char* begin = const_cast<char*>(text.data());
        setg(begin, begin, begin + text.size());
    }
};

// Calls visit(line_number, line) for each line of `text`, splitting lines as tinyobjloader does
// ("\n", "\r\n" or a lone "\r").
template <class Visit>
void for_each_line(std::string_view text, Visit visit) {
    int line = 0;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view s = text.substr(pos, end - pos);
        pos = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
        visit(++line, s);
    }
}

// The whitespace-separated words of one statement, up to a '#' comment.
class Words {
  public:
    explicit Words(std::string_view line) : line_(line.substr(0, line.find('#'))) {}
    std::string_view next() {
        while (pos_ < line_.size() && is_space(line_[pos_])) ++pos_;
        const size_t start = pos_;
        while (pos_ < line_.size() && !is_space(line_[pos_])) ++pos_;
        return line_.substr(start, pos_ - start);
    }

  private:
    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
    std::string_view line_;
    size_t pos_ = 0;
};

// Checks the statements tinyobjloader would read leniently (it takes "abc" or a missing
// coordinate as 0, and a face index beyond int range wraps) and counts what the mesh will hold.
// One pass over the text, before tinyobjloader allocates anything.
class ObjSurvey {
  public:
    ObjSurvey(std::string_view text, const std::string& file) : file_(file) {
        for_each_line(text, [&](int line, std::string_view s) { statement(line, s); });
        size_.normals = normal_count_ > 0;
        size_.uvs = uv_count_ > 0;
    }
    const MeshSize& size() const { return size_; }

  private:
    void statement(int line, std::string_view s) {
        Words words(s);
        const std::string_view keyword = words.next();
        if (keyword == "v") {
            numbers(line, words, 3, "a vertex position (v x y z)");
            ++size_.vertices;
        } else if (keyword == "vn") {
            numbers(line, words, 3, "a normal (vn x y z)");
            ++normal_count_;
        } else if (keyword == "vt") {
            numbers(line, words, 1, "a texture coordinate (vt u v)");
            ++uv_count_;
        } else if (keyword == "f") {
            face(line, words);
        }
    }

    // At least `count` numbers, every one finite in float (the precision tinyobjloader keeps).
    void numbers(int line, Words& words, size_t count, const char* what) const {
        size_t found = 0;
        for (std::string_view w = words.next(); !w.empty(); w = words.next(), ++found) {
            const std::string_view digits = w.starts_with('+') ? w.substr(1) : w;
            double value = 0.0;
            const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
            if (ec == std::errc::invalid_argument || end != digits.data() + digits.size())
                fail(line, fmt::format("{}: expected a number, got \"{}\"", what, w));
            if (ec == std::errc::result_out_of_range || !std::isfinite(static_cast<float>(value)))
                fail(line, fmt::format("{}: \"{}\" is not a finite number within float range", what, w));
        }
        if (found < count)
            fail(line, fmt::format("{}: expected {} numbers, got {}", what, count, found));
    }

    // Corners v, v/vt, v//vn or v/vt/vn with integer indices in int range. Index 0 and indices
    // beyond the statements are left to tinyobjloader and to ObjMeshBuilder::validate, which
    // know which statements came before.
    void face(int line, Words& words) {
        size_t corners = 0;
        for (std::string_view w = words.next(); !w.empty(); w = words.next(), ++corners) {
            size_t parts = 0;
            for (size_t start = 0; start <= w.size(); ++parts) {
                size_t slash = w.find('/', start);
                if (slash == std::string_view::npos) slash = w.size();
                const std::string_view part = w.substr(start, slash - start);
                start = slash + 1;
                if (part.empty() && parts != 0) continue;  // "v//vn": no vt
                int64_t index = 0;
                const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), index);
                if (ec == std::errc::result_out_of_range || (ec == std::errc() && end == part.data() + part.size() &&
                                                             (index > INT32_MAX || index < -INT32_MAX)))
                    fail(line, fmt::format("face index {} is out of range", part));
                if (ec != std::errc() || end != part.data() + part.size() || parts >= 3)
                    fail(line, fmt::format("face corner \"{}\" is not v, v/vt, v//vn or v/vt/vn with integer "
                                           "indices",
                                           w));
            }
        }
        if (corners < 3) fail(line, fmt::format("a face has fewer than 3 vertices ({})", corners));
        // tinyobjloader stores the corner count in an unsigned char.
        if (corners > 255) fail(line, "a face has more than 255 vertices, the most tinyobjloader supports");
        size_.corners += corners;
        size_.triangles += corners - 2;
    }

    [[noreturn]] void fail(int line, std::string message) const {
        throw SceneError(SourceLocation{file_, line, 0, {}}, std::move(message));
    }

    const std::string& file_;
    MeshSize size_;
    uint64_t normal_count_ = 0;
    uint64_t uv_count_ = 0;
};

// The line of face number `face` among the file's `f` statements (all of which have three or
// more corners once the survey passed); 0 if not found. tinyobjloader keeps no line per face, so
// this second pass runs only to locate an error.
int line_of_face(std::string_view text, size_t face) {
    int found = 0;
    size_t seen = 0;
    for_each_line(text, [&](int line, std::string_view s) {
        Words words(s);
        if (found == 0 && words.next() == "f" && seen++ == face) found = line;
    });
    return found;
}

// tinyobjloader's errors end in "line N.)"; pull N out so the location is structured.
int line_in_message(const std::string& message) {
    const size_t at = message.rfind("line ");
    if (at == std::string::npos) return 0;
    int line = 0;
    for (size_t i = at + 5; i < message.size() && std::isdigit(static_cast<unsigned char>(message[i])); ++i)
        line = line * 10 + (message[i] - '0');
    return line;
}

std::string trimmed(std::string s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    return s;
}

struct CornerKey {
    int v, vt, vn;
    bool operator==(const CornerKey&) const = default;
};

struct CornerKeyHash {
    size_t operator()(const CornerKey& k) const {
        uint64_t h = static_cast<uint32_t>(k.v);
        h = (h ^ static_cast<uint32_t>(k.vt)) * 0x9E3779B97F4A7C15ull;
        h = (h ^ static_cast<uint32_t>(k.vn)) * 0x9E3779B97F4A7C15ull;
        return static_cast<size_t>(h ^ (h >> 32));
    }
};

class ObjMeshBuilder {
  public:
    ObjMeshBuilder(std::string_view text, const std::string& file, const tinyobj::attrib_t& attrib)
        : text_(text), file_(file), attrib_(attrib) {}

    // Checks every index of every face and decides whether the mesh keeps normals and uvs.
    void validate(const std::vector<tinyobj::shape_t>& shapes) {
        const size_t vertex_count = attrib_.vertices.size() / 3;
        const size_t normal_count = attrib_.normals.size() / 3;
        const size_t uv_count = attrib_.texcoords.size() / 2;
        size_t face = 0;
        for (const tinyobj::shape_t& shape : shapes) {
            size_t corner = 0;
            for (const unsigned char n : shape.mesh.num_face_vertices) {
                for (size_t k = 0; k < n; ++k) {
                    const tinyobj::index_t& i = shape.mesh.indices[corner + k];
                    check(i.vertex_index, vertex_count, face, "vertex", "v");
                    // tinyobjloader marks a missing vt or vn with -1.
                    if (i.texcoord_index == -1)
                        all_uvs_ = false;
                    else
                        check(i.texcoord_index, uv_count, face, "texture coordinate", "vt");
                    if (i.normal_index == -1)
                        all_normals_ = false;
                    else
                        check(i.normal_index, normal_count, face, "normal", "vn");
                }
                corner += n;
                ++face;
            }
        }
    }

    TriangleMesh build(const std::vector<tinyobj::shape_t>& shapes) {
        vertex_of_.reserve(attrib_.vertices.size() / 3);
        std::vector<uint32_t> polygon;
        for (const tinyobj::shape_t& shape : shapes) {
            size_t corner = 0;
            for (const unsigned char n : shape.mesh.num_face_vertices) {
                polygon.clear();
                for (size_t k = 0; k < n; ++k) polygon.push_back(vertex(shape.mesh.indices[corner + k]));
                corner += n;
                // A fan keeps every triangle's winding equal to the polygon's.
                for (size_t j = 1; j + 1 < polygon.size(); ++j) {
                    mesh_.indices.push_back(polygon[0]);
                    mesh_.indices.push_back(polygon[j]);
                    mesh_.indices.push_back(polygon[j + 1]);
                }
            }
        }
        return std::move(mesh_);
    }

  private:
    void check(int index, size_t count, size_t face, const char* what, const char* statement) const {
        if (index >= 0 && static_cast<size_t>(index) < count) return;
        const std::string found = index >= 0 ? fmt::format("{} {}", what, index + 1)
                                             : fmt::format("a {} before the first one", what);
        throw SceneError(
            SourceLocation{file_, line_of_face(text_, face), 0, {}},
            fmt::format("face refers to {}, but the file has {} {} statements", found, count, statement));
    }

    // The mesh vertex of one (v, vt, vn) triple, made on first use. Attributes the mesh drops
    // take no part in the key, so corners that differ only in them share a vertex.
    uint32_t vertex(const tinyobj::index_t& i) {
        const CornerKey key{i.vertex_index, all_uvs_ ? i.texcoord_index : -1,
                            all_normals_ ? i.normal_index : -1};
        const auto [it, inserted] =
            vertex_of_.try_emplace(key, static_cast<uint32_t>(mesh_.positions.size()));
        if (inserted) {
            const auto& a = attrib_;
            const size_t v = static_cast<size_t>(key.v);
            mesh_.positions.emplace_back(a.vertices[3 * v], a.vertices[3 * v + 1], a.vertices[3 * v + 2]);
            if (all_normals_) {
                const size_t n = static_cast<size_t>(key.vn);
                mesh_.normals.emplace_back(a.normals[3 * n], a.normals[3 * n + 1], a.normals[3 * n + 2]);
            }
            if (all_uvs_) {
                const size_t t = static_cast<size_t>(key.vt);
                mesh_.uvs.emplace_back(a.texcoords[2 * t], a.texcoords[2 * t + 1]);
            }
        }
        return it->second;
    }

    std::string_view text_;
    const std::string& file_;
    const tinyobj::attrib_t& attrib_;
    bool all_normals_ = true;
    bool all_uvs_ = true;
    std::unordered_map<CornerKey, uint32_t, CornerKeyHash> vertex_of_;
    TriangleMesh mesh_;
};

}  // namespace

TriangleMesh parse_obj(std::string_view text, const std::string& file_name, const MeshSizeCheck& check) {
    const ObjSurvey survey(text, file_name);
    if (survey.size().triangles == 0) return {};
    if (survey.size().triangles > UINT32_MAX)
        throw SceneError(SourceLocation{file_name, 0, 0, {}},
                         fmt::format("{} triangles are more than the 2^32 - 1 a mesh can index",
                                     survey.size().triangles));
    if (check) check(survey.size());

    MemoryStreamBuf buffer(text);
    std::istream stream(&buffer);
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    // With no material reader tinyobjloader skips mtllib, so a missing .mtl is no error. We
    // triangulate ourselves: tinyobjloader 2.0-rc10's triangulation silently drops polygons
    // whose indices are out of range, where we want an error with the line.
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream,
                          /*readMatFn=*/nullptr, /*triangulate=*/false, /*default_vcols_fallback=*/false))
        throw SceneError(SourceLocation{file_name, line_in_message(error), 0, {}},
                         fmt::format("malformed OBJ statement (tinyobjloader: {})", trimmed(error)));

    ObjMeshBuilder builder(text, file_name, attrib);
    builder.validate(shapes);
    return builder.build(shapes);
}

}  // namespace candela
