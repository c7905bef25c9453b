// The extension module candela._candela: its errors and image files, and the bindings of the other
// files. The package python/candela/ wraps it (the Image array, the progress bar).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/format.h>
#include <stdlib.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <map>

#include "bindings.h"
#include "candela/core/error.h"
#include "candela/film/aov_layers.h"
#include "candela/image/image_io.h"
#include "candela/image/image_layers.h"
#include "candela/render/job/render_overrides.h"
#include "candela/scene/enum_names.h"

namespace candela::python {

// SceneError (bad input: the scene, a keyword's value, an image file) as candela.SceneError, a
// ValueError whose message is the line the CLI prints after "candela: error: ", with the parts
// as attributes; RenderError (a failure that is not the input's) as RuntimeError.
void bind_errors(py::module_& m) {
    static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
    scene_error.doc() =
        "Bad input: a scene file, a scene document, a keyword's value or an image file.\n\n"
        "str(e) is the line the command line prints: 'FILE:LINE:COL: /json/pointer: message'.\n"
        "Attributes: file (str, '' when not from a file), line and column (int, 0 when unknown),\n"
        "pointer (the JSON pointer into the scene document, '' when none), message (str).";
    py::register_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const SceneError& e) {
            const SourceLocation& at = e.where();
            py::object error = py::handle(scene_error.ptr())(py::str(e.what()));
            error.attr("file") = at.file;
            error.attr("line") = at.line;
            error.attr("column") = at.column;
            error.attr("pointer") = at.json_pointer;
            error.attr("message") = e.message();
            PyErr_SetObject(scene_error.ptr(), error.ptr());
        } catch (const RenderError& e) {
            PyErr_SetString(PyExc_RuntimeError, e.what());
        }
    });
}

namespace {

namespace fs = std::filesystem;
using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// A (height, width, 3) array, or (height, width) / (height, width, 1) grey, as an Image.
Image image_of(const FloatArray& a, const std::string& what) {
    const bool grey = a.ndim() == 2 || (a.ndim() == 3 && a.shape(2) == 1);
    if (!(grey || (a.ndim() == 3 && a.shape(2) == 3)) || a.shape(0) < 1 || a.shape(1) < 1) {
        std::string shape;
        for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
        throw py::value_error(
            fmt::format("{}: expected an array of shape (height, width, 3), (height, width, 1) "
                        "or (height, width), got shape ({})",
                        what, shape));
    }
    Image image(int(a.shape(1)), int(a.shape(0)));
    const float* from = a.data();
    for (Rgb& p : image.pixels) {
        p = grey ? Rgb(from[0]) : Rgb(from[0], from[1], from[2]);
        from += grey ? 1 : 3;
    }
    return image;
}

// The tone map and transfer of a display dict (the keys of the scene's "film"), defaults for the
// keys it lacks.
DisplayEncoding display_of(const std::optional<py::dict>& d) {
    DisplayEncoding e;
    if (!d) return e;
    for (const auto& [key, value] : *d) {
        const std::string k = key.cast<std::string>();
        if (k == "tonemap") {
            const std::string name = value.cast<std::string>();
            const std::optional<Tonemap> t = parse_tonemap(name);
            if (!t)
                bad_flag(fmt::format("tonemap: unknown tone map \"{}\"; expected one of: {}", name,
                                     names_list(tonemap_names())));
            e.tonemap = *t;
        } else if (k == "transfer") {
            const std::string name = value.cast<std::string>();
            const std::optional<Transfer> t = parse_transfer(name);
            if (!t)
                bad_flag(fmt::format("transfer: unknown transfer \"{}\"; expected one of: {}", name,
                                     names_list(transfer_names())));
            e.transfer = *t;
        } else if (k == "exposure") {
            e.exposure = value.cast<float>();
        } else if (k == "gamma") {
            e.gamma = value.cast<float>();
        } else {
            bad_flag(
                fmt::format("display: unknown key \"{}\"; expected one of: tonemap, exposure, transfer, gamma", k));
        }
    }
    return e;
}

// AOV arrays by layer name (the render's), with the layers' channel names.
std::vector<ImageLayer> layers_of(const std::map<std::string, FloatArray>& aovs) {
    std::vector<ImageLayer> layers;
    for (const auto& [name, array] : aovs) {
        const std::optional<AovLayer> layer = parse_aov_layer(name);
        if (!layer) bad_flag(fmt::format("aovs: unknown AOV layer \"{}\"; expected one of: {}", name, kAovLayerNames));
        const AovLayerInfo& info = aov_layer_info(*layer);
        ImageLayer l{name, info.channels, {}, image_of(array, "aovs[\"" + name + "\"]")};
        for (int c = 0; c < info.channels; ++c) l.channel_names[size_t(c)] = std::string(info.channel[size_t(c)]);
        layers.push_back(std::move(l));
    }
    return layers;
}

// The PNG the library writes for `image`, as bytes (a notebook's display): written to a folder
// of its own in the temporary folder, read back, removed.
py::bytes png_bytes(const Image& image, const DisplayEncoding& display) {
    std::string folder = (fs::temp_directory_path() / "candela-png-XXXXXX").string();
    if (!mkdtemp(folder.data())) throw RenderError("cannot make a temporary folder for the PNG");
    const fs::path file = fs::path(folder) / "image.png";
    std::string bytes;
    try {
        write_image(file, image, display);
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    } catch (...) {
        fs::remove_all(folder);
        throw;
    }
    fs::remove_all(folder);
    return py::bytes(bytes);
}

}  // namespace

void bind_images(py::module_& m) {
    m.def(
        "write",
        [](const fs::path& file, const FloatArray& image, const std::map<std::string, FloatArray>& aovs,
           const std::optional<py::dict>& display) {
            const Image pixels = image_of(image, "image");
            const DisplayEncoding encoding = display_of(display);
            const std::vector<ImageLayer> layers = layers_of(aovs);
            py::gil_scoped_release release;
            write_image_with_layers(file, pixels, layers, encoding);
        },
        py::arg("path"), py::arg("image"), py::arg("aovs"), py::arg("display"));
    m.def(
        "read",
        [](const fs::path& file) {
            Image image;
            {
                py::gil_scoped_release release;
                image = read_image(file);
            }
            py::array_t<float> out({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)});
            std::memcpy(out.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(Rgb));
            return out;
        },
        py::arg("path"));
    m.def(
        "png_bytes",
        [](const FloatArray& image, const std::optional<py::dict>& display) {
            return png_bytes(image_of(image, "image"), display_of(display));
        },
        py::arg("image"), py::arg("display"));
}

}  // namespace candela::python

PYBIND11_MODULE(_candela, m) {
    m.doc() = "candela's C++ core; use the package candela, which wraps it.";
    m.attr("__version__") = CANDELA_VERSION;
    candela::python::bind_errors(m);
    candela::python::bind_scene(m);
    candela::python::bind_render(m);
    candela::python::bind_images(m);
}
