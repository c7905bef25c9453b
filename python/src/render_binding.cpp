// candela.render's core: keywords into a render job (render/job/job.h), run with the GIL released;
// Python's signals (Ctrl-C) stop it at the next tile, and the progress callback hears of each pass.
// The image and AOV layers come back as float32 arrays.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <xmmintrin.h>
#include <algorithm>
#include <cctype>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>

#include "bindings.h"
#include "candela/core/error.h"
#include "candela/render/job/job.h"
#include "candela/scene/enum_names.h"

namespace candela::python {

namespace {

// An image's pixels as a new (height, width, channels) float32 array, channels 1 to 3 (an AOV
// layer keeps its first `channels` of r, g, b).
py::array_t<float> to_array(const Image& image, int channels) {
    py::array_t<float> out({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(channels)});
    float* to = out.mutable_data();
    if (channels == 3) {
        static_assert(sizeof(Rgb) == 3 * sizeof(float));
        std::memcpy(to, image.pixels.data(), image.pixels.size() * sizeof(Rgb));
    } else {
        for (const Rgb& p : image.pixels)
            for (int c = 0; c < channels; ++c) *to++ = p[c];
    }
    return out;
}

py::dict display_dict(const DisplayEncoding& d) {
    py::dict out;
    out["tonemap"] = std::string(tonemap_name(d.tonemap));
    out["exposure"] = d.exposure;
    out["transfer"] = std::string(transfer_name(d.transfer));
    out["gamma"] = d.gamma;
    return out;
}

const char* end_name(RenderEnd end) {
    switch (end) {
        case RenderEnd::kComplete: return "complete";
        case RenderEnd::kStopped: return "stopped";
        case RenderEnd::kDeadline: return "time_limit";
    }
    return "";
}

// The statistics `candela render --stats` writes, as a dict.
py::dict stats_dict(const RenderJobResult& r) {
    const RenderStats& s = r.render.stats;
    py::dict out;
    out["integrator"] = r.integrator;
    out["width"] = r.width;
    out["height"] = r.height;
    out["spp"] = r.spp;
    out["spp_done"] = r.render.state.samples_done;
    out["end"] = end_name(r.render.end);
    out["threads"] = s.threads;
    out["passes"] = s.passes;
    out["samples"] = s.samples;
    out["dropped_samples"] = s.dropped_samples;
    out["load_seconds"] = r.load_seconds;
    out["build_seconds"] = s.build_seconds;
    out["render_seconds"] = s.render_seconds;
    py::dict rays;
    rays["camera"] = s.rays.camera;
    rays["bounce"] = s.rays.bounce;
    rays["shadow"] = s.rays.shadow;
    rays["total"] = s.rays.total();
    out["rays"] = rays;
    out["relmse_estimate"] = s.relmse_estimate ? py::object(py::float_(*s.relmse_estimate)) : py::none();
    out["converged"] = s.converged;
    return out;
}

// The keywords that override the scene's settings, checked by the job as the CLI's flags are.
struct Keywords {
    std::optional<int> spp;
    std::optional<uint64_t> seed;
    std::optional<bool> spectral;
    std::optional<std::pair<int, int>> resolution;
    int threads = 0;
    std::optional<std::vector<std::string>> aovs;
    std::optional<double> target_error;
    std::optional<double> time_limit;
    std::optional<std::string> integrator;
    std::optional<std::string> sampler;
};

RenderOverrides overrides_of(const Keywords& k) {
    RenderOverrides o{.spp = k.spp, .seed = k.seed, .spectral = k.spectral, .target_error = k.target_error};
    if (k.resolution) o.resolution = Resolution{k.resolution->first, k.resolution->second};
    if (k.integrator) o.integrator = integrator_override("integrator", *k.integrator);
    if (k.sampler) o.sampler = sampler_override("sampler", *k.sampler);
    if (k.aovs) o.aovs = aov_layers_override("aovs", *k.aovs);
    return o;
}

// The render threads flush denormals to zero (geometry/accelerator.h, enable_flush_denormals), and
// the caller's thread is one of them (it takes tiles too): its mode (Python's, numpy's) is given
// back as it was when the job returns or throws.
class FloatingPointMode {
  public:
    FloatingPointMode() : csr_(_mm_getcsr()) {}
    ~FloatingPointMode() { _mm_setcsr(csr_); }
    FloatingPointMode(const FloatingPointMode&) = delete;
    FloatingPointMode& operator=(const FloatingPointMode&) = delete;

  private:
    unsigned int csr_;
};

// The job names a bad value by the CLI's flag ("--time-limit: expected seconds > 0, got 0"); Python
// names it by its keyword ("time_limit: ..."). Errors in files are left as they are.
SceneError by_keyword(const SceneError& e) {
    const std::string& m = e.message();
    if (!e.where().file.empty() || m.rfind("--", 0) != 0) return e;
    std::string keyword;
    size_t i = 2;
    for (; i < m.size() && (std::isalnum(static_cast<unsigned char>(m[i])) || m[i] == '-'); ++i)
        keyword += m[i] == '-' ? '_' : m[i];
    return SceneError(e.where(), keyword + m.substr(i));
}

// The caller's side of a render, on the caller's thread: the render job runs there (with the GIL
// released), and the job's stop function, which every render thread asks before each tile, takes
// the GIL back there a few times a second to run Python's signal handlers (Ctrl-C). TBB's calling
// thread works on the tiles too, so it asks before tiles as well as between passes.
class Caller {
  public:
    explicit Caller(std::optional<std::function<void(double)>> progress) : progress_(std::move(progress)) {}
    Caller(const Caller&) = delete;
    Caller& operator=(const Caller&) = delete;
    ~Caller() {  // with the GIL: an error kept but not raised (the job threw another) is dropped
        Py_XDECREF(type_);
        Py_XDECREF(value_);
        Py_XDECREF(traceback_);
    }

