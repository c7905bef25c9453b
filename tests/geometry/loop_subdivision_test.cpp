#include "candela/geometry/loop_subdivision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <utility>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

struct Polyhedron {
    std::vector<Vec3f> positions;
    std::vector<int> indices;  // counter-clockwise seen from outside
};

Polyhedron tetrahedron() {
    return {{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2}};
}

Polyhedron octahedron() {
    return {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
            {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5}};
}

// The regular icosahedron with circumradius 1.
Polyhedron icosahedron() {
    const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<Vec3f> p = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                            {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (Vec3f& v : p) v = normalize(v);
    return {p, {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1}};
}

// An n x n grid of unit squares in z = 0, each cut into two triangles wound counter-clockwise
// seen from +z.
Polyhedron grid(int n) {
    Polyhedron g;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) g.positions.push_back({static_cast<float>(x), static_cast<float>(y), 0});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int v = y * (n + 1) + x;
            g.indices.insert(g.indices.end(), {v, v + 1, v + n + 2, v, v + n + 2, v + n + 1});
        }
    return g;
}

TriangleMesh subdivide(const Polyhedron& p, int levels) { return loop_subdivide(p.positions, p.indices, levels); }

Vec3f winding(const TriangleMesh& m, size_t t) {
    const Vec3f a = m.positions[m.indices[3 * t]];
    return cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a);
}

std::string error_of(const Polyhedron& p, int levels) {
    try {
        subdivide(p, levels);
    } catch (const SceneError& e) {
        EXPECT_TRUE(e.where().file.empty());
        return e.message();
    }
    ADD_FAILURE() << "expected a SceneError";
    return "";
}

TEST(LoopSubdivision, MakesFourTrianglesOfEachPerLevel) {
    // A closed triangle mesh has V = 2 + F/2 (Euler), F = 4^levels F0.
    for (int levels = 0; levels <= 3; ++levels) {
        SCOPED_TRACE(levels);
        const TriangleMesh tet = subdivide(tetrahedron(), levels), oct = subdivide(octahedron(), levels);
        EXPECT_EQ(tet.triangle_count(), 4u << (2 * levels));
        EXPECT_EQ(tet.positions.size(), 2 + tet.triangle_count() / 2);
        EXPECT_EQ(oct.triangle_count(), 8u << (2 * levels));
        EXPECT_EQ(oct.positions.size(), 2 + oct.triangle_count() / 2);
        EXPECT_EQ(oct.normals.size(), oct.positions.size());
        EXPECT_TRUE(oct.uvs.empty());
    }
}

TEST(LoopSubdivision, PushesAnIcosahedronToPbrtsLimitRadius) {
    // Every vertex has valence 5: Warren's beta = 3/40, so gamma = 1/(5 + 3/(8 beta)) = 1/10 and
    // the limit is v/2 + (sum of the 5 neighbours)/10 = (1/2 + sqrt(5)/10) v, the neighbours lying
    // at cos = 1/sqrt(5) from v. (Loop's own beta would give another radius.)
    const TriangleMesh m = subdivide(icosahedron(), 0);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(length(m.positions[i]), 0.5f + std::sqrt(5.0f) / 10.0f, 1e-6f) << "vertex " << i;
        // By symmetry the normal is radial; pbrt-v4's points inward (see the header).
        EXPECT_NEAR(dot(m.normals[i], normalize(m.positions[i])), -1.0f, 1e-6f) << "vertex " << i;
    }
}

// The largest angle (as 1 - cos) between the normals of two vertices joined by an edge.
float largest_normal_turn(const TriangleMesh& m) {
    float largest = 0.0f;
    for (size_t i = 0; i < m.indices.size(); ++i) {
        const size_t j = i % 3 == 2 ? i - 2 : i + 1;
        largest = std::max(largest, 1.0f - dot(m.normals[m.indices[i]], m.normals[m.indices[j]]));
    }
    return largest;
}

