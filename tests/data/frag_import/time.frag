#include "DE-Raytracer.frag"
// FragM's clock, which the DE reads: the ball breathes
uniform float time;
uniform float Radius; slider[0,1,2]
float DE(vec3 p) {
	return length(p) - Radius * (1.0 + 0.1 * sin(time));
}
