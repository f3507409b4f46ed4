#info A Mandelbulb turned each iteration by a rotation init() computes once per frame.
#define providesInit
#include "MathUtils.frag"
#include "Complex.frag"
#include "DE-Raytracer.frag"

uniform int Iterations; slider[1,10,40]
uniform float Power; slider[2,8,16]
uniform float Bailout; slider[1,2,10]
// Turn applied each iteration (degrees about x, y, z)
uniform vec3 Turn; slider[(-180,-180,-180),(0,0,0),(180,180,180)]

mat3 rot;

void init() {
	rot = rotationMatrixXYZ(Turn);
}

float DE(vec3 pos) {
	vec3 z = pos;
	float dr = 1.0;
	float r = length(z);
	for (int i = 0; i < Iterations && r < Bailout; i++) {
		float theta = acos(z.z / r) * Power;
		float phi = atan(z.y, z.x) * Power;
		dr = pow(r, Power - 1.0) * Power * dr + 1.0;
		vec2 turned = cMul(vec2(cos(phi), sin(phi)), vec2(1.0, 0.0));
		z = pow(r, Power) * vec3(sin(theta) * turned.x, sin(theta) * turned.y, cos(theta));
		z = rot * z + pos;
		orbitTrap = min(orbitTrap, abs(vec4(z, r * r)));
		r = length(z);
	}
	return 0.5 * log(r) * r / dr;
}

#preset Default
Eye = 0,0,3
Target = 0,0,0
Turn = 0,0,0
#endpreset
