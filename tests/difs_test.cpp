// The dIFS estimate (formulas/difs.hpp) against closed forms: one shape is its own distance, the
// shapes an orbit measures are their union, each over its divisor; a folded and scaled stack stays
// conservative. And the generalized box fold (formulas/generalized_box_fold.hpp) on the cube is
// the box fold.
#include <gtest/gtest.h>

#include <random>

#include "core/de_check.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

Node nodeOf(std::string_view id, std::initializer_list<std::pair<std::string_view, vec3>> values) {
    Node n = Node::make(*findBlock(id));
    for (const auto& [name, v] : values) {
        const int i = n.block->paramIndex(name);
        EXPECT_GE(i, 0) << id << " has no " << name;
        n.values[size_t(i)] = v;
    }
    return n;
}

Formula difsOf(std::vector<Node> nodes, int iterations) {
    Formula f;
    f.nodes = std::move(nodes);
    f.estimator = Node::make(*findBlock("difs"));
    f.iterations = iterations;
    f.bailout = 1e6;
    return f;
}

// The distance outside a box of half-sizes h about the origin (0 within: the dIFS box's).
double outsideBox(const vec3& p, const vec3& h) { return length(max(abs(p) - h, vec3(0.0))); }

}  // namespace

TEST(Difs, OneShapeIsItsOwnDistance) {
    const vec3 size(0.5, 0.25, 1.0);
    const Formula f = difsOf({nodeOf("difs_box", {{"size", size}})}, 1);
    const Formula torus = difsOf({nodeOf("difs_torus", {{"ring_radius", vec3(1.0)}, {"thickness", vec3(0.25)}})}, 1);
    for (const vec3& p : test::randomPoints(500, 3.0, 5)) {
        EXPECT_NEAR(evaluate(f, p).distance, outsideBox(p, size), 1e-12);
        const double ring = length(glm::dvec2(length(glm::dvec2(p.x, p.y)) - 1.0, p.z)) - 0.25;
        EXPECT_NEAR(evaluate(torus, p).distance, ring, 1e-12);
        EXPECT_EQ(evaluate(torus, p).inside, ring <= 0.0);
    }
}

// Two iterations of (box, scale by 2 about the origin, translate): the box at p, then at
// 2 p + t over the running derivative 2 (plus the divisor's offset): the union of the box and a
// half-size copy moved by -t / 2.
TEST(Difs, TheOrbitsShapesAreTheirUnionEachOverItsDivisor) {
    const vec3 size(0.3, 0.3, 0.3), t(1.0, 0.0, 0.0);
    for (double offset : {0.0, 1.0}) {
        const Formula f = difsOf({nodeOf("difs_box", {{"size", size}, {"w_offset", vec3(offset)}}),
                                  nodeOf("scale", {{"scale", vec3(2.0)}}), nodeOf("translate", {{"offset", t}})},
                                 2);
        for (const vec3& p : test::randomPoints(500, 3.0, 6)) {
            const double first = outsideBox(p, size) / (1.0 + offset);
            const double second = outsideBox(2.0 * p + t, size) / (2.0 + offset);
            EXPECT_NEAR(evaluate(f, p).distance, std::min(first, second), 1e-12) << "w_offset " << offset;
        }
    }
    // No shape step: nothing is drawn (Mandelbulber2's start, 1000, everywhere).
    const Formula none = difsOf({nodeOf("scale", {{"scale", vec3(2.0)}})}, 3);
    EXPECT_EQ(evaluate(none, vec3(0.1, 0.2, 0.3)).distance, 1000.0);
}

// A dIFS of bars folded by planes and scaled (a tree of boxes): the least of the shape distances
// over the running derivative is a lower bound of the distance to their union, on random rays.
TEST(Difs, AFoldedAndScaledStackIsConservative) {
    Formula f = difsOf({nodeOf("difs_box", {{"size", vec3(0.4, 0.4, 1.0)}}), nodeOf("abs_fold", {}),
                        nodeOf("rotate", {{"axis", vec3(1.0, 1.0, 0.0)}, {"angle", vec3(35.0)}}),
                        nodeOf("scale", {{"scale", vec3(1.6)}, {"center", vec3(0.0, 0.0, 1.2)}})},
                       12);
    f.boundRadius = 3.0;
    Camera camera;
    camera.position = vec3(0.0, -3.5, 0.5);
    camera.target = vec3(0.0, 0.0, 0.5);
    ConservativenessOptions o;
    o.rays = 80;
    o.stepsAcrossBound = 6000;
    o.seed = 17;
    const ConservativenessReport r = checkConservativeness(f, camera, o);
    EXPECT_GE(r.raysHit, 12);
    std::printf("dIFS tree of boxes: %d/%d rays hit, worst DE / distance %.4f\n", r.raysHit, r.rays, r.worstRatio);
    EXPECT_LE(r.worstRatio, 1.0 + 1e-3) << "at (" << r.worstPoint.x << ", " << r.worstPoint.y << ", " << r.worstPoint.z
                                        << ")";
}

// The generalized box fold's cube (type 1) at `solid` s reflects each coordinate beyond s, as the
// box fold at limit s: a face is a mirror, an edge a half turn, a corner a point reflection.
TEST(Difs, TheGeneralizedFoldOnTheCubeIsTheBoxFold) {
    for (double solid : {0.5, 1.0, 1.7}) {
        const Node general = nodeOf("generalized_box_fold", {{"type", vec3(1.0)}, {"solid", vec3(solid)}});
        const Node box = nodeOf("box_fold", {{"limit", vec3(solid)}});
        for (const vec3& x : test::randomPoints(2000, 4.0, 8)) {
            P4 a{x, 1.0}, b{x, 1.0};
            general.block->apply(a, x, general.args());
            box.block->apply(b, x, box.args());
            EXPECT_NEAR(length(a.xyz - b.xyz), 0.0, 1e-9)
                << "solid " << solid << " at " << x.x << " " << x.y << " " << x.z;
        }
    }
}

// Every type folds a point outside its polyhedron by an isometry onto one no farther from the
// origin along the faces' normals than the point was (a fold moves points inwards), and leaves the
// inside as it is.
TEST(Difs, TheGeneralizedFoldKeepsTheInsideAndFoldsTheOutsideInwards) {
    for (int type = 0; type <= 7; ++type) {
        const Node fold = nodeOf("generalized_box_fold", {{"type", vec3(type)}, {"solid", vec3(1.0)}});
        for (const vec3& x : test::randomPoints(2000, 0.5, 9 + uint64_t(type))) {
            P4 p{x, 1.0};
            fold.block->apply(p, x, fold.args());
            EXPECT_EQ(p.xyz, x) << "type " << type << ": a point within 0.5 of the centre is inside";
        }
        int folded = 0;
        for (const vec3& x : test::randomPoints(2000, 4.0, 19 + uint64_t(type))) {
            P4 p{x, 1.0};
            fold.block->apply(p, x, fold.args());
            folded += p.xyz != x;
            EXPECT_EQ(p.w, 1.0);
            EXPECT_LE(length(p.xyz), length(x) + 1e-9) << "type " << type;
        }
        EXPECT_GT(folded, 500) << "type " << type;
    }
}
