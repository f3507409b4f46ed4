#info A rounded box on DE-Raytracer's floor, tilted, seen from above it.
#info Written for fraktal's tests in FragM's dialect.
#include "DE-Raytracer.frag"
#group Box
// Half sizes of the box
uniform vec3 Size; slider[(0,0,0),(0.8,0.5,0.6),(2,2,2)]
// Rounding of its edges
uniform float Rounding; slider[0,0.1,1]

float DE(vec3 p) {
	vec3 q = abs(p) - Size;
	return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - Rounding;
}

#preset Default
Eye = 2.5,0.3,3.2
Target = 0,0.1,0
Up = 0,1,0
FOV = 0.55
EnableFloor = true Locked
FloorNormal = -0.08,1,0.03
FloorHeight = -0.7
MaxRaySteps = 300
#endpreset

#preset Below
Eye = 2.5,-2.5,3.2
Target = 0,0,0
Up = 0,1,0
FOV = 0.55
EnableFloor = true
FloorNormal = -0.08,1,0.03
FloorHeight = -0.7
#endpreset
