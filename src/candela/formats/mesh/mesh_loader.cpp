#include "candela/formats/mesh/mesh_loader.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>

#include "candela/core/error.h"
#include "candela/formats/mesh/obj_loader.h"
#include "candela/formats/mesh/ply_gz_loader.h"
#include "candela/formats/mesh/ply_loader.h"

namespace candela {
namespace {

using MeshParser = TriangleMesh (*)(std::string_view bytes, const std::string& file_name,
                                    const MeshSizeCheck& check);

struct MeshFormat {
    std::string_view extension;  // lower case, with the dot
    MeshParser parse;
};

// The one table of mesh formats: dispatch and the error message both read it. A file name is
// matched by its ending, the longest matching extension winning.
constexpr MeshFormat kMeshFormats[] = {{".obj", parse_obj}, {".ply", parse_ply}, {".ply.gz", parse_ply_gz}};

std::string lower_case(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

[[noreturn]] void fail(const std::string& name, const std::string& message) {
    throw SceneError(SourceLocation{name, 0, 0, {}}, message);
}

// The file's bytes, mapped rather than read: the page cache holds them, so a large file costs no
// memory of its own, and a PLY whose header alone shows it too large is refused before its data
// is touched.
class MappedFile {
  public:
    MappedFile(const std::filesystem::path& file, const std::string& name) {
        // O_NONBLOCK: opening a FIFO must not wait for a writer (it is refused below).
        const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
        if (fd < 0)
            fail(name, fmt::format("cannot read mesh file: {}", errno == ENOENT ? "no such file" : std::strerror(errno)));
        struct stat st {};
        if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
            ::close(fd);
            fail(name, S_ISDIR(st.st_mode) ? "cannot read mesh file: not a regular file (a folder)"
                                           : "cannot read mesh file: not a regular file");
        }
        size_ = static_cast<size_t>(st.st_size);
        if (size_ > 0) {
            void* data = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
            const int error = errno;
            ::close(fd);
            if (data == MAP_FAILED) fail(name, fmt::format("cannot read mesh file: {}", std::strerror(error)));
            data_ = static_cast<const char*>(data);
        } else {
            ::close(fd);
        }
    }
    ~MappedFile() {
        if (data_) ::munmap(const_cast<char*>(data_), size_);
    }
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;

    std::string_view bytes() const { return {data_ ? data_ : "", size_}; }

  private:
    const char* data_ = nullptr;
    size_t size_ = 0;
};

// What both formats share once parsed: a mesh must have triangles and finite values, and its
// normals are made unit length. A zero-length or non-finite normal has no direction to give, so
// the whole mesh then drops its normals and renders with geometric normals (flat shading), rather
// than mixing interpolated and made-up ones; files with such normals exist (degenerate regions of
// scans), and refusing them would refuse usable geometry.
}  // namespace

void finish_loaded_mesh(TriangleMesh& mesh, const std::string& name) {
    if (mesh.triangle_count() == 0)
        throw SceneError(SourceLocation{name, 0, 0, {}}, "the mesh file has no triangles");
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        if (!is_finite(mesh.positions[i]))
            throw SceneError(SourceLocation{name, 0, 0, {}},
                             fmt::format("vertex {} has a non-finite position", i + 1));
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!std::isfinite(mesh.uvs[i].x) || !std::isfinite(mesh.uvs[i].y))
            throw SceneError(SourceLocation{name, 0, 0, {}},
                             fmt::format("vertex {} has a non-finite uv", i + 1));
    const bool normals_usable = std::all_of(mesh.normals.begin(), mesh.normals.end(), [](const Vec3f& n) {
        const float l2 = length_squared(n);
        return std::isfinite(l2) && l2 > 0.0f;
    });
    if (!normals_usable) {
        mesh.normals.clear();
        return;
    }
    for (Vec3f& n : mesh.normals) n = normalize(n);
}

TriangleMesh load_mesh(const std::filesystem::path& file, const MeshSizeCheck& check) {
    const std::string name = file.string();
    const std::string file_name = lower_case(file.filename().string());
    const MeshFormat* match = nullptr;
    for (const MeshFormat& format : kMeshFormats)
        if (file_name.ends_with(format.extension) && (!match || format.extension.size() > match->extension.size()))
            match = &format;
    if (match) {
        const MappedFile bytes(file, name);
        TriangleMesh mesh = match->parse(bytes.bytes(), name, check);
        finish_loaded_mesh(mesh, name);
        return mesh;
    }
    std::string known;
    for (const MeshFormat& format : kMeshFormats) {
        if (!known.empty()) known += ", ";
        known += format.extension;
    }
    throw SceneError(SourceLocation{name, 0, 0, {}},
                     fmt::format("unknown mesh file extension \"{}\"; expected one of: {}",
                                 file.extension().string(), known));
}

}  // namespace candela
