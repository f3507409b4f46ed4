#info A sphere that reads a uniform of every annotation kind, for fraktal's import tests.
#include "DE-Raytracer.frag"
#define RADIUS_SCALE 1.0

#group Shape
// Radius of the sphere
uniform float Radius; slider[0.1,1,3]
// Steps of the radial ripple
uniform int Ripples; slider[0,3,12]
// Where the sphere sits
uniform vec3 Center; slider[(-1,-1,-1),(0,0.25,0),(1,1,1)]
// Stretch along x and y
uniform vec2 Stretch; slider[(0.5,0.5),(1,1),(2,2)]

#group Finish
// A shell instead of a ball
uniform bool Hollow; checkbox[true]
// Tint of the surface (read by the DE to nudge it, for the test)
uniform vec3 Tint; color[0.8,0.6,0.4]
// How the ripple is shaped
uniform int Profile; menu[1, Flat;Sine;Square]

float ripple(vec3 p) {
	if (Profile == 0) return 0.0;
	float s = sin(float(Ripples) * atan(p.y, p.x));
	return Profile == 1 ? 0.02 * s : 0.02 * sign(s);
}

float DE(vec3 pos) {
	vec3 p = pos - Center;
	p.xy /= Stretch;
	float d = length(p) - Radius * RADIUS_SCALE + ripple(p) + 0.001 * Tint.r;
	if (Hollow) d = abs(d) - 0.05;
	return d * min(Stretch.x, Stretch.y);
}

#preset Default
Eye = 0,0,4
Target = 0,0,0
Radius = 1.2
Ripples = 5
Hollow = false
Profile = 2
Center = 0,0.25,0
#endpreset
