#info A box-fold fractal with every kind of FragM annotation. Written for fraktal's tests.
#include "DE-Raytracer.frag"
#include "shared/fold_helpers.frag"

#group Box
// Iterations of the fold
uniform int Iterations; slider[0,12,50]
// The scale of each step
uniform float Scale; slider[-3,2.0,3] Locked
uniform float MinRadius; slider[0,0.25,2]
uniform float FixedRadius; slider[0,1,2] NotLocked
// Offset, as a 4D tuple (only xyz is used)
uniform vec4 Offset4; slider[(-1,-1,-1,-1),(0,0,0,0),(1,1,1,1)]
uniform vec2 Twist; slider[(-1,-1),(0.5,0.25),(1,1)]
uniform float Tiny; slider[1e-5,1e-3,1e-1] Logarithmic
// Colour of the box
uniform vec3 BoxColor; color[0.8,0.5,0.25]
// Glow colour and strength
uniform vec4 BoxGlow; color[0,0.3,1,1.0,0.9,0.5] NotLockable
// The fold to use
uniform int FoldKind; menu[1, Box;Sphere;Both]
uniform sampler2D Palette; file[palette.png]
uniform bool Fixed; checkbox[TRUE] AlwaysLocked

float DE(vec3 p) {
	vec3 z = p;
	float dz = 1.0;
	for (int i = 0; i < Iterations; i++) {
		if (FoldKind != 1) boxFold(z, dz);
		if (FoldKind != 0) sphereFold(z, dz, MinRadius * MinRadius, FixedRadius * FixedRadius);
		z = Scale * z + p + Offset4.xyz;
		dz = dz * abs(Scale) + 1.0;
		orbitTrap = min(orbitTrap, abs(vec4(z, dot(z, z))));
	}
	return length(z) / abs(dz);
}

#preset Default
Iterations = 14
Scale = 2.5 Locked
Offset4 = 0.1,0.2,0.3,0.4
Twist = 0.5,0.25
Tiny = 0.001 Logarithmic
BoxColor = 0.8,0.5,0.25
BoxGlow = 1,0.9,0.5,0.3
FoldKind = 2
Fixed = true AlwaysLocked
#endpreset

#preset A default of sorts
Iterations = 9
#endpreset
