#info A power bulb turned by a rotation computed once per frame in init().
#info Written for fraktal's tests in FragM's dialect.
#define providesInit
#include "MathUtils.frag"
#include "DE-Raytracer.frag"
#group Bulb

// Number of iterations
uniform int Iterations; slider[1,8,60]

// The bulb's power
uniform float Power; slider[1,8,16]

// Escape radius
uniform float Bailout; slider[0,4,30]

// Draw the Julia set of JuliaC instead
uniform bool Julia; checkbox[false]
uniform vec3 JuliaC; slider[(-2,-2,-2),(0.2,-0.1,0.3),(2,2,2)]

#group Rotation
// Axis of the turn applied each iteration
uniform vec3 RotAxis; slider[(-1,-1,-1),(0,1,0),(1,1,1)]
// Angle of the turn, in degrees
uniform float RotAngle; slider[-180,0,180]

uniform float time;

mat3 turn;

void init() {
	turn = rotationMatrix3(normalize(RotAxis), RotAngle + 0.0 * time);
}

/* A brace in a comment: { and another } must not confuse the function finder.
   void fakeFunction() { return; }
*/
void bulbPower(inout vec3 z, float r, inout float dr) {
	// "strings" with braces { are not GLSL, but a comment may hold one: }
	float theta = acos(clamp(z.z / r, -1.0, 1.0)) * Power;
	float phi = atan(z.y, z.x) * Power;
	dr = pow(r, Power - 1.0) * Power * dr + 1.0;
	z = pow(r, Power) * vec3(sin(theta) * cos(phi), sin(phi) * sin(theta), cos(theta));
}

float DE(vec3 pos) {
	vec3 z = pos;
	float dr = 1.0;
	float r = length(z);
	int i = 0;
	while (r < Bailout && i < Iterations) {
		bulbPower(z, r, dr);
		z += Julia ? JuliaC : pos;
		z = turn * z;
		r = length(z);
		orbitTrap = min(orbitTrap, abs(vec4(z, r * r)));
		i++;
	}
	return 0.5 * log(r) * r / dr;
}

#preset Default
FOV = 0.62536
Eye = 1.65,-1.2,0.28
Target = -5.2,4.2,-0.6
Up = 0.4,0.37,-0.83
Detail = -2.85
FudgeFactor = 0.9
MaxRaySteps = 164
AO = 0,0,0,0.85
Iterations = 12
Power = 8 Locked
Julia = false
JuliaC = 0.2,-0.1,0.3 NotLocked
RotAngle = 0
#endpreset

#preset Julia
Julia = true
JuliaC = -0.4,0.6,0.1 Locked
Iterations = 20
Bailout = 6 Locked
#endpreset
