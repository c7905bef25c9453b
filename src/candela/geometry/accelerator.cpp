#include "candela/geometry/accelerator.h"

#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <vector>

#include "candela/core/check.h"
#include "candela/core/error.h"
#include "candela/geometry/curve_hit.h"
#include "candela/geometry/disk_intersection.h"
#include "candela/geometry/instance_motion.h"
#include "candela/geometry/quadric_intersection.h"
#include "candela/geometry/ray_offset.h"
#include "candela/geometry/sphere_intersection.h"
#include "candela/math/constants.h"

namespace candela {

namespace {

std::atomic<RayObserver*> g_ray_observer{nullptr};

// Embree reports failures through a per-device error code; the ones it can raise here (out of
// memory, invalid arguments) are internal failures, not bad input. (Throwing from its error
// callback would unwind through C code, so the code is polled after each build step instead.)
void check_embree(RTCDevice device, const char* step) {
    RTCError code = rtcGetDeviceError(device);
    if (code != RTC_ERROR_NONE)
        throw RenderError(std::string("Embree failed to ") + step + " (error code " + std::to_string(int(code)) + ")");
}

// Float bounds of a sphere, rounded outwards so that they contain the double sphere.
void write_sphere_bounds(const Sphere& s, RTCBounds* b) {
    auto lo = [](double v) { return std::nextafter(float(v), -kInfinity); };
    auto hi = [](double v) { return std::nextafter(float(v), kInfinity); };
    b->lower_x = lo(s.center.x - s.radius);
    b->lower_y = lo(s.center.y - s.radius);
    b->lower_z = lo(s.center.z - s.radius);
    b->upper_x = hi(s.center.x + s.radius);
    b->upper_y = hi(s.center.y + s.radius);
    b->upper_z = hi(s.center.z + s.radius);
}

// Embree's user geometry calls these for the spheres; the user pointer is the Sphere.
void sphere_bounds(const RTCBoundsFunctionArguments* args) {
    write_sphere_bounds(*static_cast<const Sphere*>(args->geometryUserPtr), args->bounds_o);
}

std::optional<double> intersect_embree_ray(const Sphere& s, const RTCRay& r) {
    return intersect_sphere(s, Vec3d(Vec3f(r.org_x, r.org_y, r.org_z)), Vec3d(Vec3f(r.dir_x, r.dir_y, r.dir_z)),
                            double(r.tnear), double(r.tfar));
}

// A user geometry's hit at ray parameter t, written into Embree's record. The record is rebuilt
// from the ray afterwards (make_sphere_hit, make_disk_hit), so only t and the ids matter.
void write_user_hit(const RTCIntersectFunctionNArguments* args, RTCRayHit* rh, double t) {
    // The stored t may round up past tfar; hits must never move tfar outwards.
    float tf = std::min(float(t), rh->ray.tfar);
    rh->ray.tfar = tf;
    rh->hit.geomID = args->geomID;
    rh->hit.primID = args->primID;
    rh->hit.instID[0] = args->context->instID[0];
    rh->hit.u = 0.0f;
    rh->hit.v = 0.0f;
    rh->hit.Ng_x = rh->hit.Ng_y = rh->hit.Ng_z = 0.0f;
}

void sphere_intersect(const RTCIntersectFunctionNArguments* args) {
    // candela only traces single rays (rtcIntersect1), so N is 1.
    if (!args->valid[0]) return;
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    const auto& s = *static_cast<const Sphere*>(args->geometryUserPtr);
    std::optional<double> t = intersect_embree_ray(s, rh->ray);
    if (t) write_user_hit(args, rh, *t);
}

void sphere_occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    const auto& s = *static_cast<const Sphere*>(args->geometryUserPtr);
    if (intersect_embree_ray(s, *r)) r->tfar = -kInfinity;  // Embree's mark for "occluded"
}

// The same for disks; the user pointer is the Disk.
void write_disk_bounds(const Disk& d, RTCBounds* b) {
    // Along each axis, center + x u_i + y v_i over the unit disk reaches center_i +- |(u_i, v_i)|;
    // rounded outwards so that the float bounds contain the double disk.
    const Vec3d half(std::hypot(d.axis_u.x, d.axis_v.x), std::hypot(d.axis_u.y, d.axis_v.y),
                     std::hypot(d.axis_u.z, d.axis_v.z));
    auto lo = [](double v) { return std::nextafter(float(v), -kInfinity); };
    auto hi = [](double v) { return std::nextafter(float(v), kInfinity); };
    b->lower_x = lo(d.center.x - half.x);
    b->lower_y = lo(d.center.y - half.y);
    b->lower_z = lo(d.center.z - half.z);
    b->upper_x = hi(d.center.x + half.x);
    b->upper_y = hi(d.center.y + half.y);
    b->upper_z = hi(d.center.z + half.z);
}

void disk_bounds(const RTCBoundsFunctionArguments* args) {
    write_disk_bounds(*static_cast<const Disk*>(args->geometryUserPtr), args->bounds_o);
}

std::optional<double> intersect_embree_ray(const Disk& d, const RTCRay& r) {
    return intersect_disk(d, Vec3d(Vec3f(r.org_x, r.org_y, r.org_z)), Vec3d(Vec3f(r.dir_x, r.dir_y, r.dir_z)), double(r.tnear),
                          double(r.tfar));
}

void disk_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    std::optional<double> t = intersect_embree_ray(*static_cast<const Disk*>(args->geometryUserPtr), rh->ray);
    if (t) write_user_hit(args, rh, *t);
}

void disk_occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    if (intersect_embree_ray(*static_cast<const Disk*>(args->geometryUserPtr), *r)) r->tfar = -kInfinity;
}

