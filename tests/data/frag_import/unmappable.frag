#include "DE-Raytracer.frag"
// A 4D offset: fraktal's parameters are numbers, toggles and 3-vectors
uniform vec4 Offset4; slider[(-1,-1,-1,-1),(0.5,0,0,0.25),(1,1,1,1)]
float DE(vec3 p) {
	vec4 q = vec4(p, 0.0) - Offset4;
	return length(q) - 1.0;
}
#preset Default
Offset4 = 0.25,0,0,0
#endpreset