TEST(LoopSubdivision, WindsTrianglesWithPbrtsSmoothNormalsOnAClosedMesh) {
    float previous_turn = 2.0f;
    for (int levels = 1; levels <= 4; ++levels) {
        SCOPED_TRACE(levels);
        const TriangleMesh m = subdivide(octahedron(), levels);
        for (size_t t = 0; t < m.triangle_count(); ++t) {
            const Vec3f n = normalize(winding(m, t));
            for (int c = 0; c < 3; ++c) {
                const Vec3f& nv = m.normals[m.indices[3 * t + static_cast<size_t>(c)]];
                EXPECT_NEAR(length(nv), 1.0f, 1e-5f);
                EXPECT_GT(dot(nv, n), 0.5f) << "triangle " << t << " corner " << c;  // the same side
            }
            EXPECT_LT(dot(n, m.positions[m.indices[3 * t]]), 0.0f) << "triangle " << t;  // inward, as pbrt
        }
        // The limit surface is smooth (tangent-plane continuous): the normal turns across an edge
        // by less at each level, the edges being shorter. (Near the valence-4 vertices it falls
        // more slowly than the 4x of regular regions.)
        const float turn = largest_normal_turn(m);
        EXPECT_LT(turn, previous_turn / 1.5f);
        previous_turn = turn;
    }
}

TEST(LoopSubdivision, KeepsAFlatGridFlatWithItsStraightBoundaryEdges) {
    const int n = 6;
    const TriangleMesh m = subdivide(grid(n), 2);
    EXPECT_EQ(m.triangle_count(), 2u * n * n * 16);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const Vec3f& p = m.positions[i];
        EXPECT_EQ(p.z, 0.0f) << "vertex " << i;
        EXPECT_NEAR(m.normals[i].z, -1.0f, 1e-6f) << "vertex " << i;  // pbrt's side (see the header)
        EXPECT_TRUE(p.x >= 0 && p.x <= n && p.y >= 0 && p.y <= n) << "vertex " << i;
    }
    // The boundary: the vertices on edges that only one triangle uses. Away from the corners
    // (which the boundary curve cuts, as in pbrt-v4, whose boundary corners are not sharp) it
    // stays on the square's sides, the boundary rules being 1D B-spline rules along them.
    std::map<std::pair<uint32_t, uint32_t>, int> edge_uses;
    for (size_t t = 0; t < m.triangle_count(); ++t)
        for (size_t c = 0; c < 3; ++c) {
            const uint32_t a = m.indices[3 * t + c], b = m.indices[3 * t + (c + 1) % 3];
            ++edge_uses[{std::min(a, b), std::max(a, b)}];
        }
    size_t checked = 0;
    for (const auto& [edge, uses] : edge_uses) {
        if (uses != 1) continue;
        for (const uint32_t v : {edge.first, edge.second}) {
            const Vec3f& p = m.positions[v];
            const float side = static_cast<float>(n);
            if (std::min(p.x, side - p.x) < 1.0f && std::min(p.y, side - p.y) < 1.0f) continue;  // near a corner
            EXPECT_TRUE(p.x == 0 || p.x == n || p.y == 0 || p.y == n) << "boundary vertex " << v << " at (" << p.x << ", " << p.y << ")";
            ++checked;
        }
    }
    EXPECT_EQ(checked, 2u * 4 * (4 * (n - 2) + 1));  // 4 sides, each vertex seen from its two edges
    for (size_t t = 0; t < m.triangle_count(); ++t) EXPECT_LT(winding(m, t).z, 0.0f) << "triangle " << t;
}

// A mesh of tests/data/meshes/loop_reference.txt: pbrt-v4's output, from an independent port of
// its LoopSubdivide (tools/loop_reference/pbrt_loop_reference.py).
struct Reference {
    std::string name;
    int levels = 0;
    Polyhedron input;
    std::vector<Vec3f> positions, normals;
    size_t triangles = 0;
};

