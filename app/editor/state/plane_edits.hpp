// Edits of a 2D formula (core/plane/plane_formula.hpp) as the 2D Formula panel performs them:
// the once-run start list and the loop list are edited alike (node_list_edits.hpp), the
// estimator is replaced. Pure functions on the data, unit-tested (tests/editor_plane_test.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/editor/state/editor_state.hpp"
#include "core/plane/plane_formula.hpp"

namespace fraktal::editor {

// The 2D blocks of one category, in registry order (the categorised "Add block" menu).
std::vector<const PlaneBlockDesc*> planeBlocksIn(Category category);

// The list a selection points into (nullptr for the estimator).
std::vector<PlaneNode>* planeList(PlaneFormula& f, PlaneList list);
// The selected node (the estimator for PlaneList::Estimator); nullptr when out of range.
PlaneNode* selectedPlaneNode(PlaneFormula& f, const PlaneSelection& sel);
// The selection moved into range: an empty list's selection falls to the loop's first node or
// the estimator.
PlaneSelection clampedSelection(const PlaneFormula& f, PlaneSelection sel);

// Adds `block` after the selected node of the selected list (an estimator block replaces the
// estimator). Returns the new selection (unchanged when the list is full).
PlaneSelection addPlaneBlock(PlaneFormula& f, const PlaneBlockDesc& block, PlaneSelection sel);
// Sets parameter `param` of the selected node, clamped to the declared range.
bool setPlaneParam(PlaneFormula& f, const PlaneSelection& sel, int param, double value);

// The node a 2D compile-error log names (`start node 2 "Rotate" (rotate)`, `node 1 "Power"
// (power)`, numbered from 1 as generatePlaneGLSL names them), or nullopt when it names none.
std::optional<PlaneSelection> planeNodeNamedInLog(const std::string& log);

// The zoom factor of `wheelSteps` mouse-wheel notches (positive: in), 1.25x a notch.
double planeWheelZoomFactor(double wheelSteps);

// One frame of mouse input over the 2D view, in window pixels: the drag since the last frame
// and the cursor, relative to the viewport's top left.
struct PlaneInput {
    double dragX = 0.0, dragY = 0.0;
    double cursorX = 0.0, cursorY = 0.0;
    double wheel = 0.0;  // notches, positive: zoom in
};
// The view after the input: the plane follows a drag, and a wheel zooms keeping the plane point
// under the cursor where it is. The image (imageWidth x imageHeight) fills a viewport
// `viewportWidth` window pixels wide (the render scale may make them differ).
PlaneViewRect navigatePlane(PlaneViewRect view, const PlaneInput& in, int imageWidth, int imageHeight,
                            double viewportWidth);

}  // namespace fraktal::editor
