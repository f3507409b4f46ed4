#info A ball pushed away from the eye: its DE reads 3D.frag's Eye, as some tessellations do.
#info Written for fraktal's tests in FragM's dialect.
#include "DE-Raytracer.frag"
uniform vec3 Eye;
#group Ball
// How far the ball is pushed away from the eye
uniform float Push; slider[0,0.5,2]

float DE(vec3 p) {
	return length(p + Push * normalize(Eye)) - 1.0;
}

#preset Default
Eye = 1.5,0.5,3.5
Target = 0,0,0
Up = 0,1,0
FOV = 0.45
Push = 0.75
#endpreset
