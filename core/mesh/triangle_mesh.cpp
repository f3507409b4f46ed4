#include "core/mesh/triangle_mesh.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>

namespace fraktal::mesh {

double TriangleMesh::enclosedVolume() const {
    double sixTimes = 0.0;
    for (const auto& t : triangles) sixTimes += glm::dot(point(t[0]), glm::cross(point(t[1]), point(t[2])));
    return sixTimes / 6.0;
}

void TriangleMesh::flip() {
    for (auto& t : triangles) std::swap(t[1], t[2]);
}

void TriangleMesh::transform(double scale, const vec3& offset) {
    for (auto& p : points)
        for (int a = 0; a < 3; ++a) p[a] = float(p[a] * scale + offset[a]);
}

std::array<vec3, 2> TriangleMesh::bounds() const {
    if (points.empty()) return {vec3(0.0), vec3(0.0)};
    vec3 lo(1e300), hi(-1e300);
    for (size_t i = 0; i < points.size(); ++i) {
        lo = glm::min(lo, point(uint32_t(i)));
        hi = glm::max(hi, point(uint32_t(i)));
    }
    return {lo, hi};
}

ManifoldReport checkManifold(const TriangleMesh& mesh) {
    ManifoldReport r;
    // Each undirected edge: how many triangles run it a -> b with a < b, and b -> a.
    std::unordered_map<uint64_t, std::array<int, 2>> edges;
    edges.reserve(mesh.triangles.size() * 2);
    for (const auto& t : mesh.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            ++r.degenerateTriangles;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            ++edges[key][a < b ? 0 : 1];
        }
    }
    r.edges = int64_t(edges.size());
    for (const auto& [key, uses] : edges) {
        const int total = uses[0] + uses[1];
        if (total == 1)
            ++r.boundaryEdges;
        else if (total > 2)
            ++r.overSharedEdges;
        else if (uses[0] != 1)
            ++r.misorientedEdges;
    }
    // Fans: the triangles about each vertex, joined where they share an edge through it; more
    // than one group is a pinch (two parts of the surface meeting at the vertex alone).
    std::vector<std::vector<uint32_t>> around(mesh.points.size());
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i)
        for (uint32_t v : mesh.triangles[i]) around[v].push_back(i);
    std::vector<uint32_t> parent;
    for (uint32_t v = 0; v < around.size(); ++v) {
        const auto& tris = around[v];
        if (tris.size() < 2) continue;
        parent.resize(tris.size());
        std::iota(parent.begin(), parent.end(), 0u);
        auto find = [&](uint32_t x) {
            while (parent[x] != x) x = parent[x] = parent[parent[x]];
            return x;
        };
        // Triangles about v that share another vertex share an edge through v.
        std::map<uint32_t, uint32_t> firstWith;
        for (uint32_t i = 0; i < tris.size(); ++i)
            for (uint32_t w : mesh.triangles[tris[i]]) {
                if (w == v) continue;
                auto [it, fresh] = firstWith.emplace(w, i);
                if (!fresh) parent[find(i)] = find(it->second);
            }
        int groups = 0;
        for (uint32_t i = 0; i < tris.size(); ++i) groups += find(i) == i;
        if (groups > 1) ++r.pinchedVertices;
    }
    return r;
}

double pointTriangleDistance(const vec3& p, const vec3& a, const vec3& b, const vec3& c) {
    const vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return glm::length(p - a);
    const vec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return glm::length(p - b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const vec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return glm::length(p - c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const double denom = 1.0 / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

}  // namespace fraktal::mesh
