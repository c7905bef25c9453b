// candela.Scene: a scene document loaded from a JSON or pbrt-v4 file, or made from a dict, and the
// conversion between JSON values and Python's.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/format.h>

#include <utility>

#include "bindings.h"
#include "candela/core/error.h"
#include "candela/formats/json/json_locator.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"
#include "candela/formats/scene_file.h"

namespace candela::python {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// Every element of a document made from a dict is located by its JSON pointer alone: there is no
// file whose lines the text that the loader reads would match.
std::optional<SourceLocation> no_file(const std::string&) { return SourceLocation{}; }

std::shared_ptr<const SceneDocument> load_file(const fs::path& file) {
    auto scene = std::make_shared<SceneDocument>();
    scene->file = file;
    if (is_pbrt_scene_file(file)) {
        auto imported = std::make_shared<pbrt::ImportedScene>(pbrt::import_pbrt_file(file));
        scene->document = imported->document;
        scene->imported = std::move(imported);
        scene->load(LoadOptions{});  // bad input is an error of load(), not of the first render
    } else {
        scene->text = read_text_file(file);
        // The loader's own parse reports bad JSON with its location; after a load that succeeded,
        // the document's parse cannot fail.
        scene->load(LoadOptions{});
        scene->document = Json::parse(*scene->text);
    }
    return scene;
}

// A new document: with `like`'s folder, in-memory meshes and (while the document is unchanged) text.
std::shared_ptr<const SceneDocument> from_dict(const py::dict& d, std::optional<fs::path> folder,
                                               const std::shared_ptr<const SceneDocument>& like) {
    auto scene = std::make_shared<SceneDocument>();
    scene->document = from_python(d);
    if (like) {
        scene->file = like->file;
        if (scene->document == like->document) scene->text = like->text;
        if (like->imported) {
            auto imported = std::make_shared<pbrt::ImportedScene>(*like->imported);
            imported->document = scene->document;
            scene->imported = std::move(imported);
        }
    }
    // A file name in no folder's listing: relative names resolve against `folder`, errors show none.
    if (folder) scene->file = *folder / "<dict>";
    py::gil_scoped_release release;  // loading reads meshes and images: other threads run meanwhile
    scene->load(LoadOptions{});
    return scene;
}

}  // namespace

Scene SceneDocument::load(const LoadOptions& options) const {
    if (imported) return pbrt::load_imported_scene(*imported, file, options);
    // The text loaded is what the content hash reads in place of the file (scene.h), which a dict
    // has not, and which may have changed since load().
    std::string json = text ? *text : document.dump(2);
    LoadOptions o = options;
    if (!text) o.source_map = no_file;
    Scene scene = load_scene_from_string(json, file, o);
    scene.translated_json = std::move(json);
    return scene;
}

py::object to_python(const Json& value) {
    switch (value.type()) {
        case Json::value_t::null: return py::none();
        case Json::value_t::boolean: return py::bool_(value.get<bool>());
        case Json::value_t::number_integer: return py::int_(value.get<int64_t>());
        case Json::value_t::number_unsigned: return py::int_(value.get<uint64_t>());
        case Json::value_t::number_float: return py::float_(value.get<double>());
        case Json::value_t::string: return py::str(value.get_ref<const std::string&>());
        case Json::value_t::array: {
            py::list out;
            for (const Json& v : value) out.append(to_python(v));
            return out;
        }
        case Json::value_t::object: {
            py::dict out;
            for (const auto& [key, v] : value.items()) out[py::str(key)] = to_python(v);
            return out;
        }
        default: throw py::type_error("a JSON value candela's documents do not hold (binary)");
    }
}

Json from_python(py::handle value, const std::string& pointer) {
    const auto where = [&] { return pointer.empty() ? std::string("/") : pointer; };
    if (value.is_none()) return nullptr;
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>();  // before int: bool is an int
    if (py::isinstance<py::int_>(value)) {
        if (py::reinterpret_borrow<py::int_>(value) < py::int_(0)) return value.cast<int64_t>();
        return value.cast<uint64_t>();
    }
    if (py::isinstance<py::float_>(value)) return value.cast<double>();
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::dict>(value)) {
        Json out = Json::object();
        for (const auto& [key, v] : py::reinterpret_borrow<py::dict>(value)) {
            if (!py::isinstance<py::str>(key))
                throw py::type_error(fmt::format("{}: a scene document's keys are strings, got {}", where(),
                                                 py::repr(key).cast<std::string>()));
            const std::string k = key.cast<std::string>();
            out[k] = from_python(v, fmt::format("{}/{}", pointer, escape_pointer_token(k)));
        }
        return out;
    }
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        Json out = Json::array();
        size_t i = 0;
        for (py::handle v : value) out.push_back(from_python(v, fmt::format("{}/{}", pointer, i++)));
        return out;
    }
    if (py::hasattr(value, "tolist")) return from_python(value.attr("tolist")(), pointer);  // numpy
    throw py::type_error(
        fmt::format("{}: a scene document holds dicts, lists, str, float, int, bool and None, "
                    "not {}",
                    where(), py::repr(py::type::handle_of(value)).cast<std::string>()));
}

void bind_scene(py::module_& m) {
    py::class_<SceneDocument, std::shared_ptr<SceneDocument>>(
        m, "Scene",
        "A scene: its JSON document (docs/SCENE_FORMAT.md) and what loading it needs besides.\n\n"
        "Immutable: change a scene by editing its dict and making a new one,\n"
        "Scene.from_dict(d, like=scene).")
        .def_static(
            "from_dict",
            [](const py::dict& d, std::optional<fs::path> folder, std::shared_ptr<const SceneDocument> like) {
                return std::const_pointer_cast<SceneDocument>(from_dict(d, std::move(folder), like));
            },
            py::arg("d"), py::kw_only(), py::arg("folder") = py::none(), py::arg("like") = py::none(),
            "A scene from a scene document (a dict as to_dict returns, or one written by hand).\n\n"
            "folder: where relative file names (meshes, images) resolve; default: like's folder, else the\n"
            "current folder. like: a scene whose folder, and for a pbrt-v4 scene whose meshes held in\n"
            "memory, the document may use; while d equals like's document, errors point at like's file.\n"
            "Raises SceneError (located by JSON pointer) for a document that does not load, TypeError\n"
            "for a value no JSON document holds.")
        .def(
            "to_dict", [](const SceneDocument& s) { return to_python(s.document); },
            "The scene document as a new dict (lists, str, float, int, bool, None): edit it freely.")
        .def_property_readonly(
            "file",
            [](const SceneDocument& s) -> std::optional<std::string> {
                if (s.text || s.imported) return s.file.string();
                return std::nullopt;
            },
            "The file it was loaded from; None for a scene made from a dict.")
        .def("__repr__", [](const SceneDocument& s) {
            return fmt::format("<candela.Scene {}>", s.text || s.imported ? s.file.string() : "from a dict");
        });
    m.def(
        "load", [](const fs::path& file) { return std::const_pointer_cast<SceneDocument>(load_file(file)); },
        py::arg("path"), py::call_guard<py::gil_scoped_release>(),
        "Loads a scene file: candela's JSON, or pbrt-v4's (.pbrt, .pbrt.gz), with all it names.\n\n"
        "Raises SceneError with the file, line and column of the problem, as the CLI reports it.");
}

}  // namespace candela::python
