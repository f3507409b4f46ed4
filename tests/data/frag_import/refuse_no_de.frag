#include "DE-Raytracer.frag"
uniform float Radius; slider[0,1,2]
float distanceTo(vec3 p) {
	return length(p) - Radius;
}
