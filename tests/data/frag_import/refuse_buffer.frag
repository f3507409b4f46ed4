#buffer RGBA32F
#include "DE-Raytracer.frag"
uniform float Radius; slider[0,1,2]
float DE(vec3 p) {
	return length(p) - Radius;
}
