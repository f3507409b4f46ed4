#info A box turned toward a direction slider, for fraktal's import tests: a vec3 slider whose
#info minimum equals its maximum is a direction in FragM (each component in [-1, 1]), as 3D.frag's Up.
#info Written for fraktal's tests in FragM's dialect.
#include "MathUtils.frag"
#include "DE-Raytracer.frag"
#group Box
// The direction the box's long side points along
uniform vec3 Axis; slider[(0,0,0),(0,1,0),(0,0,0)]
// A length whose range is written backwards: FragM holds it at its minimum
uniform float Length; slider[1.5,0.5,1]

float DE(vec3 p) {
	vec3 a = normalize(Axis);
	float along = dot(p, a);
	vec3 across = p - along * a;
	return max(abs(along) - Length, length(across) - 0.3);
}

#preset Default
Eye = 0,0.5,4
Target = 0,0,0
Up = 0,1,0
FOV = 0.5
Axis = 0.6,-0.8,0
#endpreset
