// Motion blur in a scene file: the time intervals of the camera's shutter and of motions, and the
// `motion` of shapes and instances (geometry/instance_motion.h).
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "candela/formats/json/scene_sections.h"
#include "candela/scene/enum_names.h"

namespace candela {

std::array<double, 2> read_time_interval(const JsonCursor& v, std::string_view first, std::string_view second) {
    auto e = v.elements(2, fmt::format("an array of 2 numbers [{}, {}]", first, second));
    const std::array<double, 2> t{e[0].number(), e[1].number()};
    if (!(t[1] > t[0])) e[1].fail(fmt::format("{} must be after {} ({}), got {}", second, first, t[0], t[1]));
    return t;
}

AnimatedTransform read_motion(JsonCursor motion, const Transform& start) {
    if (!motion.is_object())
        motion.fail_expected("an object {\"transform\": the transform at the end, \"times\": [start, end]}");
    std::array<double, 2> times{0.0, 1.0};
    if (auto v = motion.get("times")) times = read_time_interval(*v, "start", "end");
    const JsonCursor transform = motion.require("transform");
    const Transform end = read_transform(transform);
    motion.reject_unknown_keys();
    // pbrt-v4's decomposition has no rotation between a mirrored and an unmirrored frame.
    if (end.swaps_handedness() != start.swaps_handedness())
        transform.fail(fmt::format("the end transform {} space and the start transform does not; a motion cannot "
                                   "turn one into the other",
                                   end.swaps_handedness() ? "mirrors" : "keeps the handedness of"));
    return AnimatedTransform(start, times[0], end, times[1]);
}

void check_instance_range(const Instance& instance, const Transform& to_world, const ObjectBounds& bounds,
                          const JsonCursor& blame, std::string_view what) {
    // Embree places the object by a float matrix, and hits on it are float: the matrix, its
    // inverse and the object's corners must stay within float range.
    for (const AffineMap* map : {&instance.to_world, &instance.to_object})
        for (const auto& row : map->m)
            for (float v : row)
                if (!std::isfinite(v))
                    blame.fail(fmt::format("the transform of {} {} beyond float range", what,
                                           map == &instance.to_world ? "reaches" : "has an inverse"));
    if (bounds.empty()) return;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p((corner & 1) ? bounds.hi.x : bounds.lo.x, (corner & 2) ? bounds.hi.y : bounds.lo.y,
                      (corner & 4) ? bounds.hi.z : bounds.lo.z);
        if (!is_finite(Vec3f(to_world.apply_point(p))))
            blame.fail(fmt::format("the transform moves {} beyond float range", what));
    }
}

namespace {

// The box around shape `shape` as the loader placed it.
ObjectBounds shape_bounds(const Shape& shape, const Scene& scene) {
    ObjectBounds b;
    switch (shape.kind) {
        case ShapeKind::kMesh: b.add(scene.meshes[shape.index]); break;
        case ShapeKind::kSphere: b.add(scene.spheres[shape.index]); break;
        case ShapeKind::kDisk: b.add(scene.disks[shape.index]); break;
        case ShapeKind::kQuadric: b.add(scene.quadrics[shape.index]); break;
        case ShapeKind::kCurves:
            for (const CurvePoint& c : scene.curves[shape.index].points) {
                b.add(Vec3d(c.p) - Vec3d(double(c.r)));
                b.add(Vec3d(c.p) + Vec3d(double(c.r)));
            }
            break;
    }
    return b;
}

}  // namespace

void make_shape_move(const JsonCursor& motion, const Transform& start, Scene& scene) {
    const AnimatedTransform path = read_motion(motion, start);
    if (!path.animated()) return;  // the end is the start: it stands still
    // The shape's geometry is in the world at its start transform: its instance takes it back to
    // the shape's own space, then along the path.
    const auto id = static_cast<uint32_t>(scene.shapes.size() - 1);
    const auto object = static_cast<uint32_t>(scene.objects.size());
    const std::string name = motion.pointer();
    const Transform placement = start.inverse();
    const ObjectBounds bounds = shape_bounds(scene.shapes[id], scene);
    for (const Transform& end : {path.start(), path.end()}) {
        const Transform to_world = end * placement;
        check_instance_range(make_instance(object, to_world), to_world, bounds, motion, "the moving shape");
    }
    scene.objects.push_back(ObjectShapes{id, 1});
    scene.object_names.push_back(name);
    Instance instance = make_instance(object, path.at(scene.camera.shutter[0]) * placement);
    instance.motion = static_cast<uint32_t>(scene.instance_motions.size());
    scene.instance_motions.push_back(InstanceMotion{path, placement});
    scene.instances.push_back(instance);
}

}  // namespace candela
