// The block registry: one line per block. A block that lacks part of its declaration fails to
// compile here (see the concepts in core/block.hpp).
#include "formulas/abox_fold4d.hpp"
#include "formulas/abs_add_conditional.hpp"
#include "formulas/abs_fold.hpp"
#include "formulas/add_c.hpp"
#include "formulas/add_c_axes.hpp"
#include "formulas/add_c_symmetric.hpp"
#include "formulas/aexion.hpp"
#include "formulas/amazing_surf.hpp"
#include "formulas/axis_remainder.hpp"
#include "formulas/axis_scale.hpp"
#include "formulas/benesi.hpp"
#include "formulas/benesi_folds.hpp"
#include "formulas/benesi_pine_tree.hpp"
#include "formulas/box_fold.hpp"
#include "formulas/box_fold_axes.hpp"
#include "formulas/box_fold_soft.hpp"
#include "formulas/box_fold_value.hpp"
#include "formulas/coastalbrot.hpp"
#include "formulas/collatz.hpp"
#include "formulas/conditional_shift.hpp"
#include "formulas/deforms.hpp"
#include "formulas/derivative_tweak.hpp"
#include "formulas/difs.hpp"
#include "formulas/estimators.hpp"
#include "formulas/four_d.hpp"
#include "formulas/generalized_box_fold.hpp"
#include "formulas/hypercomplex.hpp"
#include "formulas/ides.hpp"
#include "formulas/inv_cylindrical.hpp"
#include "formulas/kifs_icosahedral.hpp"
#include "formulas/kifs_octahedral.hpp"
#include "formulas/kifs_tetrahedral.hpp"
#include "formulas/kleinian.hpp"
#include "formulas/mandelbox_smooth.hpp"
#include "formulas/mandelbulb.hpp"
#include "formulas/mandelbulb_bermarte.hpp"
#include "formulas/mandelbulb_eye.hpp"
#include "formulas/mandelbulb_kali_multi.hpp"
#include "formulas/mandelbulb_variants.hpp"
#include "formulas/menger_fold.hpp"
#include "formulas/menger_rotate.hpp"
#include "formulas/menger_scale.hpp"
#include "formulas/menger_smooth.hpp"
#include "formulas/msltoe.hpp"
#include "formulas/objects.hpp"
#include "formulas/octahedral_fold.hpp"
#include "formulas/plane_fold.hpp"
#include "formulas/platonic_solid.hpp"
#include "formulas/poly_fold.hpp"
#include "formulas/poly_fold_sym.hpp"
#include "formulas/primitives.hpp"
#include "formulas/pseudo_kleinian.hpp"
#include "formulas/quadratic_bulbs.hpp"
#include "formulas/quaternion.hpp"
#include "formulas/quaternion4d.hpp"
#include "formulas/riemann_sphere.hpp"
#include "formulas/rotate.hpp"
#include "formulas/rotate4d.hpp"
#include "formulas/scale.hpp"
#include "formulas/scale_vary.hpp"
#include "formulas/scator.hpp"
#include "formulas/sierpinski_fold.hpp"
#include "formulas/sin_cos_max.hpp"
#include "formulas/sin_or_cos.hpp"
#include "formulas/smooth_box_fold.hpp"
#include "formulas/sphere_fold.hpp"
#include "formulas/sphere_fold_parabolic.hpp"
#include "formulas/sphere_invert.hpp"
#include "formulas/translate.hpp"

