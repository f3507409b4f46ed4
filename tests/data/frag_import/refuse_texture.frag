#include "DE-Raytracer.frag"
// A height map
uniform sampler2D Heights; file[heights.png]
float DE(vec3 p) {
	return p.y - texture2D(Heights, p.xz).r;
}