// The same for the clipped quadrics (quadric.h); the user pointer is the Quadric.
void write_quadric_bounds(const Quadric& q, RTCBounds* b) {
    Vec3d lo, hi;
    quadric_world_bounds(q, lo, hi);
    auto down = [](double v) { return std::nextafter(float(v), -kInfinity); };
    auto up = [](double v) { return std::nextafter(float(v), kInfinity); };
    b->lower_x = down(lo.x);
    b->lower_y = down(lo.y);
    b->lower_z = down(lo.z);
    b->upper_x = up(hi.x);
    b->upper_y = up(hi.y);
    b->upper_z = up(hi.z);
}

void quadric_bounds(const RTCBoundsFunctionArguments* args) {
    write_quadric_bounds(*static_cast<const Quadric*>(args->geometryUserPtr), args->bounds_o);
}

std::optional<QuadricHit> intersect_embree_ray(const Quadric& q, const RTCRay& r) {
    return intersect_quadric(q, Vec3d(Vec3f(r.org_x, r.org_y, r.org_z)), Vec3d(Vec3f(r.dir_x, r.dir_y, r.dir_z)),
                             double(r.tnear), double(r.tfar));
}

void quadric_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    std::optional<QuadricHit> hit = intersect_embree_ray(*static_cast<const Quadric*>(args->geometryUserPtr), rh->ray);
    if (hit) write_user_hit(args, rh, hit->t);
}

void quadric_occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    if (intersect_embree_ray(*static_cast<const Quadric*>(args->geometryUserPtr), *r)) r->tfar = -kInfinity;
}

// The object-space point of a hit on a quadric at ray parameter t of the (world or instance
// object space) ray: the ray's point taken into the quadric's space and moved onto the surface as
// intersect_quadric moves it (reprojected, or onto the disk's plane).
Vec3d quadric_surface_point(const Quadric& q, const Vec3d& p_world) {
    Vec3d p = q.to_object.apply_point(p_world);
    switch (q.kind) {
        case QuadricKind::kSphere: return p * (q.radius / length(p));
        case QuadricKind::kCylinder: {
            const double s = q.radius / std::sqrt(p.x * p.x + p.y * p.y);
            return Vec3d(p.x * s, p.y * s, p.z);
        }
        case QuadricKind::kDisk: return Vec3d(p.x, p.y, q.height);
    }
    return p;
}

// The uv of a point at barycentrics b of triangle `tri`: Accelerator::uv's rule, which the alpha
// test must share so that a cutout and a texture on the same surface line up.
Vec2f mesh_uv(const TriangleMesh& mesh, uint32_t tri, const Vec2f& b) {
    if (mesh.uvs.empty()) return b;
    const uint32_t* v = &mesh.indices[3 * size_t(tri)];
    float b0 = 1.0f - b.x - b.y;
    return mesh.uvs[v[0]] * b0 + mesh.uvs[v[1]] * b.x + mesh.uvs[v[2]] * b.y;
}

// A shape that alpha_cutout.h cuts out: the Embree user data of its filter functions (meshes) or
// of its intersection functions (spheres, whose Embree user geometry runs no filters).
struct CutoutShape {
    const TriangleMesh* mesh = nullptr;
    const Sphere* sphere = nullptr;
    const Disk* disk = nullptr;
    FloatParam alpha;
    const TextureSet* textures = nullptr;
    uint32_t id = 0;  // the Embree geometry id = shape id, hashed with the primitive

    // Whether the ray (o, d) stops at the point p, uv of primitive `prim`.
    bool stops(const Vec3f& o, const Vec3f& d, uint32_t prim, const Vec2f& uv, const Vec3f& p) const {
        float a = alpha.is_textured() ? textures->eval(alpha, TextureContext{uv, p}) : alpha.value;
        return alpha_stops(a, alpha_hash(o, d, id, prim));
    }
};

// Embree's intersection and occlusion filter for cut-out meshes: called for each candidate hit,
// it rejects (valid = 0) those the alpha test lets through, and Embree then looks further.
void mesh_cutout_filter(const RTCFilterFunctionNArguments* args) {
    const auto& c = *static_cast<const CutoutShape*>(args->geometryUserPtr);
    const TriangleMesh& mesh = *c.mesh;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const uint32_t tri = RTCHitN_primID(args->hit, args->N, i);
        const Vec2f b(RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
        const uint32_t* v = &mesh.indices[3 * size_t(tri)];
        const Vec3f p = mesh.positions[v[0]] * (1.0f - b.x - b.y) + mesh.positions[v[1]] * b.x +
                        mesh.positions[v[2]] * b.y;
        const Vec3f o(RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i),
                      RTCRayN_org_z(args->ray, args->N, i));
        const Vec3f d(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                      RTCRayN_dir_z(args->ray, args->N, i));
        if (!c.stops(o, d, tri, mesh_uv(mesh, tri, b), p)) args->valid[i] = 0;
    }
}

// The nearest root in (tnear, tfar) of a cut-out sphere at which the ray stops: the near root,
// or the far one when the near one lets it through. The two crossings are hashed as primitives
// 0 and 1, so that they are decided independently.
std::optional<double> intersect_cutout_sphere(const CutoutShape& c, const RTCRay& r) {
    const Sphere& s = *c.sphere;
    const Vec3f o(r.org_x, r.org_y, r.org_z), d(r.dir_x, r.dir_y, r.dir_z);
    double tmin = double(r.tnear);
    for (uint32_t root = 0; root < 2; ++root) {
        std::optional<double> t = intersect_sphere(s, Vec3d(o), Vec3d(d), tmin, double(r.tfar));
        if (!t) return t;
        Vec3d p = project_to_sphere(s, Vec3d(o) + Vec3d(d) * *t);
        if (c.stops(o, d, root, sphere_uv((p - s.center) / s.radius), Vec3f(p))) return t;
        tmin = *t;
    }
    return std::nullopt;
}

void cutout_sphere_bounds(const RTCBoundsFunctionArguments* args) {
    write_sphere_bounds(*static_cast<const CutoutShape*>(args->geometryUserPtr)->sphere, args->bounds_o);
}

