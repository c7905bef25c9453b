#pragma once
// Curves as pbrt-v4 gives them, one record per curve, before they become Bezier segments
// (geometry/curves.h): what a `.curves` file holds, what the pbrt importer collects from a run of
// `Shape "curve"` directives (kept in memory under a file name, like the mesh store, and written
// by `candela convert` beside the converted scene), and what a JSON `curves` shape reads.
//
// The `.curves` file (docs/SCENE_FORMAT.md): plain text, one curve per line,
//     N width0 width1 x1 y1 z1 ... xN yN zN [nx ny nz ...]
// N control points, the width at the curve's start and end, the points, and for ribbons the
// normals at the segments' ends. Blank lines and lines starting with '#' are skipped. The basis,
// degree and kind of curve are the JSON shape's.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "candela/geometry/curves.h"

namespace candela {

struct CurveData {
    std::vector<Vec3f> points;        // every curve's control points, one after the other
    std::vector<uint32_t> point_end;  // per curve, one past its last point
    std::vector<float> widths;        // per curve, width0 and width1
    std::vector<Vec3f> normals;       // ribbons: every curve's end normals, one after the other
    std::vector<uint32_t> normal_end; // per curve, one past its last normal

    size_t curve_count() const { return point_end.size(); }
    size_t bytes() const {
        return (points.size() + normals.size()) * sizeof(Vec3f) +
               (point_end.size() + normal_end.size()) * sizeof(uint32_t) + widths.size() * sizeof(float);
    }
    void add(std::span<const Vec3f> curve_points, float width0, float width1, std::span<const Vec3f> end_normals);
};

// Curves held in memory under the file names a translated scene gives them (as mesh_store.h).
using CurveStore = std::map<std::string, CurveData>;

// Reads a `.curves` file; a malformed line throws SceneError naming the file and the line.
CurveData read_curve_file(const std::filesystem::path& path);
// Writes `data` as a `.curves` file (exact: floats in their shortest round-trip form).
void write_curve_file(const std::filesystem::path& path, const CurveData& data);

// Adds every curve of `data` to `set`, as add_curve does one. Returns "" or what is wrong with the
// first bad curve, naming it ("curve 12: ...").
std::string add_curves(CurveSet& set, const CurveData& data, CurveBasis basis, int degree);

}  // namespace candela
