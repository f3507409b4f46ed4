#info A bumpy ball lit and coloured by DE-Raytracer's settings, for fraktal's import tests.
#info Written for fraktal's tests in FragM's dialect.
#include "MathUtils.frag"
#include "DE-Raytracer.frag"
#group Ball
// The ball's radius
uniform float Radius; slider[0.5,1,2]
// How far the bumps rise
uniform float Bumps; slider[0,0.1,0.3]

float DE(vec3 p) {
	vec3 z = p;
	for (int i = 0; i < 4; i++) {
		z = abs(z) * 1.3 - vec3(0.2);
		orbitTrap = min(orbitTrap, abs(vec4(z, dot(z, z))));
	}
	return 0.5 * (length(p) - Radius - Bumps * sin(6.0 * p.x) * sin(6.0 * p.y) * sin(6.0 * p.z));
}

#preset Default
Eye = 0.4,1.2,3.6
Target = 0,0,0
Up = 0,1,0
FOV = 0.5
Detail = -3
MaxRaySteps = 200
Gamma = 2.2
Exposure = 1.4
ToneMapping = 1
SpotLight = 1,0.9,0.8,0.6
SpotLightDir = 0.35,-0.4
CamLight = 0.9,0.95,1,0.8
CamLightMin = 0.3
Specular = 0.5
SpecularExp = 20
SpecularMax = 8
HardShadow = 1 Locked
ShadowSoft = 4
AO = 0,0,0,0.6
DetailAO = -1.5
Fog = 0.4
Glow = 1,1,1,0.2
BackgroundColor = 0.2,0.3,0.5
GradientBackground = 0
BaseColor = 0.9,0.8,0.7
OrbitStrength = 0.6
X = 0.5,0.6,0.6,0.7
Y = 1,0.6,0,0.4
Z = 0.8,0.78,1,-0.5
R = 0.4,0.7,1,0.12
CycleColors = false
#endpreset

#preset Cycling
Eye = 0.4,1.2,3.6
Target = 0,0,0
Up = 0,1,0
FOV = 0.5
OrbitStrength = 1
CycleColors = true
Cycles = 3.5
X = 0.1,0.5,0.9,1
Y = 1,0.6,0,0
Z = 0.8,0.78,1,0.5
R = 0.4,0.7,1,0
AO = 0.3,0.1,0,0.9
DetailAO = 0
HardShadow = 0.3
#endpreset

#preset Flat
Eye = 0.4,1.2,3.6
Target = 0,0,0
Up = 0,1,0
FOV = 0.5
OrbitStrength = 0
BaseColor = 0.25,0.5,0.75
AO = 0,0,0,0
HardShadow = 0
Fog = 0
Specular = 1.6
SpotLightDir = 1,0.7
BackgroundColor = 1.2,-0.5,0.5
#endpreset
