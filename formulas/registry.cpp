// The block registry: one line per block. A block that lacks part of its declaration fails to
// compile here (see the concepts in core/block.hpp).
#include "formulas/abs_fold.hpp"
#include "formulas/add_c.hpp"
#include "formulas/box_fold.hpp"
#include "formulas/estimators.hpp"
#include "formulas/mandelbulb.hpp"
#include "formulas/menger_fold.hpp"
#include "formulas/octahedral_fold.hpp"
#include "formulas/plane_fold.hpp"
#include "formulas/rotate.hpp"
#include "formulas/scale.hpp"
#include "formulas/sierpinski_fold.hpp"
#include "formulas/sphere_fold.hpp"
#include "formulas/translate.hpp"

namespace fraktal {

namespace {
using namespace blocks;
constexpr std::array kBlocks{
    describe<AbsFold>(),
    describe<PlaneFold>(),
    describe<BoxFold>(),
    describe<SphereFold>(),
    describe<MengerFold>(),
    describe<SierpinskiFold>(),
    describe<OctahedralFold>(),
    describe<Scale>(),
    describe<Translate>(),
    describe<Rotate>(),
    describe<AddC>(),
    describe<Mandelbulb>(),
    describe<BoxEstimator>(),
    describe<SphereEstimator>(),
    describe<TetrahedronEstimator>(),
    describe<EscapeLogEstimator>(),
    describe<EscapeLinearEstimator>(),
};
}  // namespace

std::span<const BlockDesc> allBlocks() { return kBlocks; }

}  // namespace fraktal
