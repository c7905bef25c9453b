// The front-face rules of DESIGN.md's scene format, checked on transform_mesh and make_quad:
// winding follows the right-hand rule, mirrors keep the front where it was, vertex normals follow
// the inverse transpose and agree with the winding, reverse_orientation flips both.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/geometry/triangle_mesh.h"
#include "candela/math/constants.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr float kTol = 1e-5f;

::testing::AssertionResult vec_eq(const Vec3f& a, const Vec3f& b, float tol = kTol) {
    if (std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ") != (" << b.x
                                         << ", " << b.y << ", " << b.z << ") within " << tol;
}

Vec3f vertex(const TriangleMesh& m, size_t tri, int corner) { return m.positions[m.indices[3 * tri + corner]]; }

// The front side of triangle `tri` as its winding defines it (right-hand rule).
Vec3f geometric_normal(const TriangleMesh& m, size_t tri) {
    Vec3f p0 = vertex(m, tri, 0), p1 = vertex(m, tri, 1), p2 = vertex(m, tri, 2);
    return normalize(cross(p1 - p0, p2 - p0));
}

// One triangle with counter-clockwise winding seen from `front`, optionally with vertex normals.
TriangleMesh triangle(const Vec3f& p0, const Vec3f& p1, const Vec3f& p2, bool with_normals) {
    TriangleMesh m;
    m.positions = {p0, p1, p2};
    m.indices = {0, 1, 2};
    if (with_normals) {
        Vec3f n = normalize(cross(p1 - p0, p2 - p0));
        m.normals = {n, n, n};
    }
    return m;
}

// A triangle at x = 1 whose front faces +x: cross((0,1,0), (0,0,1)) = (1,0,0).
TriangleMesh facing_plus_x(bool with_normals) {
    return triangle({1.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 1.0f}, with_normals);
}

// A triangle at z = 0 whose front faces +z: cross((1,0,0), (0,1,0)) = (0,0,1).
TriangleMesh facing_plus_z(bool with_normals) {
    return triangle({0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, with_normals);
}

// A flat fan of four triangles in the plane through (1,2,3) with normal (1,2,3)/|.|, wound
// counter-clockwise about that normal, with the plane normal at every vertex.
TriangleMesh tilted_flat_fan() {
    Vec3f n = normalize(Vec3f(1.0f, 2.0f, 3.0f));
    Vec3f u = normalize(cross(n, Vec3f(0.0f, 0.0f, 1.0f)));
    Vec3f v = cross(n, u);  // (u, v, n) right-handed, so u -> v turns counter-clockwise about n
    Vec3f c(1.0f, 2.0f, 3.0f);
    TriangleMesh m;
    m.positions = {c, c + u, c + v * 1.5f, c - u * 0.5f, c - v};
    m.indices = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1};
    m.normals.assign(m.positions.size(), n);
    return m;
}

TEST(TransformMesh, IdentityKeepsPositionsAndFront) {
    TriangleMesh m = facing_plus_z(true);
    TriangleMesh before = m;
    transform_mesh(m, Transform(), false);
    EXPECT_EQ(m.positions, before.positions);
    EXPECT_EQ(m.indices, before.indices);
    EXPECT_TRUE(vec_eq(geometric_normal(m, 0), {0.0f, 0.0f, 1.0f}));
    for (const Vec3f& n : m.normals) EXPECT_TRUE(vec_eq(n, {0.0f, 0.0f, 1.0f}));
}

TEST(TransformMesh, RotationRotatesTheFront) {
    // A quarter turn about +y takes +z to +x and the point (1,0,0) to (0,0,-1).
    TriangleMesh m = facing_plus_z(true);
    transform_mesh(m, Transform::rotate({0.0, 1.0, 0.0}, kPiD / 2.0), false);
    EXPECT_TRUE(vec_eq(m.positions[1], {0.0f, 0.0f, -1.0f}));
    EXPECT_TRUE(vec_eq(geometric_normal(m, 0), {1.0f, 0.0f, 0.0f}));
    for (const Vec3f& n : m.normals) EXPECT_TRUE(vec_eq(n, {1.0f, 0.0f, 0.0f}));
}

TEST(TransformMesh, TranslationAndScaleMovePositions) {
    TriangleMesh m = facing_plus_z(false);
    transform_mesh(m, Transform::translate({0.0, 0.0, 5.0}) * Transform::scale({2.0, 3.0, 4.0}), false);
    EXPECT_TRUE(vec_eq(m.positions[0], {0.0f, 0.0f, 5.0f}));
    EXPECT_TRUE(vec_eq(m.positions[1], {2.0f, 0.0f, 5.0f}));
    EXPECT_TRUE(vec_eq(m.positions[2], {0.0f, 3.0f, 5.0f}));
    EXPECT_TRUE(vec_eq(geometric_normal(m, 0), {0.0f, 0.0f, 1.0f}));
}

TEST(TransformMesh, MirrorKeepsTheFrontWhereItWas) {
    Transform mirror_x = Transform::scale({-1.0, 1.0, 1.0});
    // Facing +x at x = 1; its mirror image sits at x = -1 facing -x (both face away from x = 0).
    TriangleMesh a = facing_plus_x(false);
    transform_mesh(a, mirror_x, false);
    EXPECT_TRUE(vec_eq(a.positions[0], {-1.0f, 0.0f, 0.0f}));
    EXPECT_TRUE(vec_eq(geometric_normal(a, 0), {-1.0f, 0.0f, 0.0f}));
    // Facing +z: the mirror through x = 0 leaves z alone, so it still faces +z.
    TriangleMesh b = facing_plus_z(false);
    transform_mesh(b, mirror_x, false);
    EXPECT_TRUE(vec_eq(geometric_normal(b, 0), {0.0f, 0.0f, 1.0f}));
}

TEST(TransformMesh, MirrorOfAnyTriangleGivesTheMirroredNormal) {
    // For a mirror through x = 0 the normal after is the normal before with x negated.
    const Vec3f ps[][3] = {{{0.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 0.5f}, {-1.0f, 0.5f, 2.0f}},
                           {{3.0f, -1.0f, 2.0f}, {0.5f, 0.5f, 0.5f}, {1.0f, -2.0f, -3.0f}},
                           {{-2.0f, 1.0f, 1.0f}, {-2.5f, 0.0f, 3.0f}, {1.0f, 1.0f, -1.0f}}};
    for (const auto& p : ps) {
        TriangleMesh m = triangle(p[0], p[1], p[2], false);
        Vec3f before = geometric_normal(m, 0);
        transform_mesh(m, Transform::scale({-1.0, 1.0, 1.0}), false);
        EXPECT_TRUE(vec_eq(geometric_normal(m, 0), {-before.x, before.y, before.z}));
    }
}

TEST(TransformMesh, ClosedMeshFacesOutwardUnderAnyTransform) {
    // A tetrahedron wound so every face points away from its centroid; any invertible transform,
    // mirrors included, must keep every front facing out.
    TriangleMesh tet;
    tet.positions = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
    tet.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    const Transform transforms[] = {
        Transform(),
        Transform::scale({-1.0, 1.0, 1.0}),
        Transform::scale({-1.0, -1.0, 1.0}),
        Transform::scale({-2.0, -0.5, -3.0}),
        Transform::translate({4.0, -1.0, 2.0}) * Transform::rotate({1.0, 1.0, 0.0}, 2.0) *
            Transform::scale({3.0, -0.25, 1.0}),
        Transform({{{0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}),
    };
    for (const Transform& t : transforms) {
        TriangleMesh m = tet;
        transform_mesh(m, t, false);
        Vec3f centroid = (m.positions[0] + m.positions[1] + m.positions[2] + m.positions[3]) * 0.25f;
        for (size_t i = 0; i < m.triangle_count(); ++i) {
            Vec3f to_face = vertex(m, i, 0) - centroid;
            EXPECT_GT(dot(geometric_normal(m, i), to_face), 0.0f) << "triangle " << i;
        }
    }
}

TEST(TransformMesh, MirrorWithVertexNormalsAgreesWithGeometricNormal) {
    TriangleMesh m = facing_plus_x(true);
    transform_mesh(m, Transform::scale({-1.0, 1.0, 1.0}), false);
    EXPECT_TRUE(vec_eq(geometric_normal(m, 0), {-1.0f, 0.0f, 0.0f}));
    for (const Vec3f& n : m.normals) EXPECT_TRUE(vec_eq(n, {-1.0f, 0.0f, 0.0f}));
    // A tilted triangle under a non-uniform mirror: the inverse-transpose normal is exactly the
    // flipped geometric normal.
    TriangleMesh t = triangle({0.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 0.5f}, {-1.0f, 0.5f, 2.0f}, true);
    transform_mesh(t, Transform::rotate({0.0, 0.0, 1.0}, 0.5) * Transform::scale({-2.0, 1.0, 3.0}), false);
    for (const Vec3f& n : t.normals) EXPECT_TRUE(vec_eq(n, geometric_normal(t, 0)));
}

TEST(TransformMesh, ReverseOrientationFlipsGeometricAndVertexNormals) {
    TriangleMesh m = facing_plus_z(true);
    transform_mesh(m, Transform(), true);
    EXPECT_TRUE(vec_eq(geometric_normal(m, 0), {0.0f, 0.0f, -1.0f}));
    for (const Vec3f& n : m.normals) EXPECT_TRUE(vec_eq(n, {0.0f, 0.0f, -1.0f}));
    // The positions themselves do not move.
    EXPECT_EQ(m.positions, facing_plus_z(true).positions);
}

TEST(TransformMesh, MirrorAndReverseIsTheReverseOfMirrorAlone) {
    Transform mirror = Transform::translate({1.0, 2.0, 3.0}) * Transform::scale({1.0, -2.0, 0.5});
    TriangleMesh mirrored = tilted_flat_fan(), both = tilted_flat_fan();
    transform_mesh(mirrored, mirror, false);
    transform_mesh(both, mirror, true);
    ASSERT_EQ(both.positions, mirrored.positions);
    for (size_t i = 0; i < both.triangle_count(); ++i)
        EXPECT_TRUE(vec_eq(geometric_normal(both, i), -geometric_normal(mirrored, i))) << "triangle " << i;
    for (size_t v = 0; v < both.normals.size(); ++v) EXPECT_TRUE(vec_eq(both.normals[v], -mirrored.normals[v]));
    // And the mirrored-only mesh is consistent: its vertex normals agree with its winding.
    for (size_t v = 0; v < mirrored.normals.size(); ++v)
        EXPECT_TRUE(vec_eq(mirrored.normals[v], geometric_normal(mirrored, 0)));
}

TEST(TransformMesh, NonUniformScaleKeepsVertexNormalsUnitAndPerpendicular) {
    const Transform transforms[] = {
        Transform::scale({3.0, 0.5, 7.0}),
        Transform::rotate({1.0, 0.0, 1.0}, 0.6) * Transform::scale({0.2, 5.0, 1.0}),
        Transform::scale({-4.0, 1.0, 0.3}),
    };
    for (const Transform& t : transforms) {
        TriangleMesh m = tilted_flat_fan();
        transform_mesh(m, t, false);
        for (const Vec3f& n : m.normals) {
            EXPECT_NEAR(double(length(n)), 1.0, 1e-6);
            for (size_t i = 0; i < m.triangle_count(); ++i) {
                Vec3f p0 = vertex(m, i, 0), p1 = vertex(m, i, 1), p2 = vertex(m, i, 2);
                EXPECT_NEAR(double(dot(n, normalize(p1 - p0))), 0.0, 1e-5);
                EXPECT_NEAR(double(dot(n, normalize(p2 - p1))), 0.0, 1e-5);
                EXPECT_NEAR(double(dot(n, normalize(p0 - p2))), 0.0, 1e-5);
                EXPECT_NEAR(double(dot(n, geometric_normal(m, i))), 1.0, 1e-5);  // same side
            }
        }
    }
}

TEST(MakeQuad, NormalIsCrossOfEdgesAndUvsFollowCorners) {
    // cross((2,0,0), (0,0,-3)) = (0,6,0): the quad faces +y with area 6.
    const Vec3f corner(1.0f, 2.0f, 3.0f), e1(2.0f, 0.0f, 0.0f), e2(0.0f, 0.0f, -3.0f);
    TriangleMesh q = make_quad(corner, e1, e2);
    ASSERT_EQ(q.triangle_count(), 2u);
    ASSERT_EQ(q.uvs.size(), q.positions.size());
    EXPECT_TRUE(q.normals.empty());
    for (size_t i = 0; i < 2; ++i) EXPECT_TRUE(vec_eq(geometric_normal(q, i), {0.0f, 1.0f, 0.0f}));
    // Each corner carries uv = (s, t) of corner + s e1 + t e2.
    struct Corner { Vec3f p; Vec2f uv; };
    const Corner expected[] = {{{1.0f, 2.0f, 3.0f}, {0.0f, 0.0f}}, {{3.0f, 2.0f, 3.0f}, {1.0f, 0.0f}},
                               {{3.0f, 2.0f, 0.0f}, {1.0f, 1.0f}}, {{1.0f, 2.0f, 0.0f}, {0.0f, 1.0f}}};
    for (const Corner& c : expected) {
        int found = 0;
        for (size_t v = 0; v < q.positions.size(); ++v)
            if (q.positions[v] == c.p) {
                ++found;
                EXPECT_EQ(q.uvs[v], c.uv);
            }
        EXPECT_EQ(found, 1) << "corner (" << c.p.x << ", " << c.p.y << ", " << c.p.z << ")";
    }
}

TEST(MakeQuad, TrianglesCoverTheParallelogram) {
    // A skewed quad: |cross((1,0,0), (1,1,1))| = |(0,-1,1)| = sqrt(2).
    const Vec3f corner(0.5f, -1.0f, 2.0f), e1(1.0f, 0.0f, 0.0f), e2(1.0f, 1.0f, 1.0f);
    TriangleMesh q = make_quad(corner, e1, e2);
    float area = 0.0f;
    for (size_t i = 0; i < q.triangle_count(); ++i) {
        Vec3f p0 = vertex(q, i, 0), p1 = vertex(q, i, 1), p2 = vertex(q, i, 2);
        area += 0.5f * length(cross(p1 - p0, p2 - p0));
        EXPECT_TRUE(vec_eq(geometric_normal(q, i), normalize(Vec3f(0.0f, -1.0f, 1.0f))));
    }
    EXPECT_NEAR(double(area), std::sqrt(2.0), 1e-6);
    // uv interpolates as (s, t): the point corner + s e1 + t e2 gets uv (s, t) from barycentrics
    // in whichever triangle holds it.
    for (Vec2f st : {Vec2f(0.25f, 0.5f), Vec2f(0.75f, 0.1f), Vec2f(0.1f, 0.9f), Vec2f(0.6f, 0.55f)}) {
        Vec3f p = corner + e1 * st.x + e2 * st.y;
        int inside = 0;
        for (size_t i = 0; i < q.triangle_count(); ++i) {
            Vec3f p0 = vertex(q, i, 0), p1 = vertex(q, i, 1), p2 = vertex(q, i, 2);
            Vec3f n = cross(p1 - p0, p2 - p0);
            float b1 = dot(cross(p - p0, p2 - p0), n) / dot(n, n);
            float b2 = dot(cross(p1 - p0, p - p0), n) / dot(n, n);
            float b0 = 1.0f - b1 - b2;
            if (b0 < 0.0f || b1 < 0.0f || b2 < 0.0f) continue;
            ++inside;
            Vec2f uv = q.uvs[q.indices[3 * i]] * b0 + q.uvs[q.indices[3 * i + 1]] * b1 +
                       q.uvs[q.indices[3 * i + 2]] * b2;
            EXPECT_NEAR(double(uv.x), double(st.x), 1e-5);
            EXPECT_NEAR(double(uv.y), double(st.y), 1e-5);
        }
        EXPECT_EQ(inside, 1) << "(s, t) = (" << st.x << ", " << st.y << ")";
    }
}

TEST(MakeQuad, ReversedQuadFacesMinusCrossOfEdges) {
    const Vec3f e1(0.0f, 0.0f, 105.0f), e2(-130.0f, 0.0f, 0.0f);  // the Cornell box light
    TriangleMesh q = make_quad({343.0f, 548.7f, 227.0f}, e1, e2);
    Vec3f front = normalize(cross(e1, e2));
    EXPECT_TRUE(vec_eq(front, {0.0f, -1.0f, 0.0f}));  // (0*0 - 105*0, 105*-130 - 0, 0)
    transform_mesh(q, Transform(), true);
    for (size_t i = 0; i < q.triangle_count(); ++i) EXPECT_TRUE(vec_eq(geometric_normal(q, i), -front));
}

}  // namespace
}  // namespace candela
