#include "candela/geometry/loop_subdivision.h"

#include <fmt/format.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

#include "candela/core/error.h"

namespace candela {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

[[noreturn]] void fail(const std::string& message) { throw SceneError(SourceLocation{}, message); }

// Warren's even-vertex weight, as pbrt-v4 uses it (Loop's own weight differs at valences other
// than 3 and 6).
float beta(int valence) { return valence == 3 ? 3.0f / 16.0f : 3.0f / (8.0f * static_cast<float>(valence)); }

// The weight of each one-ring vertex in the limit position of a vertex refined with beta.
float limit_gamma(int valence) {
    return 1.0f / (static_cast<float>(valence) + 3.0f / (8.0f * beta(valence)));
}

// (1 - n w) p + w * sum of the ring: the shape of every interior mask here.
Vec3f weigh_ring(const Vec3f& p, const std::vector<Vec3f>& ring, float w) {
    Vec3f sum = (1.0f - static_cast<float>(ring.size()) * w) * p;
    for (const Vec3f& q : ring) sum += w * q;
    return sum;
}

// The two neighbours of boundary vertex v along the boundary.
std::pair<Far::Index, Far::Index> boundary_neighbours(const Far::TopologyLevel& level, Far::Index v) {
    Far::Index ends[2] = {-1, -1};
    int found = 0;
    for (const Far::Index e : level.GetVertexEdges(v)) {
        if (!level.IsEdgeBoundary(e) || found == 2) continue;
        const auto ev = level.GetEdgeVertices(e);
        ends[found++] = ev[0] == v ? ev[1] : ev[0];
    }
    return {ends[0], ends[1]};
}

std::vector<Vec3f> ring_positions(const Far::TopologyLevel& level, Far::Index v, const std::vector<Vec3f>& p) {
    std::vector<Vec3f> ring;
    for (const Far::Index e : level.GetVertexEdges(v)) {
        const auto ev = level.GetEdgeVertices(e);
        ring.push_back(p[static_cast<size_t>(ev[0] == v ? ev[1] : ev[0])]);
    }
    return ring;
}

// One level of pbrt-v4's refinement: the children of `parent`'s vertices and edges.
std::vector<Vec3f> refine_positions(const Far::TopologyLevel& parent, int child_vertices, const std::vector<Vec3f>& p) {
    std::vector<Vec3f> child(static_cast<size_t>(child_vertices));
    for (Far::Index v = 0; v < parent.GetNumVertices(); ++v) {
        const Vec3f& pv = p[static_cast<size_t>(v)];
        Vec3f even;
        if (parent.IsVertexBoundary(v)) {
            // The boundary is a cubic B-spline curve: 1/8 3/4 1/8.
            const auto [a, b] = boundary_neighbours(parent, v);
            even = 0.75f * pv + 0.125f * p[static_cast<size_t>(a)] + 0.125f * p[static_cast<size_t>(b)];
        } else {
            const std::vector<Vec3f> ring = ring_positions(parent, v, p);
            even = weigh_ring(pv, ring, beta(static_cast<int>(ring.size())));
        }
        child[static_cast<size_t>(parent.GetVertexChildVertex(v))] = even;
    }
    for (Far::Index e = 0; e < parent.GetNumEdges(); ++e) {
        const auto ev = parent.GetEdgeVertices(e);
        const Vec3f& a = p[static_cast<size_t>(ev[0])];
        const Vec3f& b = p[static_cast<size_t>(ev[1])];
        Vec3f odd;
        if (parent.IsEdgeBoundary(e)) {
            odd = 0.5f * a + 0.5f * b;
        } else {
            odd = 3.0f / 8.0f * a + 3.0f / 8.0f * b;
            for (const Far::Index f : parent.GetEdgeFaces(e))
                for (const Far::Index fv : parent.GetFaceVertices(f))
                    if (fv != ev[0] && fv != ev[1]) odd += 1.0f / 8.0f * p[static_cast<size_t>(fv)];
        }
        child[static_cast<size_t>(parent.GetEdgeChildVertex(e))] = odd;
    }
    return child;
}

// v's one-ring in pbrt-v4's order (SDVertex::oneRing), which sets the sign of its normals. For a
// face (v, next, prev) wound counter-clockwise, an interior ring runs clockwise: from a face's
// `next` to the `next` of the face whose `prev` it is. A boundary ring starts at the clockwise
// end and runs counter-clockwise, from a face's `next` to that face's `prev`, and so on.
std::vector<Far::Index> one_ring(const Far::TopologyLevel& level, Far::Index v) {
    struct Corner {
        Far::Index next, prev;
    };
    std::vector<Corner> corners;
    const auto faces = level.GetVertexFaces(v);
    const auto local = level.GetVertexFaceLocalIndices(v);
    for (int i = 0; i < faces.size(); ++i) {
        const auto fv = level.GetFaceVertices(faces[i]);
        corners.push_back({fv[(local[i] + 1) % 3], fv[(local[i] + 2) % 3]});
    }
    const auto find = [&corners](auto member, Far::Index value) -> const Corner* {
        for (const Corner& c : corners)
            if (c.*member == value) return &c;
        return nullptr;
    };
    std::vector<Far::Index> ring;
    if (!level.IsVertexBoundary(v)) {
        ring.push_back(corners.front().next);
        while (ring.size() < corners.size()) ring.push_back(find(&Corner::prev, ring.back())->next);
        return ring;
    }
    const Corner* c = nullptr;
    for (const Corner& candidate : corners)
        if (!find(&Corner::prev, candidate.next)) c = &candidate;
    ring.push_back(c->next);
    for (; c; c = find(&Corner::next, c->prev)) ring.push_back(c->prev);
    return ring;
}

// pbrt-v4's limit normal at a vertex: cross(S, T) of its tangent masks (Halstead et al. 1993 for
// interior vertices; Hoppe et al. 1994 for boundary ones), over limit positions.
Vec3f limit_normal(const Vec3f& p, const std::vector<Vec3f>& ring, bool boundary) {
    const int n = static_cast<int>(ring.size());
    Vec3f s(0, 0, 0), t(0, 0, 0);
    if (!boundary) {
        for (int j = 0; j < n; ++j) {
            const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / static_cast<float>(n);
            s += std::cos(angle) * ring[static_cast<size_t>(j)];
            t += std::sin(angle) * ring[static_cast<size_t>(j)];
        }
        return cross(s, t);
    }
    s = ring.back() - ring.front();
    if (n == 2) {
        t = ring[0] + ring[1] - 2.0f * p;
    } else if (n == 3) {
        t = ring[1] - p;
    } else if (n == 4) {
        t = -1.0f * ring[0] + 2.0f * ring[1] + 2.0f * ring[2] - 1.0f * ring[3] - 2.0f * p;
    } else {
        const float theta = std::numbers::pi_v<float> / static_cast<float>(n - 1);
        t = std::sin(theta) * (ring.front() + ring.back());
        for (int k = 1; k < n - 1; ++k)
            t += (2.0f * std::cos(theta) - 2.0f) * std::sin(static_cast<float>(k) * theta) * ring[static_cast<size_t>(k)];
        t = -t;
    }
    return cross(s, t);
}

void check_input(std::span<const Vec3f> positions, std::span<const int> indices, int levels) {
    if (levels < 0 || levels > kMaxLoopLevels)
        fail(fmt::format("loop subdivision levels must be in [0, {}]; got {}", kMaxLoopLevels, levels));
    if (indices.empty() || indices.size() % 3 != 0)
        fail(fmt::format("a loop subdivision surface needs three indices per triangle; got {}", indices.size()));
    std::vector<bool> used(positions.size(), false);
    for (size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] < 0 || static_cast<size_t>(indices[i]) >= positions.size())
            fail(fmt::format("loop subdivision index {} (number {}) is out of range; there are {} positions",
                             indices[i], i + 1, positions.size()));
        used[static_cast<size_t>(indices[i])] = true;
    }
    for (size_t i = 0; i < used.size(); ++i)
        if (!used[i]) fail(fmt::format("loop subdivision position {} is used by no triangle", i));
    // OpenSubdiv numbers vertices and faces with int.
    const uint64_t triangles = indices.size() / 3;
    if (triangles > (uint64_t{std::numeric_limits<int>::max()} >> (2 * levels)) ||
        positions.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
        fail(fmt::format("{} triangles subdivided {} times are more than the 2^31 - 1 OpenSubdiv can index",
                         triangles, levels));
}

}  // namespace

