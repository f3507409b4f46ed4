#donotrun
// Box and sphere folds, shared by the test frags.
#include "fold_constants.frag"

#group Folds
// How far the box fold reaches
uniform float FoldLimit; slider[0.1,1,3]

void boxFold(inout vec3 z, inout float dz) {
	z = clamp(z, -FoldLimit, FoldLimit) * 2.0 - z;
}

void sphereFold(inout vec3 z, inout float dz, float minR2, float fixedR2) {
	float r2 = dot(z, z);
	if (r2 < minR2) {
		float k = fixedR2 / minR2;
		z *= k; dz *= k;
	} else if (r2 < fixedR2) {
		float k = fixedR2 / r2;
		z *= k; dz *= k;
	}
}