void cutout_sphere_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    std::optional<double> t = intersect_cutout_sphere(*static_cast<const CutoutShape*>(args->geometryUserPtr), rh->ray);
    if (t) write_user_hit(args, rh, *t);
}

void cutout_sphere_occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    if (intersect_cutout_sphere(*static_cast<const CutoutShape*>(args->geometryUserPtr), *r)) r->tfar = -kInfinity;
}

// The crossing of a cut-out disk, if the ray stops there (a disk is crossed once: primitive 0).
std::optional<double> intersect_cutout_disk(const CutoutShape& c, const RTCRay& r) {
    const Disk& d = *c.disk;
    const Vec3f o(r.org_x, r.org_y, r.org_z), dir(r.dir_x, r.dir_y, r.dir_z);
    std::optional<double> t = intersect_disk(d, Vec3d(o), Vec3d(dir), double(r.tnear), double(r.tfar));
    if (!t) return t;
    Vec3d p = project_to_disk_plane(d, Vec3d(o) + Vec3d(dir) * *t);
    if (c.stops(o, dir, 0, disk_uv(d, p), Vec3f(p))) return t;
    return std::nullopt;
}

void cutout_disk_bounds(const RTCBoundsFunctionArguments* args) {
    write_disk_bounds(*static_cast<const CutoutShape*>(args->geometryUserPtr)->disk, args->bounds_o);
}

void cutout_disk_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    std::optional<double> t = intersect_cutout_disk(*static_cast<const CutoutShape*>(args->geometryUserPtr), rh->ray);
    if (t) write_user_hit(args, rh, *t);
}

void cutout_disk_occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    if (intersect_cutout_disk(*static_cast<const CutoutShape*>(args->geometryUserPtr), *r)) r->tfar = -kInfinity;
}

// The determinant of an instance's linear part: cbrt(|det|) is the mean scale of its curves' widths.
double linear_determinant(const AffineMap& a) {
    const auto m = [&](int i, int j) { return double(a.m[i][j]); };
    return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
           m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

constexpr int kCurveTessellationRate = 16;

// The relative error allowed for between a moving instance's placement as Embree interpolates it
// and as MotionKeys::at does (Impl::make_instance_hit).
constexpr float kMovingHitError = 4e-6f;

// Embree's filter for ribbon curves: a hit on the ray-facing ribbon stands where it lies within the
// part of the width that the ribbon, turned to its normal, shows the ray (pbrt-v4's |cos| rule;
// Embree's v is the signed distance from the centre over the half width).
void ribbon_filter(const RTCFilterFunctionNArguments* args) {
    const auto& c = *static_cast<const CurveSet*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const Vec3f d(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                      RTCRayN_dir_z(args->ray, args->N, i));
        const float scale = ribbon_width_scale(c, RTCHitN_primID(args->hit, args->N, i),
                                               std::clamp(RTCHitN_u(args->hit, args->N, i), 0.0f, 1.0f), normalize(d));
        if (!(std::abs(RTCHitN_v(args->hit, args->N, i)) <= scale)) args->valid[i] = 0;
    }
}

// Moves the ray's origin back by `distance` along its direction and its range forward by as much
// (Impl::curve_clearance); returns the amount, in units of the ray's parameter, to take off the
// t of its hit.
// Out of line: scenes without curves pay one predictable branch per ray.
[[gnu::noinline]] float move_origin_back(RTCRay& r, float distance) {
    const float len = std::sqrt(r.dir_x * r.dir_x + r.dir_y * r.dir_y + r.dir_z * r.dir_z);
    if (!(len > 0.0f)) return 0.0f;
    const float s = distance / len;
    r.org_x -= r.dir_x * s;
    r.org_y -= r.dir_y * s;
    r.org_z -= r.dir_z * s;
    r.tnear += s;
    r.tfar += s;  // stays infinite
    return s;
}

RTCRay to_embree(const Ray& ray) {
    RTCRay r;
    r.org_x = ray.o.x;
    r.org_y = ray.o.y;
    r.org_z = ray.o.z;
    r.dir_x = ray.d.x;
    r.dir_y = ray.d.y;
    r.dir_z = ray.d.z;
    r.tnear = ray.tmin;
    r.tfar = ray.tmax;
    r.time = ray.time;
    r.mask = 0xFFFFFFFFu;
    r.id = 0;
    r.flags = 0;
    return r;
}

}  // namespace

