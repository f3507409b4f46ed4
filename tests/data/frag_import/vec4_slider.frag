#info A 3D slice of a 4D ball, offset by a 4-vector slider, for fraktal's import tests.
#info Written for fraktal's tests in FragM's dialect.
#include "DE-Raytracer.frag"
#group Slice
// The ball's centre in 4D; w is how far the slice is from it
uniform vec4 Offset4; slider[(-1,-1,-1,-1),(0,0,0,0),(1,1,1,1)]
// The ball's radius in 4D
uniform float Radius; slider[0.1,1,2]

float DE(vec3 p) {
	vec4 q = vec4(p, 0.0) - Offset4;
	return length(q) - Radius;
}

#preset Default
Eye = 0,0.5,3.5
Target = 0,0,0
Up = 0,1,0
FOV = 0.5
Offset4 = 0.25,0,0,0.6
Radius = 1.1
#endpreset
