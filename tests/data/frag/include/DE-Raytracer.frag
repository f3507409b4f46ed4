#donotrun
// fraktal's test stand-in for FragM's DE-Raytracer.frag: a few of its settings and a
// plain march. Written for fraktal's tests.
#include "3D.frag"

#group Raytracer
// Distance to the surface, as a power of ten of the ray length
uniform float Detail; slider[-7,-2.3,0];
uniform float FudgeFactor; slider[0,1,1];
uniform int MaxRaySteps; slider[0,56,10000]
uniform float NormalBackStep; slider[0,1,10] Locked

#group Light
uniform vec4 AO; color[0,0.7,1,0.0,0.0,0.0];
uniform vec2 SpotLightDir; slider[(-1,-1),(0.1,0.1),(1,1)]

#group Coloring
uniform vec3 BaseColor; color[1.0,1.0,1.0];
uniform vec4 X; color[-1,0.7,1,0.5,0.6,0.6];

vec4 orbitTrap = vec4(10000.0);
float DE(vec3 pos); // the frag that includes this defines it

vec3 color(vec3 from, vec3 dir) {
	float t = 0.0;
	for (int i = 0; i < MaxRaySteps; i++) {
		float d = DE(from + t * dir) * FudgeFactor;
		if (d < pow(10.0, Detail) * t) return BaseColor;
		t += d;
	}
	return vec3(0.0);
}