struct Accelerator::Impl {
    // Per shape id (= top-level Embree geometry id), its mesh, sphere or disk (exactly one is
    // set): one load from a hit to its data. The shapes of objects have entries too, found
    // through their instances; all instances share one more entry, with none set.
    struct Geometry {
        enum class Kind : uint8_t { kMesh, kSphere, kDisk, kCurves, kInstances, kQuadric };
        const TriangleMesh* mesh = nullptr;  // set for meshes only: the hot path's one test
        const void* user = nullptr;          // the Sphere, Disk or CurveSet of the other kinds
        Kind kind = Kind::kInstances;
        const Sphere* sphere() const { return kind == Kind::kSphere ? static_cast<const Sphere*>(user) : nullptr; }
        const Disk* disk() const { return kind == Kind::kDisk ? static_cast<const Disk*>(user) : nullptr; }
        const CurveSet* curves() const { return kind == Kind::kCurves ? static_cast<const CurveSet*>(user) : nullptr; }
        const Quadric* quadric() const { return kind == Kind::kQuadric ? static_cast<const Quadric*>(user) : nullptr; }
        // A small mesh's winding normals, one per triangle (kMaxTrianglesWithNormalTable); empty
        // for larger meshes, whose hits normalize the cross product themselves.
        std::vector<Vec3f> face_normals;
    };
    std::vector<Geometry> geometries;
    // Per shape id, whether it is a shape of an object, whose hits come in object space: apart
    // from `geometries`, whose entries stay 48 bytes (an index the hot path computes with a shift).
    std::vector<bool> in_object;
    uint32_t shape_count = 0;  // the first instance's top-level id, and the instances' entry
    // Embree's curve intersectors ignore hits nearer the ray's origin than twice the curve's
    // radius (its self-intersection avoidance, EMBREE_CURVE_SELF_INTERSECTION_AVOIDANCE_FACTOR 2
    // in Debian's build): light would leak through a neighbouring hair. In a scene with curves,
    // every ray therefore starts this far behind its origin, its range moved by as much, so that
    // each curve hit is at least that far from where Embree thinks the ray starts. 0: no curves.
    float curve_clearance = 0.0f;
    std::span<const ObjectShapes> objects;
    std::span<const Instance> instances;
    // Per moving instance (Instance::motion), the keys Embree interpolates; empty when nothing moves.
    std::vector<MotionKeys> motion_keys;
    // The cut-out shapes' filter data, in a vector reserved before any is attached: Embree keeps
    // pointers to the elements.
    std::vector<CutoutShape> cutouts;
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<RTCScene> object_scenes;  // one per object, which its instances share

    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        for (RTCScene s : object_scenes) rtcReleaseScene(s);
        if (device) rtcReleaseDevice(device);
    }

    RTCScene new_scene() {
        RTCScene s = rtcNewScene(device);
        // ROBUST: no traversal shortcuts that can miss hits at shared edges.
        rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
        return s;
    }

    // Shape `id` as Embree geometry `embree_id` of `target` (the world, or its object's scene).
    void attach_shape(unsigned id, RTCScene target, unsigned embree_id, const CutoutShape* cutout) {
        const Geometry& g = geometries[id];
        if (g.mesh)
            attach_mesh(*g.mesh, target, embree_id, cutout);
        else if (g.sphere())
            attach_sphere(*g.sphere(), target, embree_id, cutout);
        else if (g.disk())
            attach_disk(*g.disk(), target, embree_id, cutout);
        else if (g.quadric())
            attach_quadric(*g.quadric(), target, embree_id);
        else
            attach_curves(*g.curves(), target, embree_id);
    }

    // Instance j: its object's scene placed by the transform, which Embree keeps in float; a moving
    // one by its keys, one time step each (instance_motion.h).
    void attach_instance(uint32_t j) {
        const Instance& instance = instances[j];
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, object_scenes[instance.object]);
        if (instance.motion == kNoMotion) {
            rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, &instance.to_world.m[0][0]);
        } else {
            const std::vector<MotionKey>& keys = motion_keys[instance.motion].keys;
            rtcSetGeometryTimeStepCount(g, unsigned(keys.size()));
            for (unsigned k = 0; k < keys.size(); ++k) {
                const MotionKey& key = keys[k];
                RTCQuaternionDecomposition qd;
                rtcInitQuaternionDecomposition(&qd);
                rtcQuaternionDecompositionSetScale(&qd, float(key.upper[0][0]), float(key.upper[1][1]),
                                                   float(key.upper[2][2]));
                rtcQuaternionDecompositionSetSkew(&qd, float(key.upper[0][1]), float(key.upper[0][2]),
                                                  float(key.upper[1][2]));
                rtcQuaternionDecompositionSetShift(&qd, float(key.shift.x), float(key.shift.y), float(key.shift.z));
                rtcQuaternionDecompositionSetQuaternion(&qd, float(key.rotation.w), float(key.rotation.v.x),
                                                        float(key.rotation.v.y), float(key.rotation.v.z));
                rtcQuaternionDecompositionSetTranslation(&qd, float(key.translation.x), float(key.translation.y),
                                                         float(key.translation.z));
                rtcSetGeometryTransformQuaternion(g, k, &qd);
            }
        }
        commit_and_attach(g, scene, shape_count + j);
    }

    // Where instance `index` is at ray time `time`: the instance itself when it stands still, else
    // its placement then, made in `scratch`.
    const Instance& placed(uint32_t index, float time, Instance& scratch) const {
        const Instance& instance = instances[index];
        if (instance.motion == kNoMotion) return instance;
        scratch = instance_at(instance, motion_keys[instance.motion], time);
        return scratch;
    }

    void attach_mesh(const TriangleMesh& mesh, RTCScene target, unsigned id, const CutoutShape* cutout) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // Embree copies into its own buffers, which it pads for its SIMD loads.
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), mesh.positions.size()));
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            v[3 * i + 0] = mesh.positions[i].x;
            v[3 * i + 1] = mesh.positions[i].y;
            v[3 * i + 2] = mesh.positions[i].z;
        }
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.triangle_count()));
        std::copy(mesh.indices.begin(), mesh.indices.end(), idx);
        if (cutout) {
            rtcSetGeometryUserData(g, const_cast<CutoutShape*>(cutout));
            rtcSetGeometryIntersectFilterFunction(g, mesh_cutout_filter);
            rtcSetGeometryOccludedFilterFunction(g, mesh_cutout_filter);
        }
        commit_and_attach(g, target, id);
    }

    // Opaque spheres keep the Sphere as user data (one load fewer per test than the cutout's).
    void attach_sphere(const Sphere& sphere, RTCScene target, unsigned id, const CutoutShape* cutout) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, 1);
        if (cutout) {
            rtcSetGeometryUserData(g, const_cast<CutoutShape*>(cutout));
            rtcSetGeometryBoundsFunction(g, cutout_sphere_bounds, nullptr);
            rtcSetGeometryIntersectFunction(g, cutout_sphere_intersect);
            rtcSetGeometryOccludedFunction(g, cutout_sphere_occluded);
        } else {
            rtcSetGeometryUserData(g, const_cast<Sphere*>(&sphere));
            rtcSetGeometryBoundsFunction(g, sphere_bounds, nullptr);
            rtcSetGeometryIntersectFunction(g, sphere_intersect);
            rtcSetGeometryOccludedFunction(g, sphere_occluded);
        }
        commit_and_attach(g, target, id);
    }

    void attach_disk(const Disk& disk, RTCScene target, unsigned id, const CutoutShape* cutout) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, 1);
        if (cutout) {
            rtcSetGeometryUserData(g, const_cast<CutoutShape*>(cutout));
            rtcSetGeometryBoundsFunction(g, cutout_disk_bounds, nullptr);
            rtcSetGeometryIntersectFunction(g, cutout_disk_intersect);
            rtcSetGeometryOccludedFunction(g, cutout_disk_occluded);
        } else {
            rtcSetGeometryUserData(g, const_cast<Disk*>(&disk));
            rtcSetGeometryBoundsFunction(g, disk_bounds, nullptr);
            rtcSetGeometryIntersectFunction(g, disk_intersect);
            rtcSetGeometryOccludedFunction(g, disk_occluded);
        }
        commit_and_attach(g, target, id);
    }

    // The loaders refuse alpha on quadrics, so they have no cut-out form.
    void attach_quadric(const Quadric& quadric, RTCScene target, unsigned id) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, 1);
        rtcSetGeometryUserData(g, const_cast<Quadric*>(&quadric));
        rtcSetGeometryBoundsFunction(g, quadric_bounds, nullptr);
        rtcSetGeometryIntersectFunction(g, quadric_intersect);
        rtcSetGeometryOccludedFunction(g, quadric_occluded);
        commit_and_attach(g, target, id);
    }

    // Curves as Embree's cubic Bezier curves, ray-facing ribbons; a `ribbon` curve is one too,
    // narrowed by ribbon_filter as pbrt-v4 narrows it. Embree copies the points into its buffers.
    void attach_curves(const CurveSet& curves, RTCScene target, unsigned id) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE);
        auto* v = static_cast<CurvePoint*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                                   sizeof(CurvePoint), curves.points.size()));
        std::copy(curves.points.begin(), curves.points.end(), v);
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT,
                                                                   sizeof(unsigned), curves.segment_count()));
        std::copy(curves.segments.begin(), curves.segments.end(), idx);
        // Embree's flat curves are chains of ray-facing quads, 4 a segment by default: a polyline
        // that shows its corners wherever a curve is wider than a pixel or two. pbrt-v4 refines
        // until the pieces are narrower than the width; 16 quads a segment keep the chord error
        // below 1/256 of the segment's bend, at no visible cost for hair (bench/RESULTS.md).
        rtcSetGeometryTessellationRate(g, float(kCurveTessellationRate));
        if (curves.type == CurveType::kRibbon) {
            rtcSetGeometryUserData(g, const_cast<CurveSet*>(&curves));
            rtcSetGeometryIntersectFilterFunction(g, ribbon_filter);
            rtcSetGeometryOccludedFilterFunction(g, ribbon_filter);
        }
        commit_and_attach(g, target, id);
    }

    void commit_and_attach(RTCGeometry g, RTCScene target, unsigned id) {
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(target, g, id);
        rtcReleaseGeometry(g);
        check_embree(device, "build a shape");
    }

    // The hit records are written in place, into the caller's optional: a returned copy of a
    // just-written struct would stall on store forwarding once per ray.
    static void make_triangle_hit(const RTCRayHit& rh, const Geometry& g, SurfaceHit& h) {
        const TriangleMesh& mesh = *g.mesh;
        uint32_t tri = rh.hit.primID;
        uint32_t i0 = mesh.indices[3 * tri], i1 = mesh.indices[3 * tri + 1], i2 = mesh.indices[3 * tri + 2];
        float b1 = rh.hit.u, b2 = rh.hit.v, b0 = 1.0f - b1 - b2;
        const Vec3f &p0 = mesh.positions[i0], &p1 = mesh.positions[i1], &p2 = mesh.positions[i2];

        h.t = rh.ray.tfar;
        h.shape_id = rh.hit.geomID;
        h.prim_id = tri;
        h.b = Vec2f(b1, b2);
        // From the barycentrics rather than o + t d: the error is then relative to the vertex
        // coordinates, not to the ray length. The point is a convex combination, so it lies in
        // the triangle's plane up to the rounding of that sum: gamma(7) (|b0 p0| + |b1 p1| +
        // |b2 p2|) bounds it (pbrt-v4, 6.8.5; barycentric error moves p within the plane only).
        h.p = p0 * b0 + p1 * b1 + p2 * b2;
        // Isotropic: Embree's intersection test mixes all coordinates, so a plane at y = 0 with
        // vertices far out in x and z still needs an offset along y of that magnitude (and a
        // zero bound would leave only a denormal step, which FTZ/DAZ flushes away).
        h.p_error = Vec3f(max_component(abs(p0 * b0) + abs(p1 * b1) + abs(p2 * b2)) * rounding_gamma(7));
        // Both normals from registers: copying h.ng into h.ns read back the two stores just made
        // with one wider load, which cannot be forwarded (a stall on every hit).
        Vec3f ng = g.face_normals.empty() ? winding_normal(p0, p1, p2) : g.face_normals[tri], ns = ng;
        if (!mesh.normals.empty()) {
            Vec3f n = mesh.normals[i0] * b0 + mesh.normals[i1] * b1 + mesh.normals[i2] * b2;
            float len = length(n);
            if (len > 0.0f) {
                ns = n / len;
                ng = face_forward(ng, ns);  // pbrt's rule: the normals agree on the front
            }
        }
        h.ng = ng;
        h.ns = ns;
    }

    static void make_sphere_hit(const RTCRayHit& rh, const Ray& ray, const Sphere& s, SurfaceHit& h) {
        h.t = rh.ray.tfar;
        h.shape_id = rh.hit.geomID;
        h.prim_id = 0;
        Vec3d p = project_to_sphere(s, Vec3d(ray.o) + Vec3d(ray.d) * double(h.t));
        Vec3d n = (p - s.center) / s.radius;
        h.p = Vec3f(p);
        // The double projection is exact to far below float precision; rounding it to float
        // dominates. gamma(5) |p| as pbrt-v4 uses for reprojected sphere points (6.8.5).
        h.p_error = Vec3f(max_component(abs(h.p)) * rounding_gamma(5));
        Vec3f ng = normalize(Vec3f(s.reverse_orientation ? -n : n));
        h.ng = ng;
        h.ns = ng;
        h.b = Vec2f(0.0f, 0.0f);
    }

    static void make_disk_hit(const RTCRayHit& rh, const Ray& ray, const Disk& d, SurfaceHit& h) {
        h.t = rh.ray.tfar;
        h.shape_id = rh.hit.geomID;
        h.prim_id = 0;
        // Moved onto the plane in double, as sphere hits are projected onto the sphere: rounding
        // to float then dominates the error, and gamma(5) |p| bounds it as for spheres.
        h.p = Vec3f(project_to_disk_plane(d, Vec3d(ray.o) + Vec3d(ray.d) * double(h.t)));
        h.p_error = Vec3f(max_component(abs(h.p)) * rounding_gamma(5));
        Vec3f ng = Vec3f(d.normal);
        h.ng = ng;
        h.ns = ng;
        h.b = Vec2f(0.0f, 0.0f);
    }

    // A hit on a clipped quadric: the point moved onto the surface in its object space, in
    // double, then to the world; rounding to float dominates the error, as for spheres.
    static void make_quadric_hit(const RTCRayHit& rh, const Ray& ray, const Quadric& q, SurfaceHit& h) {
        h.t = rh.ray.tfar;
        h.shape_id = rh.hit.geomID;
        h.prim_id = 0;
        const Vec3d p = quadric_surface_point(q, Vec3d(ray.o) + Vec3d(ray.d) * double(h.t));
        h.p = Vec3f(q.to_world.apply_point(p));
        h.p_error = Vec3f(max_component(abs(h.p)) * rounding_gamma(5));
        const Vec3f ng(quadric_normal(q, p));
        h.ng = ng;
        h.ns = ng;
        h.b = Vec2f(0.0f, 0.0f);
    }

    // A hit on a curve (curve_hit.h): pbrt-v4's point, normal and (u, v).
    static void make_curve_hit(const RTCRayHit& rh, const Ray& ray, const CurveSet& c, SurfaceHit& h) {
        h.t = rh.ray.tfar;
        h.shape_id = rh.hit.geomID;
        h.prim_id = rh.hit.primID;
        const CurveHit ch = curve_hit(c, rh.hit.primID, rh.hit.u, ray.o + ray.d * h.t, ray.d);
        h.p = ch.p;
        h.p_error = ch.p_error;
        h.ng = ch.n;
        h.ns = ch.n;
        h.b = ch.uv;
    }

    // A hit on any other kind than a mesh, or through an instance, off the triangles' path.
    void make_user_hit(const RTCRayHit& rh, const Ray& ray, const Geometry& g, SurfaceHit& h) const {
        switch (g.kind) {
            case Geometry::Kind::kSphere: make_sphere_hit(rh, ray, *g.sphere(), h); break;
            case Geometry::Kind::kDisk: make_disk_hit(rh, ray, *g.disk(), h); break;
            case Geometry::Kind::kCurves: make_curve_hit(rh, ray, *g.curves(), h); break;
            case Geometry::Kind::kQuadric: make_quadric_hit(rh, ray, *g.quadric(), h); break;
            default: make_instance_hit(rh, ray, h);
        }
    }

    // A hit through an instance: made in object space as the shape's own hits are, then moved to
    // the world (instance.h). Embree leaves the direction unnormalized in object space, so the ray
    // parameter t is the same in both.
    [[gnu::noinline]] void make_instance_hit(const RTCRayHit& rh, const Ray& ray, SurfaceHit& h) const {
        const uint32_t index = rh.hit.instID[0] - shape_count;
        Instance scratch;
        const Instance& instance = placed(index, ray.time, scratch);
        const uint32_t id = objects[instance.object].first_shape + rh.hit.geomID;
        const Geometry& shape = geometries[id];
        if (shape.mesh) {
            make_triangle_hit(rh, shape, h);
        } else {
            const AffineMap& m = instance.to_object;
            const Ray local{Vec3f(m.apply_point(Vec3d(ray.o))), Vec3f(m.apply_vector(Vec3d(ray.d))), ray.tmin,
                            ray.tmax};
            if (shape.sphere())
                make_sphere_hit(rh, local, *shape.sphere(), h);
            else if (shape.disk())
                make_disk_hit(rh, local, *shape.disk(), h);
            else if (shape.quadric())
                make_quadric_hit(rh, local, *shape.quadric(), h);
            else
                make_curve_hit(rh, local, *shape.curves(), h);
        }
        h.shape_id = id;
        h.instance = index;
        hit_to_world(instance, h);
        // Embree places a moving instance by its own float interpolation of the keys, which
        // differs from MotionKeys::at by a few float roundings of the point's magnitude (its
        // approximate acos and sincos among them): the offset of rays leaving the hit covers
        // that too. (Measured on tests/geometry/instance_motion_test.cpp's 20,000 rays: Embree's
        // hit point o + t d is at most 5.9e-7 |p| from the keys' point; the bound is about 7 times
        // that. No ray there hit its surface again without it either.)
        if (instance.motion != kNoMotion) [[unlikely]]
            h.p_error = h.p_error + Vec3f(max_component(abs(h.p)) * kMovingHitError);
    }

    // A hit's point in its shape's space: the object's, for a shape reached through an instance.
    Vec3d shape_point(const SurfaceHit& hit) const {
        if (!in_object[hit.shape_id]) return Vec3d(hit.p);
        Instance scratch;
        return placed(hit.instance, hit.time, scratch).to_object.apply_point(Vec3d(hit.p));
    }
};

