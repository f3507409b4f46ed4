#info A sphere lattice with the Slicer raytracer's DE signature, its own vertex
#info code and a colouring hook. Written for fraktal's tests.
#define providesColor
#camera 3D
#include "3D.frag"

#vertex
varying float spinSine;
uniform float Spin; slider[0,0.5,6.28]
void computeSpin() { spinSine = sin(Spin); }
#endvertex

varying float spinSine;

#group Lattice
// Distance between the spheres
uniform float Spacing; slider[0.5,2,8]
uniform float Radius; slider[0.01,0.4,1]

vec3 baseColor(vec3 p, vec3 n) {
	return abs(n);
}

float DE(vec3 pos, int type) {
	vec3 q = mod(pos + 0.5 * Spacing, Spacing) - 0.5 * Spacing;
	return length(q) - Radius * (1.0 + 0.1 * spinSine);
}

vec3 color(vec3 from, vec3 dir) { return vec3(DE(from, 0)); }

#preset Zeta
Spacing = 3
#endpreset
#preset Default
Spacing = 2
Radius = 0.5
#endpreset
#preset KeyFrame.001
Spacing = 2
#endpreset
#preset default-wide
Spacing = 5
#endpreset
