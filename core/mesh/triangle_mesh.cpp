#include "core/mesh/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
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

namespace {

// Whether the open segment pq passes through the inside of triangle abc (Moller and Trumbore
// 1997, with the segment's ends and the triangle's edges excluded by a relative margin, so
// that neighbours meeting along a shared point or edge are not counted).
bool segmentCrossesTriangle(const vec3& p, const vec3& q, const vec3& a, const vec3& b, const vec3& c) {
    constexpr double kMargin = 1e-9;
    const vec3 dir = q - p, e1 = b - a, e2 = c - a;
    const vec3 h = glm::cross(dir, e2);
    const double det = glm::dot(e1, h);
    if (std::abs(det) < 1e-30) return false;  // parallel (coplanar overlaps are not seen)
    const double inv = 1.0 / det;
    const vec3 s = p - a;
    const double u = glm::dot(s, h) * inv;
    if (u <= kMargin || u >= 1.0 - kMargin) return false;
    const vec3 qv = glm::cross(s, e1);
    const double v = glm::dot(dir, qv) * inv;
    if (v <= kMargin || u + v >= 1.0 - kMargin) return false;
    const double t = glm::dot(e2, qv) * inv;
    return t > kMargin && t < 1.0 - kMargin;
}

bool trianglesCross(const TriangleMesh& m, const std::array<uint32_t, 3>& s, const std::array<uint32_t, 3>& t) {
    const vec3 a[3] = {m.point(s[0]), m.point(s[1]), m.point(s[2])};
    const vec3 b[3] = {m.point(t[0]), m.point(t[1]), m.point(t[2])};
    for (int k = 0; k < 3; ++k) {
        if (segmentCrossesTriangle(a[k], a[(k + 1) % 3], b[0], b[1], b[2])) return true;
        if (segmentCrossesTriangle(b[k], b[(k + 1) % 3], a[0], a[1], a[2])) return true;
    }
    return false;
}

}  // namespace

int64_t countCrossingTriangles(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) return 0;
    // A uniform grid of cells about twice the mean edge long: each triangle is listed in the cells
    // its box touches, and a pair is tested in the one cell that holds the low corner of the
    // overlap of their boxes (so each pair once).
    double edgeSum = 0.0;
    for (const auto& t : mesh.triangles) edgeSum += glm::length(mesh.point(t[1]) - mesh.point(t[0]));
    const double cell = std::max(2.0 * edgeSum / double(mesh.triangles.size()), 1e-12);
    const auto box = mesh.bounds();
    auto cellOf = [&](const vec3& p) { return glm::ivec3(glm::floor((p - box[0]) / cell)); };
    std::vector<std::array<vec3, 2>> boxes(mesh.triangles.size());
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
    auto key = [](const glm::ivec3& c) {
        return (uint64_t(uint32_t(c.z)) << 42) ^ (uint64_t(uint32_t(c.y)) << 21) ^ uint64_t(uint32_t(c.x));
    };
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        const vec3 a = mesh.point(t[0]), b = mesh.point(t[1]), c = mesh.point(t[2]);
        boxes[i] = {glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))};
        const glm::ivec3 lo = cellOf(boxes[i][0]), hi = cellOf(boxes[i][1]);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) cells[key({x, y, z})].push_back(i);
    }
    int64_t crossing = 0;
    for (const auto& [cellKey, list] : cells)
        for (size_t i = 0; i < list.size(); ++i)
            for (size_t j = i + 1; j < list.size(); ++j) {
                const auto &s = mesh.triangles[list[i]], &t = mesh.triangles[list[j]];
                const auto &bs = boxes[list[i]], &bt = boxes[list[j]];
                if (glm::any(glm::greaterThan(bs[0], bt[1])) || glm::any(glm::greaterThan(bt[0], bs[1]))) continue;
                if (key(cellOf(glm::max(bs[0], bt[0]))) != cellKey) continue;
                // Neighbours sharing a vertex or an edge meet there by construction.
                bool shared = false;
                for (uint32_t v : s) shared = shared || v == t[0] || v == t[1] || v == t[2];
                if (!shared && trianglesCross(mesh, s, t)) ++crossing;
            }
    return crossing;
}

}  // namespace fraktal::mesh