    // The job's stop function: SIGINT once a Python signal handler (or the progress callback) has
    // raised, else 0. Thread-safe; only the caller's thread enters Python.
    int stop() {
        if (std::this_thread::get_id() == thread_ && !raised_ && Clock::now() >= next_check_) {
            next_check_ = Clock::now() + kCheckEvery;
            py::gil_scoped_acquire acquire;
            if (PyErr_CheckSignals() != 0) keep_error();
        }
        return raised_.load(std::memory_order_relaxed) ? SIGINT : 0;
    }

    // After each complete pass, on the caller's thread: the progress callback.
    void passed(double fraction) {
        if (!progress_ || raised_ || fraction == reported_) return;
        reported_ = fraction;
        py::gil_scoped_acquire acquire;
        try {
            (*progress_)(fraction);
        } catch (py::error_already_set& e) {
            e.restore();
            keep_error();
        }
    }

    // With the GIL: raises the error that stopped the render, if one did.
    void rethrow() {
        if (!raised_) return;
        PyErr_Restore(type_, value_, traceback_);  // hands the references back
        type_ = value_ = traceback_ = nullptr;
        throw py::error_already_set();
    }

  private:
    using Clock = std::chrono::steady_clock;
    static constexpr std::chrono::milliseconds kCheckEvery{50};

    // Takes the pending Python error (with the GIL) to raise once the job has returned.
    void keep_error() {
        PyErr_Fetch(&type_, &value_, &traceback_);
        raised_ = true;
    }

    std::optional<std::function<void(double)>> progress_;
    double reported_ = -1;  // the fraction last reported
    const std::thread::id thread_ = std::this_thread::get_id();
    Clock::time_point next_check_ = Clock::now();  // the caller's thread's only
    std::atomic<bool> raised_{false};
    PyObject* type_ = nullptr;  // the error kept, owned until rethrow() hands it back to Python
    PyObject* value_ = nullptr;
    PyObject* traceback_ = nullptr;
};

py::tuple render(const std::shared_ptr<const SceneDocument>& scene, const Keywords& k,
                 std::optional<std::function<void(double)>> progress, bool progress_bar) {
    if (!scene) throw py::type_error("render: expected a candela.Scene, got None");
    Caller caller(std::move(progress));
    DisplayEncoding display;
    int spp = 0;
    RenderJobOptions o;
    o.scene = scene->file;
    o.load = [&](const LoadOptions& options) {
        Scene loaded = scene->load(options);
        display = loaded.film;
        spp = k.spp.value_or(loaded.sampler.spp);
        return loaded;
    };
    o.write_files = false;
    o.overrides = overrides_of(k);
    o.threads = k.threads;
    o.time_limit = k.time_limit;
    o.progress = progress_bar;
    o.stop = [&caller] { return caller.stop(); };
    o.on_pass = [&](const RenderState& state) {
        if (spp > 0) caller.passed(std::min(1.0, double(state.samples_done) / spp));
    };
    RenderJobResult result;
    {
        const FloatingPointMode kept;
        py::gil_scoped_release release;
        try {
            result = run_render_job(o);
        } catch (const SceneError& e) {
            throw by_keyword(e);
        }
    }
    caller.rethrow();
    // Complete: 1 (the passes may have said less, where adaptive sampling or a target stopped early).
    if (result.render.end == RenderEnd::kComplete) {
        caller.passed(1.0);
        caller.rethrow();
    }
    py::dict aovs;
    for (const ImageLayer& layer : result.render.aov_layers)
        aovs[py::str(layer.name)] = to_array(layer.image, layer.channels);
    return py::make_tuple(to_array(result.render.image, 3), aovs, stats_dict(result), display_dict(display));
}

}  // namespace

void bind_render(py::module_& m) {
    m.def(
        "render",
        [](const std::shared_ptr<SceneDocument>& scene, std::optional<int> spp, std::optional<uint64_t> seed,
           std::optional<bool> spectral, std::optional<std::pair<int, int>> resolution, int threads,
           std::optional<std::vector<std::string>> aovs, std::optional<double> target_error,
           std::optional<double> time_limit, std::optional<std::string> integrator, std::optional<std::string> sampler,
           std::optional<std::function<void(double)>> progress, bool progress_bar) {
            const Keywords k{spp,
                             seed,
                             spectral,
                             resolution,
                             threads,
                             std::move(aovs),
                             target_error,
                             time_limit,
                             std::move(integrator),
                             std::move(sampler)};
            return render(scene, k, std::move(progress), progress_bar);
        },
        py::arg("scene"), py::kw_only(), py::arg("spp") = py::none(), py::arg("seed") = py::none(),
        py::arg("spectral") = py::none(), py::arg("resolution") = py::none(), py::arg("threads") = 0,
        py::arg("aovs") = py::none(), py::arg("target_error") = py::none(), py::arg("time_limit") = py::none(),
        py::arg("integrator") = py::none(), py::arg("sampler") = py::none(), py::arg("progress") = py::none(),
        py::arg("progress_bar") = false);
}

}  // namespace candela::python
