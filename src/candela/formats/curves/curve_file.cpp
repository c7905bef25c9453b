#include "candela/formats/curves/curve_file.h"

#include <fmt/format.h>
#include <fmt/os.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "candela/core/error.h"

namespace candela {

void CurveData::add(std::span<const Vec3f> curve_points, float width0, float width1,
                    std::span<const Vec3f> end_normals) {
    points.insert(points.end(), curve_points.begin(), curve_points.end());
    point_end.push_back(uint32_t(points.size()));
    widths.push_back(width0);
    widths.push_back(width1);
    normals.insert(normals.end(), end_normals.begin(), end_normals.end());
    normal_end.push_back(uint32_t(normals.size()));
}

namespace {

// The numbers of one line, separated by blanks; false at the first that is not a number.
bool parse_numbers(std::string_view line, std::vector<float>& out, std::string& bad) {
    out.clear();
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        if (i == line.size()) break;
        size_t end = i;
        while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r') ++end;
        float v = 0;
        const char* first = line.data() + i;
        if (*first == '+') ++first;
        auto [ptr, ec] = std::from_chars(first, line.data() + end, v);
        if (ec != std::errc() || ptr != line.data() + end) {
            bad = std::string(line.substr(i, end - i));
            return false;
        }
        out.push_back(v);
        i = end;
    }
    return true;
}

}  // namespace

CurveData read_curve_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError({path.string(), 0, 0, {}}, "cannot open the curves file");
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    CurveData data;
    std::vector<float> v;
    std::string bad;
    int line_number = 0;
    size_t start = 0;
    while (start < s.size()) {
        size_t end = s.find('\n', start);
        if (end == std::string::npos) end = s.size();
        const std::string_view line(s.data() + start, end - start);
        start = end + 1;
        ++line_number;
        const auto fail = [&](const std::string& m) { throw SceneError({path.string(), line_number, 0, {}}, m); };
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string_view::npos || line[first] == '#') continue;
        if (!parse_numbers(line, v, bad)) fail(fmt::format("expected a number, found \"{}\"", bad.substr(0, 40)));
        if (v.size() < 3 || !(v[0] >= 1 && v[0] == std::floor(v[0])))
            fail("expected N width0 width1 and N control points (x y z each), N >= 1");
        const size_t n = size_t(v[0]);
        if (v.size() < 3 + 3 * n)
            fail(fmt::format("{} control points announced, {} numbers follow the widths", n, v.size() - 3));
        if ((v.size() - 3 - 3 * n) % 3 != 0) fail("the normals after the control points are not triples (x y z)");
        std::vector<Vec3f> p(n), normals((v.size() - 3 - 3 * n) / 3);
        for (size_t k = 0; k < n; ++k) p[k] = Vec3f(v[3 + 3 * k], v[4 + 3 * k], v[5 + 3 * k]);
        for (size_t k = 0; k < normals.size(); ++k) {
            const size_t o = 3 + 3 * n + 3 * k;
            normals[k] = Vec3f(v[o], v[o + 1], v[o + 2]);
        }
        data.add(p, v[1], v[2], normals);
    }
    if (data.curve_count() == 0) throw SceneError({path.string(), 0, 0, {}}, "the curves file holds no curves");
    return data;
}

void write_curve_file(const std::filesystem::path& path, const CurveData& data) {
    auto out = fmt::output_file(path.string());
    out.print("# candela curves: N width0 width1, N control points (x y z), then a ribbon's end normals\n");
    uint32_t p = 0, n = 0;
    for (size_t c = 0; c < data.curve_count(); ++c) {
        out.print("{} {} {}", data.point_end[c] - p, data.widths[2 * c], data.widths[2 * c + 1]);
        for (; p < data.point_end[c]; ++p) out.print(" {} {} {}", data.points[p].x, data.points[p].y, data.points[p].z);
        for (; n < data.normal_end[c]; ++n)
            out.print(" {} {} {}", data.normals[n].x, data.normals[n].y, data.normals[n].z);
        out.print("\n");
    }
}

std::string add_curves(CurveSet& set, const CurveData& data, CurveBasis basis, int degree) {
    uint32_t p = 0, n = 0;
    for (size_t c = 0; c < data.curve_count(); ++c) {
        const std::span<const Vec3f> points(data.points.data() + p, data.point_end[c] - p);
        const std::span<const Vec3f> normals(data.normals.data() + n, data.normal_end[c] - n);
        std::string error = add_curve(set, points, basis, degree, data.widths[2 * c], data.widths[2 * c + 1], normals);
        if (!error.empty()) return fmt::format("curve {}: {}", c + 1, error);
        p = data.point_end[c];
        n = data.normal_end[c];
    }
    return "";
}

}  // namespace candela
