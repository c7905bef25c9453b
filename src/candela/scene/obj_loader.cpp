#include "candela/scene/obj_loader.h"

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include <cctype>
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

struct FaceLine {
    int line;
    size_t corners;
};

// The `f` statements of an OBJ text in order, with their line numbers, splitting lines as
// tinyobjloader does ("\n", "\r\n" or a lone "\r"). tinyobjloader keeps no line per face, so this
// second pass runs only to locate an error.
std::vector<FaceLine> scan_face_lines(std::string_view text) {
    std::vector<FaceLine> faces;
    int line = 0;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view s = text.substr(pos, end - pos);
        pos = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
        ++line;
        const size_t f = s.find_first_not_of(" \t");
        if (f == std::string_view::npos || s[f] != 'f' || f + 1 >= s.size() ||
            (s[f + 1] != ' ' && s[f + 1] != '\t'))
            continue;
        size_t corners = 0;
        for (size_t i = f + 1; i < s.size(); ++i)
            if (!std::isspace(static_cast<unsigned char>(s[i])) &&
                std::isspace(static_cast<unsigned char>(s[i - 1])))
                ++corners;
        faces.push_back({line, corners});
    }
    return faces;
}

// The line of face number `face` among those tinyobjloader kept (three or more corners); 0 if
// not found.
int line_of_face(std::string_view text, size_t face) {
    size_t kept = 0;
    for (const FaceLine& f : scan_face_lines(text)) {
        if (f.corners < 3) continue;
        if (kept++ == face) return f.line;
    }
    return 0;
}

// The line of the first face whose corner count `bad` rejects; 0 if none.
template <class Predicate>
int line_of_first_face(std::string_view text, Predicate bad) {
    for (const FaceLine& f : scan_face_lines(text))
        if (bad(f.corners)) return f.line;
    return 0;
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

TriangleMesh parse_obj(std::string_view text, const std::string& file_name) {
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

    // tinyobjloader drops faces of fewer than 3 corners with a warning, and stores the corner
    // count in an unsigned char, so a face of more than 255 corners would corrupt the index list.
    if (warning.find("Degenerated face") != std::string::npos)
        throw SceneError(
            SourceLocation{file_name, line_of_first_face(text, [](size_t n) { return n < 3; }), 0, {}},
            "a face has fewer than 3 vertices");
    for (const tinyobj::shape_t& shape : shapes) {
        size_t corners = 0;
        for (const unsigned char n : shape.mesh.num_face_vertices) corners += n;
        if (corners != shape.mesh.indices.size())
            throw SceneError(
                SourceLocation{file_name, line_of_first_face(text, [](size_t n) { return n > 255; }), 0, {}},
                "a face has more than 255 vertices, the most tinyobjloader supports");
    }

    ObjMeshBuilder builder(text, file_name, attrib);
    builder.validate(shapes);
    return builder.build(shapes);
}

}  // namespace candela
