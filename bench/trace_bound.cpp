// candela_trace_bound SCENE RAYS [--threads 1,2] [--summary FILE] [--benchmark_* flags]
//
// The raw-traversal bound: traces the rays candela_record_rays recorded for SCENE through Embree
// alone, on the very RTCScene candela builds (same flags, same geometry, via
// Accelerator::embree_scene()), with no shading, sampling or hit-record work. A Google Benchmark
// per ray kind (camera and bounce rays with rtcIntersect1, shadow rays with rtcOccluded1) and for
// the recorded mix in its recorded order, at each thread count (the list is split into one
// contiguous slice per thread); the *_stream variants hand Embree batches of 256 rays
// (rtcIntersect1M / rtcOccluded1M). Counter Mrays (shown per second) is the throughput of all
// threads together.
//
// Before timing, one pass checks that every ray's outcome (hit or not, occluded or not) equals
// the renderer's: a different scene or build would show here, not as a wrong bound.
// --summary FILE writes one line per benchmark, "NAME THREADS MRAYS_PER_S" (the median when
// --benchmark_repetitions is given), for bench/run.sh.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "bench/ray_file.h"
#include "candela/geometry/accelerator.h"
#include "candela/formats/json/scene_loader.h"

using namespace candela;
using bench::RayKind;
using bench::RecordedRay;

