#info A ball seen from 3D.frag's default camera: no camera line in the preset.
#info Written for fraktal's tests in FragM's dialect.
#include "DE-Raytracer.frag"
uniform float Radius; slider[0.1,2,4]

float DE(vec3 p) {
	return length(p) - Radius;
}

#preset Default
Radius = 2
#endpreset
