// An indexed triangle mesh and the measures that say whether it can be printed: the volume it
// encloses and whether it is closed and manifold.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vec.hpp"

namespace fraktal::mesh {

struct TriangleMesh {
    std::vector<std::array<float, 3>> points;
    std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise seen from outside
    // Each point's colour, linear Rec.709 (albedo), or empty: no colour.
    std::vector<std::array<float, 3>> colors;

    vec3 point(uint32_t i) const { return vec3(points[i][0], points[i][1], points[i][2]); }
    // The signed volume enclosed (divergence theorem over the triangles' tetrahedra with the
    // origin): positive when the triangles face outwards.
    double enclosedVolume() const;
    // Reverses every triangle (the inside becomes the outside).
    void flip();
    // Moves and scales every point: p * scale + offset.
    void transform(double scale, const vec3& offset);
    // The bounding box (zero-size at the origin when empty).
    std::array<vec3, 2> bounds() const;
};

// Closed and manifold, as a slicer needs: every edge is shared by exactly two triangles, which
// run it in opposite directions (consistent orientation), no triangle repeats a vertex, and
// every vertex's triangles form a single fan (no two solids touching at a point).
struct ManifoldReport {
    int64_t edges = 0;
    int64_t boundaryEdges = 0;     // used by one triangle: a hole
    int64_t overSharedEdges = 0;   // used by three or more
    int64_t misorientedEdges = 0;  // two triangles running it the same way
    int64_t degenerateTriangles = 0;
    int64_t pinchedVertices = 0;  // more than one fan of triangles about the vertex
    bool manifold() const {
        return boundaryEdges == 0 && overSharedEdges == 0 && misorientedEdges == 0 && degenerateTriangles == 0 &&
               pinchedVertices == 0;
    }
};
ManifoldReport checkManifold(const TriangleMesh& mesh);

// The pairs of triangles that pass through each other (a printer's slicer fails on them), among
// those sharing no vertex: an edge of one crossing the other's inside. Pairs that only touch, and
// coplanar overlaps, are not counted.
int64_t countCrossingTriangles(const TriangleMesh& mesh);

// The distance from p to the nearest point of the triangle abc (Ericson, Real-Time Collision
// Detection, 5.1.5).
double pointTriangleDistance(const vec3& p, const vec3& a, const vec3& b, const vec3& c);

}  // namespace fraktal::mesh