namespace {

constexpr unsigned kStreamBatch = 256;

RTCRay to_rtc(const RecordedRay& r) {
    RTCRay ray;
    ray.org_x = r.org[0], ray.org_y = r.org[1], ray.org_z = r.org[2];
    ray.dir_x = r.dir[0], ray.dir_y = r.dir[1], ray.dir_z = r.dir[2];
    ray.tnear = r.tnear;
    ray.tfar = r.tfar;
    ray.time = 0.0f;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

RTCRayHit to_rtc_hit(const RecordedRay& r) {
    RTCRayHit rh;
    rh.ray = to_rtc(r);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

// One query per ray, as candela traces them; returns how many hit (or were occluded).
uint64_t trace_single(RTCScene scene, const RecordedRay* begin, const RecordedRay* end) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    uint64_t hits = 0;
    for (const RecordedRay* r = begin; r != end; ++r) {
        if (r->kind == RayKind::kShadow) {
            RTCRay ray = to_rtc(*r);
            rtcOccluded1(scene, &context, &ray);
            hits += ray.tfar == -INFINITY;
        } else {
            RTCRayHit rh = to_rtc_hit(*r);
            rtcIntersect1(scene, &context, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    return hits;
}

// Batches of kStreamBatch rays of one kind through Embree's stream API.
uint64_t trace_stream(RTCScene scene, const RecordedRay* begin, const RecordedRay* end, bool coherent) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    static thread_local std::vector<RTCRayHit> hits_buffer(kStreamBatch);
    static thread_local std::vector<RTCRay> rays_buffer(kStreamBatch);
    uint64_t hits = 0;
    const bool shadow = begin != end && begin->kind == RayKind::kShadow;
    for (const RecordedRay* b = begin; b < end; b += kStreamBatch) {
        const auto m = unsigned(std::min<ptrdiff_t>(kStreamBatch, end - b));
        if (shadow) {
            for (unsigned i = 0; i < m; ++i) rays_buffer[i] = to_rtc(b[i]);
            rtcOccluded1M(scene, &context, rays_buffer.data(), m, sizeof(RTCRay));
            for (unsigned i = 0; i < m; ++i) hits += rays_buffer[i].tfar == -INFINITY;
        } else {
            for (unsigned i = 0; i < m; ++i) hits_buffer[i] = to_rtc_hit(b[i]);
            rtcIntersect1M(scene, &context, hits_buffer.data(), m, sizeof(RTCRayHit));
            for (unsigned i = 0; i < m; ++i) hits += hits_buffer[i].hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    return hits;
}

// Every ray's outcome must match the renderer's; returns the number that differ.
uint64_t count_mismatches(RTCScene scene, const std::vector<RecordedRay>& rays) {
    uint64_t differ = 0;
    for (const RecordedRay& r : rays) differ += trace_single(scene, &r, &r + 1) != r.hit;
    return differ;
}

struct Workload {
    std::string name;
    std::vector<RecordedRay> rays;
    bool stream = false;
    bool coherent = false;
};

void run_workload(benchmark::State& state, RTCScene scene, const Workload* w) {
    enable_flush_denormals();  // as the render threads do
    const size_t n = w->rays.size();
    const auto t = size_t(state.thread_index()), threads = size_t(state.threads());
    const RecordedRay* begin = w->rays.data() + n * t / threads;
    const RecordedRay* end = w->rays.data() + n * (t + 1) / threads;
    uint64_t hits = 0;
    for (auto _ : state)
        hits += w->stream ? trace_stream(scene, begin, end, w->coherent) : trace_single(scene, begin, end);
    benchmark::DoNotOptimize(hits);
    // Summed over threads, then divided by the (real) time: the throughput of all threads.
    state.counters["Mrays"] = benchmark::Counter(double(end - begin) * double(state.iterations()) / 1e6,
                                                   benchmark::Counter::kIsRate);
}

// The console table, plus the summary lines bench/run.sh reads.
class SummaryReporter : public benchmark::ConsoleReporter {
  public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs) {
            const bool single = run.repetitions <= 1 && run.run_type == Run::RT_Iteration;
            const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
            auto it = run.counters.find("Mrays");
            if ((single || median) && !run.error_occurred && it != run.counters.end())
                lines += fmt::format("{} {} {:.3f}\n", run.run_name.function_name, run.threads, it->second.value);
        }
        ConsoleReporter::ReportRuns(runs);
    }
    std::string lines;
};

std::vector<int> parse_threads(const std::string& list) {
    std::vector<int> out;
    size_t pos = 0;
    while (pos <= list.size()) {
        size_t comma = list.find(',', pos);
        if (comma == std::string::npos) comma = list.size();
        int t = std::stoi(list.substr(pos, comma - pos));
        if (t < 1) throw std::runtime_error("--threads: expected a list of integers >= 1");
        out.push_back(t);
        pos = comma + 1;
    }
    return out;
}

int run(int argc, char** argv) {
    std::vector<std::string> positional;
    std::string threads_list = "1,2", summary;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--threads" && i + 1 < argc)
            threads_list = argv[++i];
        else if (a == "--summary" && i + 1 < argc)
            summary = argv[++i];
        else if (a.starts_with("--"))
            throw std::runtime_error("unknown option " + a);
        else
            positional.push_back(a);
    }
    if (positional.size() != 2) {
        fmt::print(stderr, "usage: candela_trace_bound SCENE RAYS [--threads 1,2] [--summary FILE] [--benchmark_...]\n");
        return 2;
    }
    const std::vector<int> thread_counts = parse_threads(threads_list);

    Scene scene = load_scene(positional[0]);
    Accelerator accel(scene.meshes, scene.spheres, scene.shapes);
    auto rtc_scene = static_cast<RTCScene>(accel.embree_scene());
    std::vector<RecordedRay> rays = bench::read_ray_file(positional[1]);

    enable_flush_denormals();
    if (uint64_t differ = count_mismatches(rtc_scene, rays))
        throw std::runtime_error(fmt::format("{} of {} rays have another outcome than when recorded: is {} the "
                                             "scene the rays were recorded from?",
                                             differ, rays.size(), positional[0]));

    std::vector<Workload> workloads;
    for (int k = 0; k < bench::kRayKindCount; ++k) {
        Workload w{bench::kRayKindNames[k], {}, false, k == int(RayKind::kCamera)};
        for (const RecordedRay& r : rays)
            if (r.kind == RayKind(k)) w.rays.push_back(r);
        Workload s = w;
        s.name += "_stream";
        s.stream = true;
        workloads.push_back(std::move(w));
        workloads.push_back(std::move(s));
    }
    workloads.push_back({"mix", rays, false, false});
    rays.clear();
    rays.shrink_to_fit();

    for (const Workload& w : workloads) {
        if (w.rays.empty()) continue;
        for (int t : thread_counts)
            benchmark::RegisterBenchmark(w.name.c_str(), run_workload, rtc_scene, &w)
                ->Threads(t)
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond);
    }
    SummaryReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    if (!summary.empty()) {
        std::FILE* f = std::fopen(summary.c_str(), "w");
        if (!f || std::fputs(reporter.lines.c_str(), f) < 0 || std::fclose(f) != 0)
            throw std::runtime_error("cannot write " + summary);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);  // takes the --benchmark_* flags out of argv
    try {
        return run(argc, argv);
    } catch (const SceneError& e) {
        fmt::print(stderr, "candela_trace_bound: error: {}\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "candela_trace_bound: {}\n", e.what());
        return 1;
    }
}