std::vector<Reference> read_references() {
    std::ifstream in(std::filesystem::path(CANDELA_TEST_DATA_DIR) / "meshes" / "loop_reference.txt");
    EXPECT_TRUE(in) << "tests/data/meshes/loop_reference.txt";
    std::vector<Reference> refs;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string tag;
        words >> tag;
        if (tag == "mesh") {
            refs.emplace_back();
            words >> refs.back().name >> refs.back().levels;
        } else if (tag == "P") {
            Vec3f p;
            words >> p.x >> p.y >> p.z;
            refs.back().input.positions.push_back(p);
        } else if (tag == "I") {
            int a, b, c;
            words >> a >> b >> c;
            refs.back().input.indices.insert(refs.back().input.indices.end(), {a, b, c});
        } else if (tag == "V") {
            Vec3f p, n;
            words >> p.x >> p.y >> p.z >> n.x >> n.y >> n.z;
            refs.back().positions.push_back(p);
            refs.back().normals.push_back(n);
        } else if (tag == "T") {
            words >> refs.back().triangles;
        }
    }
    return refs;
}

TEST(LoopSubdivision, MatchesPbrtV4VertexByVertex) {
    // Boundaries (valences 2 to 5), irregular interior vertices (4, 5, 8) and a bump: pbrt's
    // weights, limit masks and the sign of its normals. The two number their vertices
    // differently, so vertices are matched by position.
    const std::vector<Reference> refs = read_references();
    ASSERT_EQ(refs.size(), 3u);
    for (const Reference& ref : refs) {
        SCOPED_TRACE(ref.name + " at level " + std::to_string(ref.levels));
        const TriangleMesh m = subdivide(ref.input, ref.levels);
        ASSERT_EQ(m.triangle_count(), ref.triangles);
        ASSERT_EQ(m.positions.size(), ref.positions.size());
        ASSERT_EQ(m.normals.size(), ref.normals.size());
        for (size_t r = 0; r < ref.positions.size(); ++r) {
            size_t nearest = 0;
            for (size_t i = 1; i < m.positions.size(); ++i)
                if (length_squared(m.positions[i] - ref.positions[r]) <
                    length_squared(m.positions[nearest] - ref.positions[r]))
                    nearest = i;
            EXPECT_LT(length(m.positions[nearest] - ref.positions[r]), 2e-6f) << "pbrt vertex " << r;
            EXPECT_GT(dot(m.normals[nearest], ref.normals[r]), 1.0f - 1e-6f) << "pbrt vertex " << r;
        }
        // And the front agrees with the normals, as pbrt-v4 lets them decide it.
        for (size_t t = 0; t < m.triangle_count(); ++t)
            for (size_t c = 0; c < 3; ++c)
                EXPECT_GT(dot(normalize(winding(m, t)), m.normals[m.indices[3 * t + c]]), 0.5f) << "triangle " << t;
    }
}

TEST(LoopSubdivision, RejectsWhatItCannotSubdivide) {
    EXPECT_EQ(error_of(tetrahedron(), -1), "loop subdivision levels must be in [0, 15]; got -1");
    EXPECT_EQ(error_of(tetrahedron(), 16), "loop subdivision levels must be in [0, 15]; got 16");
    EXPECT_EQ(error_of({tetrahedron().positions, {0, 1}}, 1),
              "a loop subdivision surface needs three indices per triangle; got 2");
    EXPECT_EQ(error_of({tetrahedron().positions, {0, 1, 4}}, 1),
              "loop subdivision index 4 (number 3) is out of range; there are 4 positions");
    EXPECT_EQ(error_of({tetrahedron().positions, {0, 1, 2}}, 1), "loop subdivision position 3 is used by no triangle");
    EXPECT_EQ(error_of(tetrahedron(), 15),
              "4 triangles subdivided 15 times are more than the 2^31 - 1 OpenSubdiv can index");
    // Two triangles sharing an edge in the same direction: wound inconsistently.
    const Polyhedron flipped = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {0, 1, 2, 1, 2, 3}};
    EXPECT_TRUE(error_of(flipped, 1).starts_with("the loop subdivision surface is not a consistently wound manifold"));
    // Two triangles meeting at a vertex only, and a triangle with a repeated corner.
    const Polyhedron bowtie = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}, {0, 1, 2, 0, 3, 4}};
    EXPECT_TRUE(error_of(bowtie, 1).starts_with("the loop subdivision surface is not a consistently wound manifold at position 0"));
    const Polyhedron repeated = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2, 0, 0, 1}};
    EXPECT_TRUE(error_of(repeated, 1).starts_with("the loop subdivision surface is not a consistently wound manifold"));
}

}  // namespace
}  // namespace candela
