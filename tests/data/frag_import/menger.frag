#info A Menger sponge by mirror folds, as fraktal's presets/menger.json builds it from blocks.
#info Written for fraktal's tests in FragM's dialect.
#include "MathUtils.frag"
#include "DE-Raytracer.frag"
#group Menger

// Number of folds
uniform int Iterations; slider[1,8,20]

// Scale about the corner
uniform float Scale; slider[1,3,4]

// The corner the scale is about
uniform vec3 Offset; slider[(0,0,0),(1,1,1),(2,2,2)]

#group Twist
// Turn each fold about z
uniform bool Twist; checkbox[false]
// Angle of the turn, in degrees
uniform float Angle; slider[-180,0,180]

// Sorts the coordinates so that x >= y >= z (the sponge's mirror folds).
void sortDescending(inout vec3 z) {
	float a = min(z.x - z.y, 0.0); z.x -= a; z.y += a;
	a = min(z.x - z.z, 0.0); z.x -= a; z.z += a;
	a = min(z.y - z.z, 0.0); z.y -= a; z.z += a;
}

float boxDistance(vec3 z, vec3 size) {
	vec3 q = abs(z) - size;
	return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

float DE(vec3 pos) {
	vec3 z = pos;
	float w = 1.0;
	int n = 0;
	while (n < Iterations) {
		z = abs(z);
		sortDescending(z);
		z = (z - Offset) * Scale + Offset;
		w *= Scale;
		z.z -= 2.0 * min(0.0, z.z + 1.0);
		if (Twist) z = rotationMatrix3(vec3(0.0, 0.0, 1.0), Angle) * z;
		orbitTrap = min(orbitTrap, abs(vec4(z, dot(z, z))));
		n++;
		if (dot(z, z) > 1e6) break;
	}
	return boxDistance(z, vec3(1.0)) / w;
}

#preset Default
FOV = 0.414213562
Eye = 2.3,1.7,3.0
Target = 0,0,0
Up = 0,1,0
Detail = -3.24
FudgeFactor = 1
MaxRaySteps = 200
Iterations = 8
Scale = 3
Offset = 1,1,1
Twist = false
Angle = 0
Gamma = 2
Exposure = 0.8
ToneMapping = 4
AO = 0,0,0,0.7
DetailAO = -0.8
Specular = 0.3
SpecularExp = 24
SpotLight = 1,0.95,0.9,0.5
SpotLightDir = -0.3,0.6
CamLight = 1,1,1,1.2
CamLightMin = 0.1
Glow = 1,1,1,0
Fog = 0.2
HardShadow = 0.8 Locked
ShadowSoft = 8
BaseColor = 1,1,1
OrbitStrength = 0.4
X = 0.5,0.6,0.6,0.3
Y = 1,0.6,0,0.5
Z = 0.8,0.78,1,0.2
R = 0.4,0.7,1,0.1
BackgroundColor = 0.35,0.35,0.4
GradientBackground = 0.3
CycleColors = false
#endpreset

#preset Twisted
FOV = 0.6
Eye = 0,0,5
Target = 0,0,0
Up = 0,1,0
Iterations = 5
Scale = 3
Offset = 1,1,1
Twist = true
Angle = 30 Locked
#endpreset