Accelerator::Accelerator(std::span<const TriangleMesh> meshes, std::span<const Sphere> spheres,
                         std::span<const Disk> disks, std::span<const Shape> shapes, AlphaCutouts cutouts,
                         Instancing instancing, std::span<const CurveSet> curves,
                         std::span<const Quadric> quadrics)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.geometries.resize(shapes.size() + (instancing.instances.empty() ? 0 : 1));
    m.shape_count = static_cast<uint32_t>(shapes.size());
    m.in_object.assign(shapes.size(), false);
    m.objects = instancing.objects;
    m.instances = instancing.instances;
    for (const InstanceMotion& motion : instancing.motions)
        m.motion_keys.push_back(make_motion_keys(motion, instancing.shutter));
    for (const ObjectShapes& object : instancing.objects) {
        CANDELA_CHECK(size_t(object.first_shape) + object.shape_count <= shapes.size());
        for (uint32_t k = 0; k < object.shape_count; ++k) m.in_object[object.first_shape + k] = true;
    }
    for (size_t id = 0; id < shapes.size(); ++id) {
        const uint32_t index = shapes[id].index;
        // A disk shape given to the constructor without disks would read past the span.
        CANDELA_CHECK(index < (shapes[id].kind == ShapeKind::kMesh     ? meshes.size()
                               : shapes[id].kind == ShapeKind::kSphere ? spheres.size()
                               : shapes[id].kind == ShapeKind::kDisk   ? disks.size()
                               : shapes[id].kind == ShapeKind::kQuadric ? quadrics.size()
                                                                       : curves.size()));
        switch (shapes[id].kind) {
            case ShapeKind::kMesh: {
                const TriangleMesh& mesh = meshes[index];
                m.geometries[id].mesh = &mesh;
                if (mesh.triangle_count() <= kMaxTrianglesWithNormalTable)
                    m.geometries[id].face_normals = winding_normals(mesh);
                break;
            }
            case ShapeKind::kSphere:
                m.geometries[id].user = &spheres[index];
                m.geometries[id].kind = Impl::Geometry::Kind::kSphere;
                break;
            case ShapeKind::kDisk:
                m.geometries[id].user = &disks[index];
                m.geometries[id].kind = Impl::Geometry::Kind::kDisk;
                break;
            case ShapeKind::kQuadric:
                m.geometries[id].user = &quadrics[index];
                m.geometries[id].kind = Impl::Geometry::Kind::kQuadric;
                break;
            case ShapeKind::kCurves: {
                m.geometries[id].user = &curves[index];
                m.geometries[id].kind = Impl::Geometry::Kind::kCurves;
                // Instances may scale the curves up: by at most the largest instance scale.
                float r = 0.0f;
                for (const CurvePoint& c : curves[index].points) r = std::max(r, c.r);
                float scale = 1.0f;
                // (A moving instance: at its first key; its scale may change, which the clearance
                // does not follow.)
                if (m.in_object[id])
                    for (const Instance& instance : instancing.instances)
                        for (int i = 0; i < 3; ++i)
                            for (int j = 0; j < 3; ++j) scale = std::max(scale, std::abs(instance.to_world.m[i][j]) * 1.7321f);
                m.curve_clearance = std::max(m.curve_clearance, 2.02f * r * scale);
                break;
            }
        }
    }
    m.device = rtcNewDevice(nullptr);
    if (!m.device) throw RenderError("cannot create the Embree device");
    m.scene = m.new_scene();
    m.cutouts.reserve(shapes.size());
    auto cutout_of = [&](unsigned id) -> const CutoutShape* {
        if (!cutouts.cuts(id)) return nullptr;
        const Impl::Geometry& g = m.geometries[id];
        const FloatParam& alpha = cutouts.shape_alpha[id];
        CANDELA_CHECK(!alpha.is_textured() || cutouts.textures);
        // The loaders refuse alpha on curves (Embree's curves would need a filter of their own).
        CANDELA_CHECK(g.kind != Impl::Geometry::Kind::kCurves && g.kind != Impl::Geometry::Kind::kQuadric);
        return &m.cutouts.emplace_back(CutoutShape{g.mesh, g.sphere(), g.disk(), alpha, cutouts.textures, id});
    };
    // Each object once, its shapes numbered from 0 in its own scene (compact ids: Embree sizes a
    // scene's geometry table by the largest); an object no instance places is left empty.
    std::vector<bool> placed(instancing.objects.size(), false);
    for (const Instance& instance : instancing.instances) {
        CANDELA_CHECK(instance.object < instancing.objects.size());
        placed[instance.object] = true;
    }
    for (size_t k = 0; k < instancing.objects.size(); ++k) {
        const ObjectShapes& object = instancing.objects[k];
        RTCScene s = m.object_scenes.emplace_back(m.new_scene());
        if (!placed[k]) continue;
        for (uint32_t i = 0; i < object.shape_count; ++i)
            m.attach_shape(object.first_shape + i, s, i, cutout_of(object.first_shape + i));
        rtcCommitScene(s);
        check_embree(m.device, "build an object");
    }
    for (unsigned id = 0; id < shapes.size(); ++id)
        if (!m.in_object[id]) m.attach_shape(id, m.scene, id, cutout_of(id));
    for (uint32_t j = 0; j < instancing.instances.size(); ++j) {
        // An empty object has nothing to hit (and an empty Embree scene no bounds to place).
        if (instancing.objects[instancing.instances[j].object].shape_count > 0) m.attach_instance(j);
    }
    rtcCommitScene(m.scene);
    check_embree(m.device, "build the scene");
}