namespace fraktal {

// Named, not anonymous: the 2D registry (formulas/plane/registry.cpp) may share a unity build's unit
// with this file, and its blocks have the same names; each using-directive stays in its own scope.
namespace block_registry {
using namespace blocks;
constexpr std::array kBlocks{
    describe<AbsFold>(),
    describe<PlaneFold>(),
    describe<BoxFold>(),
    describe<SphereFold>(),
    describe<SphereFoldParabolic>(),
    describe<MengerFold>(),
    describe<SierpinskiFold>(),
    describe<OctahedralFold>(),
    describe<Scale>(),
    describe<Translate>(),
    describe<Rotate>(),
    describe<AddC>(),
    describe<Mandelbulb>(),
    describe<SphereInvert>(),
    describe<AmazingSurf>(),
    describe<SmoothBoxFold>(),
    describe<KifsTetrahedral>(),
    describe<KifsOctahedral>(),
    describe<KifsIcosahedral>(),
    describe<MengerRotate>(),
    describe<PseudoKleinian>(),
    describe<Kleinian>(),
    describe<ModTile>(),
    describe<Twist>(),
    describe<Bend>(),
    describe<MandelbulbPhase>(),
    describe<MandelbulbSine>(),
    describe<MandelbulbCosine>(),
    describe<Bristorbrot>(),
    // Blocks added later go after the others of their kind, so that the editor's menus keep their
    // rows (each category lists its blocks in this order).
    describe<AxisScale>(),
    describe<MengerScale>(),
    describe<ConditionalShift>(),
    describe<BoxFoldAxes>(),
    describe<BenesiPow2>(),
    describe<BenesiPineTree>(),
    describe<RiemannSphere>(),
    describe<RiemannSphereV1>(),
    describe<RiemannSphereV2>(),
    describe<Coastalbrot>(),
    describe<MandelbulbEye>(),
    describe<MsltoeDonut>(),
    describe<MsltoeSym2Mod>(),
    describe<MandelboxSmoothFold>(),
    describe<JosKleinian>(),
    describe<AbsAddConditional>(),
    describe<EiffieMsltoe>(),
    describe<MengerSmooth>(),
    describe<BenesiT1>(),
    describe<BenesiBoxFold>(),
    describe<BoxFoldSoft>(),
    describe<BoxFoldGeneral>(),
    describe<Mandelbulb2>(),
    describe<Lkmitch>(),
    describe<PrismFold>(),
    describe<AddCAxes>(),
    describe<GeneralizedBoxFold>(),
    describe<DifsTorus>(),
    describe<DifsBox>(),
    describe<DifsEllipsoid>(),
    describe<DifsGrid>(),
    describe<DifsHexGrid>(),
    describe<SinCosMax>(),
    describe<SinOrCos>(),
    describe<ScaleVary>(),
    describe<DifsCylinder>(),
    describe<AddCSymmetric>(),
    describe<PlatonicSolid>(),
    describe<DerivativeTweak>(),
    describe<StartW>(),
    describe<Menger4d>(),
    describe<Sierpinski4d>(),
    describe<MandelbulbKaliMulti>(),
    describe<ScatorSquare>(),
    describe<AxisRemainder>(),
    describe<BoxFoldValue>(),
    describe<AboxFold4d>(),
    describe<Rotate4d>(),
    describe<PolyFold>(),
    describe<PolyFoldSym>(),
    describe<Quaternion4d>(),
    describe<MandelbulbBermarte>(),
    describe<InvCylindrical>(),
    describe<QuickDudley>(),
    describe<Makin3d2>(),
    describe<Mandelbulb3>(),
    describe<Mandelbulb4>(),
    describe<MsltoeSym3Mod>(),
    describe<MsltoeSym3Mod2>(),
    describe<MsltoeSym4Fold>(),
    describe<Ides>(),
    describe<AexionOctopus>(),
    describe<MsltoeToroidal>(),
    describe<RiemannBulb>(),
    describe<MandelbulbMulti>(),
    describe<Collatz>(),
    describe<BoxEstimator>(),
    describe<SphereEstimator>(),
    describe<TetrahedronEstimator>(),
    describe<GradientTwin<BoxEstimator>>(),
    describe<GradientTwin<SphereEstimator>>(),
    describe<GradientTwin<TetrahedronEstimator>>(),
    describe<EscapeLogEstimator>(),
    describe<EscapePotentialEstimator>(),
    describe<EscapeGradientEstimator>(),
    describe<EscapeLinearEstimator>(),
    describe<PseudoKleinianEstimator>(),
    describe<KleinianEstimator>(),
    describe<PlaneCombine>(),
    describe<SphereCombine>(),
    describe<BoxCombine>(),
    describe<QuaternionJulia>(),
    describe<QuaternionMandelbrot>(),
    describe<HypercomplexMandelbrot>(),
    describe<WaterCombine>(),
    describe<AexionEstimator>(),
    describe<EscapeLinearGradientEstimator>(),
    describe<EscapeLinearXyEstimator>(),
    describe<HypercomplexJulia>(),
    describe<DifsEstimator>(),
};
}  // namespace block_registry
using block_registry::kBlocks;

std::span<const BlockDesc> allBlocks() { return kBlocks; }

namespace {
// The kinds of object beside the fractal, in the editor's "Add object" order.
constexpr std::array kObjects{
    describeObject<objects::Plane>(),    describeObject<objects::Box>(),   describeObject<objects::Sphere>(),
    describeObject<objects::Cylinder>(), describeObject<objects::Torus>(),
};
}  // namespace

std::span<const ObjectDesc> allObjects() { return kObjects; }

}  // namespace fraktal
