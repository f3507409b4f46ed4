// The 2D block registry, beside the 3D one (formulas/registry.cpp): one line per block. A block
// that lacks part of its declaration fails to compile here (see the concepts in
// core/plane/plane_block.hpp).
#include "formulas/plane/abs_fold.hpp"
#include "formulas/plane/estimators.hpp"
#include "formulas/plane/line_fold.hpp"
#include "formulas/plane/power.hpp"
#include "formulas/plane/rotate.hpp"
#include "formulas/plane/scale.hpp"
#include "formulas/plane/translate.hpp"
#include "formulas/plane/triangle_capture.hpp"
#include "formulas/plane/triangle_corner.hpp"

namespace fraktal {

// A named namespace, not an anonymous one: in a unity build this file may share a unit with the 3D
// registry, whose blocks have the same names (AbsFold, Rotate, ...), and each using-directive must
// stay in its own scope.
namespace plane_registry {
using namespace plane_blocks;
constexpr std::array kPlaneBlocks{
    describePlane<LineFold>(),         describePlane<AbsFold>(),
    describePlane<Rotate>(),           describePlane<Scale>(),
    describePlane<Translate>(),        describePlane<TriangleCorner>(),
    describePlane<TriangleCapture>(),  describePlane<Power>(),
    describePlane<EscapeEstimator>(),  describePlane<TriangleEstimator>(),
    describePlane<SegmentEstimator>(),
};
}  // namespace plane_registry
using plane_registry::kPlaneBlocks;

std::span<const PlaneBlockDesc> allPlaneBlocks() { return kPlaneBlocks; }

const PlaneBlockDesc* findPlaneBlock(std::string_view id) {
    for (const PlaneBlockDesc& b : kPlaneBlocks)
        if (b.id == id) return &b;
    return nullptr;
}

}  // namespace fraktal