Accelerator::~Accelerator() = default;

std::optional<SurfaceHit> Accelerator::intersect(const Ray& ray) const {
    std::optional<SurfaceHit> result;  // the one object returned, built in place
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray = to_embree(ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    const bool moved = impl_->curve_clearance > 0.0f;
    float back = 0.0f;
    if (moved) [[unlikely]]
        back = move_origin_back(rh.ray, impl_->curve_clearance);
    rtcIntersect1(impl_->scene, &context, &rh);
    if (moved) [[unlikely]]
        rh.ray.tfar -= back;
    if (RayObserver* o = g_ray_observer.load(std::memory_order_relaxed)) [[unlikely]]
        o->observe(ray, false, rh.hit.geomID != RTC_INVALID_GEOMETRY_ID);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return result;
    // A hit through an instance is found by the instance's id (a select, not a branch), which
    // leads to make_user_hit: one test on the triangles' path, as before disks and instances.
    const Impl::Geometry& g =
        impl_->geometries[rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? impl_->shape_count : rh.hit.geomID];
    if (g.mesh == nullptr)
        impl_->make_user_hit(rh, ray, g, result.emplace());
    else
        Impl::make_triangle_hit(rh, g, result.emplace());
    result->time = ray.time;
    return result;
}

Vec2f Accelerator::uv(const SurfaceHit& hit) const {
    const Impl::Geometry& g = impl_->geometries[hit.shape_id];
    if (const Sphere* s = g.sphere()) return sphere_uv((impl_->shape_point(hit) - s->center) / s->radius);
    if (const Disk* d = g.disk()) return disk_uv(*d, impl_->shape_point(hit));
    if (g.curves()) return hit.b;
    if (const Quadric* q = g.quadric()) {
        // The hit's point back in the quadric's space (hit.p is on its surface, to float precision).
        const Vec3d p = quadric_surface_point(*q, impl_->shape_point(hit));
        return quadric_uv(*q, p, quadric_phi(p));
    }
    return mesh_uv(*g.mesh, hit.prim_id, hit.b);
}

ShadingGeometry Accelerator::shading(const SurfaceHit& hit) const {
    const Impl::Geometry& g = impl_->geometries[hit.shape_id];
    Instance scratch;
    const Instance* instance =
        impl_->in_object[hit.shape_id] ? &impl_->placed(hit.instance, hit.time, scratch) : nullptr;
    if (const Sphere* sphere = g.sphere()) {
        const Vec3d v = impl_->shape_point(hit) - sphere->center;
        const Vec3d n = v / length(v);
        const ShadingGeometry s = sphere_shading_geometry(n, sphere->radius, sphere->reverse_orientation);
        return instance ? shading_to_world(*instance, s, Vec3f(sphere->reverse_orientation ? -n : n)) : s;
    }
    if (const Disk* disk = g.disk()) {
        const ShadingGeometry s = disk_shading_geometry(*disk, impl_->shape_point(hit));
        return instance ? shading_to_world(*instance, s, Vec3f(disk->normal)) : s;
    }
    if (const Quadric* q = g.quadric()) {
        const Vec3d p = quadric_surface_point(*q, impl_->shape_point(hit));
        const Vec3f n(quadric_normal(*q, p));
        const ShadingGeometry s = quadric_shading_geometry(*q, p, n);
        return instance ? shading_to_world(*instance, s, n) : s;
    }
    if (const CurveSet* curves = g.curves()) {
        // dpdu from the segment (moved to the world with its instance), dpdv across it, so that
        // cross(dpdu, dpdv) is the hit's normal, as pbrt-v4's curves.
        const CurvePoint* cp = &curves->points[curves->segments[hit.prim_id]];
        Vec3f dpdu = bezier_derivative(cp, hit.b.x);
        float width = 2 * bezier_radius(cp, hit.b.x);
        if (instance) {
            dpdu = Vec3f(instance->to_world.apply_vector(Vec3d(dpdu)));
            width *= float(std::cbrt(std::fabs(linear_determinant(instance->to_world))));
        }
        return curve_shading_geometry(dpdu, hit.ng, width, hit.b);
    }
    const TriangleMesh& mesh = *g.mesh;
    const uint32_t* v = &mesh.indices[3 * size_t(hit.prim_id)];
    Vec3f p[3] = {mesh.positions[v[0]], mesh.positions[v[1]], mesh.positions[v[2]]};
    Vec2f uvs[3];
    Vec3f normals[3];
    for (int k = 0; k < 3; ++k) {
        if (!mesh.uvs.empty()) uvs[k] = mesh.uvs[v[k]];
        if (!mesh.normals.empty()) normals[k] = mesh.normals[v[k]];
    }
    // An instanced triangle in the world, as transform_mesh would have placed it.
    if (instance) {
        for (int k = 0; k < 3; ++k) {
            p[k] = Vec3f(instance->to_world.apply_point(Vec3d(p[k])));
            if (!mesh.normals.empty())
                normals[k] = normalize(Vec3f(instance->to_object.apply_transposed(Vec3d(normals[k]))));
        }
    }
    return triangle_shading_geometry(p, mesh.uvs.empty() ? nullptr : uvs, mesh.normals.empty() ? nullptr : normals,
                                     hit.b, hit.ng);
}

bool Accelerator::occluded(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r = to_embree(ray);
    if (impl_->curve_clearance > 0.0f) [[unlikely]]
        move_origin_back(r, impl_->curve_clearance);
    rtcOccluded1(impl_->scene, &context, &r);
    if (RayObserver* o = g_ray_observer.load(std::memory_order_relaxed)) [[unlikely]]
        o->observe(ray, true, r.tfar == -kInfinity);
    return r.tfar == -kInfinity;
}

Bounds3f Accelerator::bounds() const {
    RTCBounds b;
    rtcGetSceneBounds(impl_->scene, &b);
    Bounds3f out;
    if (b.lower_x <= b.upper_x) {
        out.lo = {b.lower_x, b.lower_y, b.lower_z};
        out.hi = {b.upper_x, b.upper_y, b.upper_z};
    }
    return out;
}

RTCSceneTy* Accelerator::embree_scene() const { return impl_->scene; }

void set_ray_observer(RayObserver* observer) { g_ray_observer.store(observer); }

void enable_flush_denormals() {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
}

}  // namespace candela
