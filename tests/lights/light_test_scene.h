#pragma once
// Small scenes of emitters for the light tests, and the density over directions that
// LightSet::sample induces at a reference point, computed independently of the sampler by
// tracing the direction through every light.
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "candela/geometry/disk_intersection.h"
#include "candela/geometry/sphere_intersection.h"
#include "candela/lights/light_set.h"

namespace candela::test {

struct LightTestScene {
    std::vector<TriangleMesh> meshes;
    std::vector<Sphere> spheres;
    std::vector<Disk> disks;
    std::vector<Shape> shapes;
    std::vector<DeltaLight> delta_lights;

    // Adds a shape and returns its id. Build the LightSet after the last one (it keeps spans).
    uint32_t add_mesh(TriangleMesh mesh, Rgb emission, bool two_sided = false) {
        meshes.push_back(std::move(mesh));
        shapes.push_back({ShapeKind::kMesh, static_cast<uint32_t>(meshes.size() - 1), 0, emission, two_sided});
        return static_cast<uint32_t>(shapes.size() - 1);
    }
    uint32_t add_sphere(Sphere sphere, Rgb emission, bool two_sided = false) {
        spheres.push_back(sphere);
        shapes.push_back({ShapeKind::kSphere, static_cast<uint32_t>(spheres.size() - 1), 0, emission, two_sided});
        return static_cast<uint32_t>(shapes.size() - 1);
    }
    uint32_t add_disk(const Disk& disk, Rgb emission, bool two_sided = false) {
        disks.push_back(disk);
        shapes.push_back({ShapeKind::kDisk, static_cast<uint32_t>(disks.size() - 1), 0, emission, two_sided});
        return static_cast<uint32_t>(shapes.size() - 1);
    }
    void add_delta_light(const DeltaLight& light) { delta_lights.push_back(light); }
    // The light set of the shapes and delta lights (and `environment`), in a scene of bounding
    // radius `scene_radius` (directional lights' and the environment's power).
    LightSet light_set(LightSelection selection = LightSelection::kPower,
                       std::optional<EnvironmentLight> environment = std::nullopt, float scene_radius = 1.0f) const {
        return LightSet(meshes, spheres, disks, shapes, delta_lights, selection, std::move(environment), scene_radius);
    }

    // The density per solid angle of the direction w (unit) of normalize(sample().p - ref): the sum
    // of LightSet::pdf over every light point on the ray from ref, because area sampling also draws
    // points hidden behind others of the same mesh. A sphere seen from outside counts once: its
    // cone sampling draws only the visible point of each direction. A disk is planar: one point.
    // Delta lights have no density over directions and are left out.
    double direction_pdf(const LightSet& lights, const Vec3f& ref, const Vec3f& w) const {
        double sum = 0.0;
        for (uint32_t id = 0; id < shapes.size(); ++id) {
            const Shape& shape = shapes[id];
            if (shape.kind == ShapeKind::kSphere) {
                const Sphere& s = spheres[shape.index];
                std::optional<double> t = intersect_sphere(s, Vec3d(ref), Vec3d(w), 0.0, 1e30);
                if (!t) continue;
                Vec3d p = project_to_sphere(s, Vec3d(ref) + Vec3d(w) * *t);
                Vec3f n((p - s.center) / s.radius);
                sum += static_cast<double>(lights.pdf(ref, id, Vec3f(p), n));
                continue;
            }
            if (shape.kind == ShapeKind::kDisk) {
                const Disk& d = disks[shape.index];
                std::optional<double> t = intersect_disk(d, Vec3d(ref), Vec3d(w), 0.0, 1e30);
                if (!t) continue;
                Vec3d p = project_to_disk_plane(d, Vec3d(ref) + Vec3d(w) * *t);
                sum += static_cast<double>(lights.pdf(ref, id, Vec3f(p), Vec3f(d.normal)));
                continue;
            }
            const TriangleMesh& m = meshes[shape.index];
            for (size_t t = 0; t < m.triangle_count(); ++t) {
                std::optional<Vec3d> p = intersect_triangle(m, t, Vec3d(ref), Vec3d(w));
                if (!p) continue;
                Vec3f n = normalize(cross(m.positions[m.indices[3 * t + 1]] - m.positions[m.indices[3 * t]],
                                          m.positions[m.indices[3 * t + 2]] - m.positions[m.indices[3 * t]]));
                sum += static_cast<double>(lights.pdf(ref, id, Vec3f(*p), n));
            }
        }
        return sum;
    }

    // The point where the ray o + t d (t > 0) crosses triangle t of m (Moller-Trumbore, double).
    static std::optional<Vec3d> intersect_triangle(const TriangleMesh& m, size_t t, const Vec3d& o, const Vec3d& d) {
        Vec3d p0(m.positions[m.indices[3 * t]]), p1(m.positions[m.indices[3 * t + 1]]),
            p2(m.positions[m.indices[3 * t + 2]]);
        Vec3d e1 = p1 - p0, e2 = p2 - p0;
        Vec3d pv = cross(d, e2);
        double det = dot(e1, pv);
        if (std::abs(det) < 1e-300) return std::nullopt;  // parallel, or a degenerate triangle
        Vec3d tv = o - p0;
        double b1 = dot(tv, pv) / det;
        Vec3d qv = cross(tv, e1);
        double b2 = dot(d, qv) / det;
        double dist = dot(e2, qv) / det;
        if (b1 < 0.0 || b2 < 0.0 || b1 + b2 > 1.0 || dist <= 0.0) return std::nullopt;
        return p0 * (1.0 - b1 - b2) + p1 * b1 + p2 * b2;
    }
};

// A mesh of one triangle.
inline TriangleMesh make_triangle(const Vec3f& p0, const Vec3f& p1, const Vec3f& p2) {
    TriangleMesh m;
    m.positions = {p0, p1, p2};
    m.indices = {0, 1, 2};
    return m;
}

}  // namespace candela::test
