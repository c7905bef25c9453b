// candela_pbrt_parse_speed [--mb N] [--file SCENE.pbrt] [--keep]: how fast the pbrt-v4 parser
// reads scene text, and in how much memory. Writes a synthetic scene of about N MB (default 200)
// to a temporary file: blocks of a trianglemesh with big P, N, uv and indices arrays (numbers
// printed as exporters print them, 6 significant digits) followed by many small directives
// (AttributeBegin, Translate, Material, a sphere, AttributeEnd); then parses it with a target
// that only counts, on one thread, and prints MB/s (10^6 bytes of text per second, by wall
// clock and by the process's CPU time) and the process's peak RSS. --file parses an existing
// scene instead. The file was just written, so it is read from the page cache: this measures the
// parser, not the disk. On a shared machine the CPU figure is the parser's speed on one core.
#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_null_target.h"
#include "candela/formats/pbrt/pbrt_parser.h"

namespace {

namespace fs = std::filesystem;

struct CountingTarget : candela::pbrt::NullTarget {
    uint64_t parameters_seen = 0;
    uint64_t numbers = 0;
    void parameters(const candela::pbrt::ParameterList& list) override {
        for (const auto& p : list) {
            ++parameters_seen;
            numbers += p.numbers.size();
        }
    }
};

// A deterministic stream of values in [-1, 1) (a 64-bit LCG), so every run writes the same file.
struct Values {
    uint64_t state = 0x9E3779B97F4A7C15ull;
    double next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) * 0x1.0p-52 - 1.0;
    }
};

void write_scene(const fs::path& path, double megabytes) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path.string());
    fmt::memory_buffer out;
    Values v;
    const auto flush = [&] {
        std::fwrite(out.data(), 1, out.size(), f);
        out.clear();
    };
    fmt::format_to(std::back_inserter(out),
                   "LookAt 0 5 -10  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
                   "Film \"rgb\" \"integer xresolution\" 640 \"integer yresolution\" 480\nWorldBegin\n");
    constexpr int kVertices = 20000, kTriangles = 40000, kSmall = 1000;
    uint64_t written = 0;
    for (int block = 0; double(written) < megabytes * 1e6; ++block) {
        fmt::format_to(std::back_inserter(out), "AttributeBegin\n  Shape \"trianglemesh\"\n    \"point3 P\" [");
        for (int i = 0; i < 3 * kVertices; ++i) fmt::format_to(std::back_inserter(out), " {:.6g}", 10 * v.next());
        fmt::format_to(std::back_inserter(out), " ]\n    \"normal N\" [");
        for (int i = 0; i < 3 * kVertices; ++i) fmt::format_to(std::back_inserter(out), " {:.6g}", v.next());
        fmt::format_to(std::back_inserter(out), " ]\n    \"point2 uv\" [");
        for (int i = 0; i < 2 * kVertices; ++i)
            fmt::format_to(std::back_inserter(out), " {:.6g}", 0.5 + 0.5 * v.next());
        fmt::format_to(std::back_inserter(out), " ]\n    \"integer indices\" [");
        for (int i = 0; i < 3 * kTriangles; ++i)
            fmt::format_to(std::back_inserter(out), " {}", int((0.5 + 0.5 * v.next()) * (kVertices - 1)));
        fmt::format_to(std::back_inserter(out), " ]\nAttributeEnd\n");
        for (int i = 0; i < kSmall; ++i)
            fmt::format_to(std::back_inserter(out),
                           "AttributeBegin\n  Translate {:.6g} {:.6g} {:.6g}\n"
                           "  Material \"diffuse\" \"rgb reflectance\" [ {:.3g} {:.3g} {:.3g} ]\n"
                           "  Shape \"sphere\" \"float radius\" {:.3g}\nAttributeEnd\n",
                           v.next(), v.next(), v.next(), 0.5 + 0.5 * v.next(), 0.5 + 0.5 * v.next(),
                           0.5 + 0.5 * v.next(), 0.1 + 0.05 * v.next());
        written += out.size();
        flush();
    }
    flush();
    if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + path.string());
}

// User plus system time of this process: on a shared machine the wall time also counts other
// processes' turns.
double cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

long peak_rss_mib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;  // Linux: KiB
}

}  // namespace

int main(int argc, char** argv) {
    double megabytes = 200;
    fs::path file;
    bool keep = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--mb") && i + 1 < argc) {
            megabytes = std::atof(argv[++i]);
        } else if (!std::strcmp(argv[i], "--file") && i + 1 < argc) {
            file = argv[++i];
        } else if (!std::strcmp(argv[i], "--keep")) {
            keep = true;
        } else {
            std::fprintf(stderr, "usage: %s [--mb N] [--file SCENE.pbrt] [--keep]\n", argv[0]);
            return 2;
        }
    }
    try {
        const bool generated = file.empty();
        if (generated) {
            file = fs::temp_directory_path() / fmt::format("candela-pbrt-speed-{}.pbrt", ::getpid());
            const auto t0 = std::chrono::steady_clock::now();
            write_scene(file, megabytes);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            fmt::print("wrote {} ({:.1f} MB) in {:.1f} s; peak RSS so far {} MiB\n", file.string(),
                       double(fs::file_size(file)) / 1e6, s, peak_rss_mib());
        }
        const double bytes = double(fs::file_size(file));
        CountingTarget target;
        const auto t0 = std::chrono::steady_clock::now();
        const double cpu0 = cpu_seconds();
        candela::pbrt::parse_file(file, target);
        const double cpu = cpu_seconds() - cpu0;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        fmt::print(
            "parsed {:.1f} MB in {:.3f} s wall, {:.3f} s CPU: {:.1f} MB/s wall, {:.1f} MB/s CPU; {} parameters, "
            "{} numbers; peak RSS {} MiB\n",
            bytes / 1e6, seconds, cpu, bytes / 1e6 / seconds, bytes / 1e6 / cpu, target.parameters_seen, target.numbers,
            peak_rss_mib());
        if (generated && !keep) fs::remove(file);
    } catch (const candela::SceneError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
