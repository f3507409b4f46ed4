#include "DE-Raytracer.frag"
// A colour with an intensity read as a shape: fraktal's parameters are numbers, toggles and 3-vectors
uniform vec4 Tint4; color[0,0.5,1,1.0,0.25,0.0]
float DE(vec3 p) {
	return length(p - Tint4.xyz) - Tint4.w;
}
#preset Default
Eye = 0,0,4
#endpreset
