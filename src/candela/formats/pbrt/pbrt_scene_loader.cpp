#include "candela/formats/pbrt/pbrt_scene_loader.h"

#include <map>

#include "candela/core/hash64.h"

namespace candela::pbrt {

std::string document_text(const ImportedScene& imported) { return imported.document.dump(2) + "\n"; }

Scene load_imported_scene(const ImportedScene& imported, const std::filesystem::path& file,
                          const LoadOptions& options) {
    auto origins = std::make_shared<std::map<std::string, Location>>();
    for (const auto& [pointer, at] : imported.origins) origins->emplace(pointer, at);
    LoadOptions o = options;
    o.meshes = &imported.meshes;
    o.curves = &imported.curves;
    // An element's origin is its own or its nearest enclosing element's.
    // Elements with no origin of their own (defaults the importer added) are located in the main
    // file as a whole: never at a line of the generated JSON text.
    o.source_map = [origins, main = file.string()](const std::string& pointer) -> std::optional<SourceLocation> {
        std::string p = pointer;
        while (true) {
            if (auto it = origins->find(p); it != origins->end())
                return SourceLocation{it->second.file, it->second.line, it->second.column, ""};
            const size_t slash = p.rfind('/');
            if (slash == std::string::npos || p.empty()) return SourceLocation{main, 0, 0, ""};
            p.resize(slash);
        }
    };
    std::string text = document_text(imported);
    Scene scene = load_scene_from_string(text, file, o);
    scene.translated_json = std::move(text);
    for (const auto& [name, mesh] : imported.meshes) {
        Hash64 h;
        h.add(mesh.positions.data(), mesh.positions.size() * sizeof(Vec3f));
        h.add(mesh.normals.data(), mesh.normals.size() * sizeof(Vec3f));
        h.add(mesh.uvs.data(), mesh.uvs.size() * sizeof(Vec2f));
        h.add(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
        scene.inline_file_hashes[name] = h.value();
    }
    for (const auto& [name, curves] : imported.curves) {
        Hash64 h;
        h.add(curves.points.data(), curves.points.size() * sizeof(Vec3f));
        h.add(curves.point_end.data(), curves.point_end.size() * sizeof(uint32_t));
        h.add(curves.widths.data(), curves.widths.size() * sizeof(float));
        h.add(curves.normals.data(), curves.normals.size() * sizeof(Vec3f));
        h.add(curves.normal_end.data(), curves.normal_end.size() * sizeof(uint32_t));
        scene.inline_file_hashes[name] = h.value();
    }
    scene.warnings.insert(scene.warnings.begin(), imported.warnings.begin(), imported.warnings.end());
    return scene;
}

Scene load_pbrt_scene(const std::filesystem::path& file, const LoadOptions& options) {
    return load_imported_scene(import_pbrt_file(file), file, options);
}

}  // namespace candela::pbrt
