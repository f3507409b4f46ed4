#info A ball whose tooltip and comment were saved as Latin-1 (café, °), as many artists' editors save them.
#info Written for fraktal's tests in FragM's dialect.
#include "DE-Raytracer.frag"
// Rayon de la sphère, en unités
uniform float Rayon; slider[0.1,1,2]

float DE(vec3 p) {
	return length(p) - Rayon; // la sphère
}

#preset Default
Eye = 0,0,4
Rayon = 1.2
#endpreset
