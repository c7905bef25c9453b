// The `transform` key of shapes and lights: an array of steps, each an object with one key.
#include <fmt/format.h>

#include <array>

#include "candela/math/constants.h"
#include "candela/formats/json/scene_sections.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 4> kStepNames = {"translate", "scale", "rotate", "matrix"};

Transform read_scale(const JsonCursor& c) {
    // One factor scales uniformly. Zero would flatten the shape and leave normals undefined.
    if (c.is_number()) {
        double s = c.number();
        if (s == 0.0) c.fail_expected("a nonzero scale factor");
        return Transform::scale(Vec3d(s));
    }
    if (!c.is_array()) c.fail_expected("a scale: a number or an array of 3 numbers [x, y, z]");
    Vec3d s = c.vec3();
    std::vector<JsonCursor> e = c.elements();
    for (int i = 0; i < 3; ++i)
        if (s[i] == 0.0) e[size_t(i)].fail_expected("a nonzero scale factor");
    return Transform::scale(s);
}

Transform read_rotate(JsonCursor c) {
    JsonCursor axis_cursor = c.require("axis");
    Vec3d axis = axis_cursor.vec3();
    if (axis == Vec3d(0.0)) axis_cursor.fail_expected("a nonzero rotation axis");
    double angle_degrees = c.require("angle").number();
    c.reject_unknown_keys();
    return Transform::rotate(axis, angle_degrees * (kPiD / 180.0));
}

Transform read_matrix(const JsonCursor& c, MatrixRows rows) {
    std::vector<JsonCursor> e = c.elements(16, "an array of 16 numbers (a 4x4 matrix, row by row)");
    Transform::Matrix m{};
    for (size_t i = 0; i < 16; ++i) m[i / 4][i % 4] = e[i].number();
    // Only affine transforms keep spheres, disks, instances and media what they are; a mesh takes
    // a projective one vertex by vertex (its triangles stay triangles), an environment its
    // directions by the upper 3x3 (pbrt-v4's, whose scenes have such matrices).
    if (rows == MatrixRows::kProjective) {
        Transform t(m);
        if (!t.invertible())
            c.fail(fmt::format("the matrix is singular (determinant {}); a transform must be invertible",
                               t.determinant()));
        return t;
    }
    for (size_t col = 0; col < 4; ++col) {
        double want = col == 3 ? 1.0 : 0.0;
        if (m[3][col] != want)
            e[12 + col].fail(
                fmt::format("expected {} (the last row of a transform matrix is "
                            "[0, 0, 0, 1]), got {}",
                            want, e[12 + col].describe()));
    }
    Transform t(m);
    if (!t.invertible())
        c.fail(
            fmt::format("the matrix is singular (determinant {}); a transform must be "
                        "invertible",
                        t.determinant()));
    return t;
}

Transform read_step(JsonCursor step, MatrixRows rows) {
    std::vector<std::string> keys = step.keys();
    if (keys.empty())
        step.fail_expected(
            "a transform step: an object with one key, translate, scale, rotate or "
            "matrix");
    for (std::string_view name : kStepNames) step.has(name);
    step.reject_unknown_keys();
    if (keys.size() > 1)
        step.document().fail_at_key(step.pointer(), keys[1],
                                    fmt::format("a transform step has one key; put {} in a step "
                                                "of its own",
                                                json_quoted(keys[1])));
    JsonCursor value = *step.get(keys[0]);
    if (keys[0] == "translate") return Transform::translate(value.vec3());
    if (keys[0] == "scale") return read_scale(value);
    if (keys[0] == "rotate") return read_rotate(value);
    return read_matrix(value, rows);
}

}  // namespace

Transform read_transform(const JsonCursor& steps, MatrixRows rows) {
    if (!steps.is_array())
        steps.fail_expected("an array of transform steps, e.g. [{\"translate\": [0, 1, 0]}]");
    Transform total;
    for (const JsonCursor& step : steps.elements()) total = read_step(step, rows) * total;
    // Each step is invertible, but their product may still underflow (two scales of 1e-200).
    if (!total.invertible())
        steps.fail(fmt::format("the transform is singular (determinant {})", total.determinant()));
    return total;
}

}  // namespace candela
