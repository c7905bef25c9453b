#include "candela/formats/mesh/ply_gz_loader.h"

#include <algorithm>

#include "candela/formats/mesh/gzip_stream.h"
#include "candela/formats/mesh/ply_loader.h"

namespace candela {

TriangleMesh parse_ply_gz(std::string_view bytes, const std::string& file_name, const MeshSizeCheck& check) {
    if (!is_gzip(bytes)) return parse_ply(bytes, file_name, check);
    GzipStream stream(bytes, file_name);
    std::string ply;
    // A header is a few hundred bytes. Pieces double, so that looking for its end again after
    // each costs time linear in what was inflated; inflating stops early when the data is not a
    // PLY, and past 16 MiB without an end_header line: parse_ply_header then says what is wrong.
    constexpr size_t kFirstPiece = 4096, kMaxHeader = size_t{16} << 20;
    const auto header_complete = [&ply] {
        if (ply.size() >= 3 && !ply.starts_with("ply")) return true;
        const size_t end = ply.find("\nend_header");
        return end != std::string::npos && ply.find('\n', end + 1) != std::string::npos;
    };
    bool more = true;
    while (more && !header_complete() && ply.size() < kMaxHeader)
        more = stream.inflate_some(ply, std::max(kFirstPiece, ply.size()));
    const MeshSize size = ply_mesh_size(ply, file_name);
    if (check) check(size);
    stream.inflate_rest(ply);
    return parse_ply(ply, file_name);
}

}  // namespace candela