TriangleMesh loop_subdivide(std::span<const Vec3f> positions, std::span<const int> indices, int levels) {
    check_input(positions, indices, levels);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    const std::vector<int> vertices_per_face(indices.size() / 3, 3);
    Far::TopologyDescriptor descriptor;
    descriptor.numVertices = static_cast<int>(positions.size());
    descriptor.numFaces = static_cast<int>(vertices_per_face.size());
    descriptor.numVertsPerFace = vertices_per_face.data();
    descriptor.vertIndicesPerFace = indices.data();
    // pbrt-v4 treats boundary edges as creases and keeps no corner sharp: "edge only".
    Sdc::Options options;
    options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    const std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(descriptor, Factory::Options(Sdc::SCHEME_LOOP, options)));
    if (!refiner) fail("OpenSubdiv cannot build the loop subdivision surface's topology");
    const Far::TopologyLevel& base = refiner->GetLevel(0);
    for (Far::Index v = 0; v < base.GetNumVertices(); ++v)
        if (base.IsVertexNonManifold(v))
            fail(fmt::format("the loop subdivision surface is not a consistently wound manifold at position {} (an "
                             "edge of more than two triangles, two fans meeting at a vertex, a degenerate "
                             "triangle, or neighbours wound opposite ways)",
                             v));
    if (levels > 0) {
        Far::TopologyRefiner::UniformOptions uniform(levels);
        uniform.fullTopologyInLastLevel = true;
        refiner->RefineUniform(uniform);
    }

    std::vector<Vec3f> p(positions.begin(), positions.end());
    for (int l = 0; l < levels; ++l)
        p = refine_positions(refiner->GetLevel(l), refiner->GetLevel(l + 1).GetNumVertices(), p);

    const Far::TopologyLevel& last = refiner->GetLevel(levels);
    TriangleMesh mesh;
    mesh.positions.resize(p.size());
    for (Far::Index v = 0; v < last.GetNumVertices(); ++v) {
        const Vec3f& pv = p[static_cast<size_t>(v)];
        if (last.IsVertexBoundary(v)) {
            const auto [a, b] = boundary_neighbours(last, v);
            mesh.positions[static_cast<size_t>(v)] =
                0.6f * pv + 0.2f * p[static_cast<size_t>(a)] + 0.2f * p[static_cast<size_t>(b)];
        } else {
            const std::vector<Vec3f> ring = ring_positions(last, v, p);
            mesh.positions[static_cast<size_t>(v)] = weigh_ring(pv, ring, limit_gamma(static_cast<int>(ring.size())));
        }
    }
    mesh.normals.resize(p.size());
    bool normals_usable = true;
    std::vector<Vec3f> ring;
    for (Far::Index v = 0; v < last.GetNumVertices(); ++v) {
        ring.clear();
        for (const Far::Index r : one_ring(last, v)) ring.push_back(mesh.positions[static_cast<size_t>(r)]);
        const Vec3f n = limit_normal(mesh.positions[static_cast<size_t>(v)], ring, last.IsVertexBoundary(v));
        const float l2 = length_squared(n);
        normals_usable = normals_usable && std::isfinite(l2) && l2 > 0.0f;
        mesh.normals[static_cast<size_t>(v)] = normals_usable ? normalize(n) : n;
    }
    // A degenerate ring has no normal to give: the mesh is then shaded flat, as load_mesh does.
    if (!normals_usable) mesh.normals.clear();
    mesh.indices.reserve(3 * static_cast<size_t>(last.GetNumFaces()));
    for (Far::Index f = 0; f < last.GetNumFaces(); ++f) {
        const auto fv = last.GetFaceVertices(f);
        // Wound against the input, so that the front agrees with pbrt's normals (see the header).
        for (const int corner : {0, 2, 1}) mesh.indices.push_back(static_cast<uint32_t>(fv[corner]));
    }
    return mesh;
}

}  // namespace candela
