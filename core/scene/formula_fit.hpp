// Settings that fit a formula's blocks, and a camera that shows its object, both found from the
// blocks and the distance estimate rather than from a table of known formulas.
#pragma once

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/preset.hpp"
#include "core/scene/distance.hpp"

namespace fraktal {

// Picks the estimator family and bailout the loop body needs when the current ones do not fit:
// a power block (Mandelbulb) wants the escape-time log estimator and a bailout of about 2; a
// point-dependent step (add c) without one a Mandelbox-type escape-time linear estimator and a
// bailout of at least 20 (the orbit grows linearly; formula_fit.cpp says why no more); neither,
// a pure IFS of folds and scales, a distance estimator (the user's, if it is one; else a box)
// and a bailout that never stops the folds, unless a step's stretch grows with |p| (twist, bend:
// BlockDesc::stretchGrowsWithRadius): then the smallest bailout that keeps the object.
// Custom GLSL blocks are left as they are. Returns whether anything changed.
bool fitEstimatorToBlocks(Formula& f);

// Surface points found by marching the DE `de` inward from a sphere of radius `radius` about
// the origin along `rays` directions spread evenly over it (a Fibonacci sphere), each step at
// most radius / 16.
std::vector<vec3> probeSurface(const DistanceAt& de, double radius, int rays = 96, int maxSteps = 256);

// The bound radius the object needs: its extent as found by probeSurface from far outside
// (`searchRadius`), plus a margin; `fallback` when no ray reaches a surface or the surface
// reaches out to the search sphere (an unbounded object).
double fittedBoundRadius(const DistanceAt& de, double searchRadius, double fallback);

// "Frame object": the camera keeps its viewing direction and field of view and moves to where
// the sphere around the object's probed surface points just fits the view, looking at its
// centre, outside the surface. When the DE shows no surface, the bound-sphere default view.
Camera framedCamera(const Formula& f, const DistanceAt& de, const Camera& current);

// After a node-list edit: the estimator and bailout fitted to the blocks and, for a formula the
// CPU can evaluate, the bound radius fitted to the new object; the camera framed when it ends up
// inside the surface, closer to it than 1% of the bound, or so far away that the object is small
// in view (more than 2 times the framed distance). Returns whether the formula changed.
bool fitFormulaAfterEdit(Formula& f, Camera& camera);
// The same on a document: when the fit replaces the estimator, its parameter tracks go with it.
bool fitFormulaAfterEdit(Preset& p);

// The view a preset shows when "Reset view" is chosen: looking at the origin from outside the
// bound sphere, framing it for the camera's field of view.
Camera defaultViewFor(const Formula& f, const Camera& current);

}  // namespace fraktal
