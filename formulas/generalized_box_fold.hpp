#pragma once
#include <algorithm>
#include <array>

#include "core/block.hpp"

namespace fraktal::blocks {

// The generalized box fold (Mandelbulber2's generalized_fold_box, fractal_formulas.cpp
// GeneralizedFoldBoxIteration; "Generalized box fold", fractalforums.com, new theories and
// research): the box fold's polyhedral form. A point outside the solid (the polyhedron whose faces
// lie at distance `solid` along the type's unit normals) is reflected through the nearest part of
// the surface that the ray from the origin leaves through: a face (a mirror), an edge (a half turn
// about it) or a vertex (a point reflection). The cube's type is the box fold at the solid's
// distance. Each case is an isometry, so the running derivative is unchanged; where the case
// changes between neighbours the two images need not agree, so the bound holds at the point only.
// The edge search runs in the face's plane from the face's centre (solid times its normal);
// Mandelbulber2 starts it from the unit normal, which is the same at its default solid of 1 (no
// example changes it) and elsewhere moves the edge off the faces' intersection, so that the fold
// is no longer an isometry.
//
// The normals of the eight types, one table, each type one or two runs of it (Mandelbulber2's
// order, which decides ties): the octahedron's 8 (its first 4 the tetrahedron's), the cube's 6
// (its last 2 the prisms' caps), the dodecahedron's 12, the icosahedron's other 12, the hexagon's
// and the pentagon's sides.
namespace generalized_fold {
constexpr double s = 0.57735026918962576, b = 0.52573111211913360, ab = 0.85065080835203993, c = 0.93417235896271570,
                 d = 0.35682208977308993, h = 0.86602540378443865, c1 = 0.30901699437494742, s1 = 0.95105651629515357,
                 c2 = 0.80901699437494742, s2 = 0.58778525229247313;
constexpr double kNormals[49][3] = {
    {s, s, -s},    {s, -s, s},   {-s, s, s},  {-s, -s, -s}, {s, s, s},    {-s, -s, s},   {-s, s, -s},
    {s, -s, -s},   {1, 0, 0},    {-1, 0, 0},  {0, 1, 0},    {0, -1, 0},   {0, 0, 1},     {0, 0, -1},
    {0, b, ab},    {0, b, -ab},  {0, -b, ab}, {0, -b, -ab}, {b, ab, 0},   {b, -ab, 0},   {-b, ab, 0},
    {-b, -ab, 0},  {ab, 0, b},   {-ab, 0, b}, {ab, 0, -b},  {-ab, 0, -b}, {0, d, c},     {0, d, -c},
    {0, -d, c},    {0, -d, -c},  {c, 0, d},   {c, 0, -d},   {-c, 0, d},   {-c, 0, -d},   {d, c, 0},
    {d, -c, 0},    {-d, c, 0},   {-d, -c, 0}, {1, 0, 0},    {0.5, h, 0},  {-0.5, h, 0},  {-1, 0, 0},
    {-0.5, -h, 0}, {0.5, -h, 0}, {1, 0, 0},   {c1, s1, 0},  {-c2, s2, 0}, {-c2, -s2, 0}, {c1, -s1, 0},
};
// Per type: the first run's start and length, the second's start and length.
constexpr int kRuns[8][4] = {{0, 4, 0, 0},  {8, 6, 0, 0},   {0, 8, 0, 0},   {14, 12, 0, 0},
                             {0, 14, 0, 0}, {0, 8, 26, 12}, {12, 2, 38, 6}, {12, 2, 44, 5}};
}  // namespace generalized_fold

struct GeneralizedBoxFold {
    static constexpr std::string_view id = "generalized_box_fold";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Generalized box fold";
    static constexpr std::string_view help =
        "The box fold on a polyhedron: outside it, a point is reflected through the face, edge or vertex the ray "
        "from the origin leaves by. Types: 0 tetrahedron, 1 cube, 2 octahedron, 3 dodecahedron, 4 octahedron and "
        "cube, 5 icosahedron, 6 hexagonal prism, 7 pentagonal prism.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"type", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 7.0, "The polyhedron (0 to 7, see the help)."},
        ParamDecl{"solid", ParamType::Float, {1.0, 0.0, 0.0}, 0.05, 4.0, "Distance of its faces from the origin."},
    };

