#include "candela/formats/pbrt/pbrt_convert.h"

#include <fmt/format.h>

#include "candela/core/atomic_file.h"
#include "candela/core/error.h"
#include "candela/formats/mesh/ply_writer.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"

namespace fs = std::filesystem;

namespace candela::pbrt {
namespace {

// The keys whose string values name files, relative to the scene's folder.
bool is_file_key(const std::string& key) { return key == "file" || key == "spectrum_file" || key == "normal_map"; }

// Makes the document's file names relative to the output's folder instead of the input's
// (meshes and curves of the stores keep their names: they are written beside the output).
void rebase_file_names(nlohmann::ordered_json& node, const fs::path& from, const fs::path& to,
                       const ImportedScene& store) {
    if (node.is_object()) {
        for (auto& [key, value] : node.items()) {
            if (value.is_string() && is_file_key(key)) {
                const std::string name = value.get<std::string>();
                if (store.meshes.count(name) || store.curves.count(name) || fs::path(name).is_absolute()) continue;
                const fs::path target = fs::weakly_canonical(fs::absolute(from / name));
                value = target.lexically_relative(fs::weakly_canonical(fs::absolute(to))).generic_string();
            } else {
                rebase_file_names(value, from, to, store);
            }
        }
    } else if (node.is_array()) {
        for (auto& element : node) rebase_file_names(element, from, to, store);
    }
}

}  // namespace

ConvertResult convert_pbrt_scene(const fs::path& in, const fs::path& out) {
    ImportedScene imported = import_pbrt_file(in);
    // Load it as a render would, so that a scene that cannot render is refused before writing.
    ConvertResult result;
    result.warnings = load_imported_scene(imported, in).warnings;
    const fs::path out_folder = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    // The output's folder is made when it is missing, whether or not meshes go into it.
    const auto make_folder = [](const fs::path& folder) {
        std::error_code ec;
        fs::create_directories(folder, ec);
        if (ec) throw SceneError(SourceLocation{folder.string(), 0, 0, ""}, "cannot create the folder: " + ec.message());
    };
    make_folder(out_folder);
    rebase_file_names(imported.document, in.parent_path().empty() ? fs::path(".") : in.parent_path(), out_folder,
                      imported);
    const auto folder_for = [&](const fs::path& file) {
        make_folder(file.parent_path());
        return file;
    };
    for (const auto& [name, mesh] : imported.meshes) write_ply(folder_for(out_folder / name), mesh);
    for (const auto& [name, curves] : imported.curves) write_curve_file(folder_for(out_folder / name), curves);
    write_contents_atomically(out, document_text(imported));
    result.mesh_files = imported.meshes.size();
    return result;
}

}  // namespace candela::pbrt
