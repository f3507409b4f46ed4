#info A Brute-Raytracer frag: membership only, no distance.
#include "Brute-Raytracer.frag"
bool inside(vec3 p) {
	return dot(p, p) < 1.0;
}