    // The three searches: along the ray from y by l, the face (other than skipped ones) it crosses
    // first before l's end, as Mandelbulber2 finds it (a * c > b keeps the nearest).
    static constexpr std::string_view glsl = R"(
    const float kS = 0.577350269, kB = 0.525731112, kAB = 0.850650808, kC = 0.934172359, kD = 0.356822090,
                kH = 0.866025404, kC1 = 0.309016994, kS1 = 0.951056516, kC2 = 0.809016994, kS2 = 0.587785252;
    const vec3 normals[49] = vec3[](
        vec3(kS, kS, -kS), vec3(kS, -kS, kS), vec3(-kS, kS, kS), vec3(-kS, -kS, -kS), vec3(kS, kS, kS), vec3(-kS, -kS, kS),
        vec3(-kS, kS, -kS), vec3(kS, -kS, -kS), vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
        vec3(0, 0, 1), vec3(0, 0, -1), vec3(0, kB, kAB), vec3(0, kB, -kAB), vec3(0, -kB, kAB), vec3(0, -kB, -kAB),
        vec3(kB, kAB, 0), vec3(kB, -kAB, 0), vec3(-kB, kAB, 0), vec3(-kB, -kAB, 0), vec3(kAB, 0, kB), vec3(-kAB, 0, kB),
        vec3(kAB, 0, -kB), vec3(-kAB, 0, -kB), vec3(0, kD, kC), vec3(0, kD, -kC), vec3(0, -kD, kC), vec3(0, -kD, -kC),
        vec3(kC, 0, kD), vec3(kC, 0, -kD), vec3(-kC, 0, kD), vec3(-kC, 0, -kD), vec3(kD, kC, 0), vec3(kD, -kC, 0),
        vec3(-kD, kC, 0), vec3(-kD, -kC, 0), vec3(1, 0, 0), vec3(0.5, kH, 0), vec3(-0.5, kH, 0), vec3(-1, 0, 0),
        vec3(-0.5, -kH, 0), vec3(0.5, -kH, 0), vec3(1, 0, 0), vec3(kC1, kS1, 0), vec3(-kC2, kS2, 0), vec3(-kC2, -kS2, 0),
        vec3(kC1, -kS1, 0));
    const ivec4 runs[8] = ivec4[](ivec4(0, 4, 0, 0), ivec4(8, 6, 0, 0), ivec4(0, 8, 0, 0), ivec4(14, 12, 0, 0),
                                  ivec4(0, 14, 0, 0), ivec4(0, 8, 26, 12), ivec4(12, 2, 38, 6), ivec4(12, 2, 44, 5));
    ivec4 run = runs[clamp(int(type + 0.5), 0, 7)];
    int sides = run.y + run.w;
    vec3 z = p.xyz;
    int mirror = -1;
    float a = 1.0;
    for (int i = 0; i < sides; ++i) {
        vec3 n = normals[i < run.y ? run.x + i : run.z + i - run.y];
        float k = dot(z, n);
        if (k > 0.0 && a * k > solid) { mirror = i; a = solid / k; }
    }
    if (mirror >= 0) {
        vec3 nm = normals[mirror < run.y ? run.x + mirror : run.z + mirror - run.y];
        vec3 x = z - nm * (dot(z, nm) - solid);
        vec3 y = nm * solid, l = x - y;
        int edge = -1;
        a = 1.0;
        for (int i = 0; i < sides; ++i) {
            vec3 n = normals[i < run.y ? run.x + i : run.z + i - run.y];
            float k = dot(l, n), m = solid - dot(y, n);
            if (i != mirror && k > 0.0 && a * k > m) { edge = i; a = m / k; }
        }
        if (edge >= 0) {
            vec3 corner = y + l * a;
            vec3 axis = cross(nm, normals[edge < run.y ? run.x + edge : run.z + edge - run.y]);
            x = corner + axis * (dot(z - corner, axis) / dot(axis, axis));
            y = corner;
            l = x - corner;
            int vertex = -1;
            a = 1.0;
            for (int i = 0; i < sides; ++i) {
                vec3 n = normals[i < run.y ? run.x + i : run.z + i - run.y];
                float k = dot(l, n), m = solid - dot(y, n);
                if (i != mirror && i != edge && k > 0.0 && a * k > m) { vertex = i; a = m / k; }
            }
            if (vertex >= 0) x = y + l * a;
        }
        p.xyz = 2.0 * x - z;
    }
)";
    static vec3 normal(const int run[4], int i) {
        const double* n = generalized_fold::kNormals[i < run[1] ? run[0] + i : run[2] + i - run[1]];
        return vec3(n[0], n[1], n[2]);
    }
    static void apply(P4& p, const vec3&, Args args) {
        const double type = args.f(0), solid = args.f(1);
        const int* run = generalized_fold::kRuns[std::clamp(int(type + 0.5), 0, 7)];
        const int sides = run[1] + run[3];
        const vec3 z = p.xyz;
        int mirror = -1;
        double a = 1.0;
        for (int i = 0; i < sides; ++i) {
            const double k = dot(z, normal(run, i));
            if (k > 0.0 && a * k > solid) mirror = i, a = solid / k;
        }
        if (mirror < 0) return;
        const vec3 nm = normal(run, mirror);
        vec3 x = z - nm * (dot(z, nm) - solid);
        vec3 y = nm * solid, l = x - y;
        int edge = -1;
        a = 1.0;
        for (int i = 0; i < sides; ++i) {
            const double k = dot(l, normal(run, i)), m = solid - dot(y, normal(run, i));
            if (i != mirror && k > 0.0 && a * k > m) edge = i, a = m / k;
        }
        if (edge >= 0) {
            const vec3 corner = y + l * a;
            const vec3 axis = glm::cross(nm, normal(run, edge));
            x = corner + axis * (dot(z - corner, axis) / dot(axis, axis));
            y = corner;
            l = x - corner;
            int vertex = -1;
            a = 1.0;
            for (int i = 0; i < sides; ++i) {
                const double k = dot(l, normal(run, i)), m = solid - dot(y, normal(run, i));
                if (i != mirror && i != edge && k > 0.0 && a * k > m) vertex = i, a = m / k;
            }
            if (vertex >= 0) x = y + l * a;
        }
        p.xyz = 2.0 * x - z;
    }
};

}  // namespace fraktal::blocks
