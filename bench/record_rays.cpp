// candela_record_rays SCENE OUT [--spp N] [--resolution WxH]: renders SCENE on one thread through
// candela's own render() and writes every ray it traces, in order, with its kind (camera, bounce,
// shadow) and outcome, to OUT (bench/ray_file.h). candela_trace_bound then traces the same rays
// through Embree alone: the raw-traversal bound for this ray mix.
//
// The accelerator's RayObserver sees each query, not its kind. Shadow rays are the occlusion
// queries; a closest-hit query is a camera ray when it starts where the camera's rays start
// (position + near * direction, computed as PerspectiveCamera does), else a bounce. The recorded
// counts are checked against the renderer's own ray counters, so a misclassified ray, or a ray
// traced on another thread, is an error rather than a silently wrong mix.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <mutex>
#include <regex>
#include <string>
#include <vector>

#include "bench/ray_file.h"
#include "candela/geometry/accelerator.h"
#include "candela/render/renderer.h"
#include "candela/formats/json/scene_loader.h"

using namespace candela;
using bench::RayKind;
using bench::RecordedRay;

namespace {

class RayRecorder final : public RayObserver {
  public:
    explicit RayRecorder(const CameraSettings& camera) : camera_(camera) {}

    void observe(const Ray& ray, bool occlusion, bool hit) override {
        std::lock_guard<std::mutex> lock(mutex_);  // uncontended: the render runs on one thread
        RecordedRay r{};
        r.org[0] = ray.o.x, r.org[1] = ray.o.y, r.org[2] = ray.o.z;
        r.dir[0] = ray.d.x, r.dir[1] = ray.d.y, r.dir[2] = ray.d.z;
        r.tnear = ray.tmin;
        r.tfar = ray.tmax;
        r.kind = occlusion ? RayKind::kShadow : starts_at_camera(ray) ? RayKind::kCamera : RayKind::kBounce;
        r.hit = hit ? 1 : 0;
        ++counts_[int(r.kind)];
        rays_.push_back(r);
    }

    const std::vector<RecordedRay>& rays() const { return rays_; }
    uint64_t count(RayKind kind) const { return counts_[int(kind)]; }

  private:
    bool starts_at_camera(const Ray& ray) const {
        Vec3f o = camera_.position + ray.d * camera_.near;
        return ray.o.x == o.x && ray.o.y == o.y && ray.o.z == o.z;
    }

    CameraSettings camera_;
    std::mutex mutex_;
    std::vector<RecordedRay> rays_;
    uint64_t counts_[bench::kRayKindCount] = {};
};

int record(const std::string& scene_file, const std::string& out, int spp, const std::string& resolution) {
    Scene scene = load_scene(scene_file);
    if (spp > 0) scene.sampler.spp = spp;
    if (!resolution.empty()) {
        std::smatch m;
        if (!std::regex_match(resolution, m, std::regex(R"((\d{1,5})x(\d{1,5}))")))
            throw std::runtime_error("--resolution: expected WIDTHxHEIGHT, got " + resolution);
        scene.camera.width = std::stoi(m[1]);
        scene.camera.height = std::stoi(m[2]);
    }
    RayRecorder recorder(scene.camera);
    RenderOptions options;
    options.threads = 1;  // one thread: the rays in the order one render thread traces them
    set_ray_observer(&recorder);
    RenderResult result = render(scene, options);
    set_ray_observer(nullptr);

    const RayCounters& c = result.stats.rays;
    if (recorder.count(RayKind::kCamera) != c.camera || recorder.count(RayKind::kBounce) != c.bounce ||
        recorder.count(RayKind::kShadow) != c.shadow)
        throw std::runtime_error(fmt::format(
            "recorded camera/bounce/shadow rays {}/{}/{} differ from the renderer's counts {}/{}/{}",
            recorder.count(RayKind::kCamera), recorder.count(RayKind::kBounce), recorder.count(RayKind::kShadow),
            c.camera, c.bounce, c.shadow));
    bench::write_ray_file(out, recorder.rays());
    fmt::print("{}: {}x{}, {} spp: {} rays (camera {}, bounce {}, shadow {}) in {:.2f} s -> {}\n", scene_file,
               scene.camera.width, scene.camera.height, scene.sampler.spp, recorder.rays().size(), c.camera, c.bounce,
               c.shadow, result.stats.render_seconds, out);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Records the rays candela traces for a scene (bench/README.md)", "candela_record_rays"};
    std::string scene, out, resolution;
    int spp = 0;
    app.add_option("scene", scene, "Scene file")->required();
    app.add_option("out", out, "Ray file to write")->required();
    app.add_option("--spp", spp, "Samples per pixel (default: the scene's)");
    app.add_option("--resolution", resolution, "Image size WIDTHxHEIGHT (default: the scene's)");
    CLI11_PARSE(app, argc, argv);
    try {
        return record(scene, out, spp, resolution);
    } catch (const SceneError& e) {
        fmt::print(stderr, "candela_record_rays: error: {}\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "candela_record_rays: {}\n", e.what());
        return 1;
    }
}
