#donotrun
// fraktal's own DE raytracer in FragM's dialect, for the frag bench's host in the tests: the
// march and hit test DE-Raytracer.frag documents (a hit where DE * FudgeFactor < 10^Detail *
// distance travelled), trace() giving a non-zero hitNormal on a hit and zero on a miss, as the
// host observes it; its floor, the plane dot(normalize(FloorNormal), p) = FloorHeight met from
// either side. Written for fraktal, not copied from FragM.
#include "3D.frag"

#group Raytracer
// Distance to the surface, as a power of ten of the ray length
uniform float Detail; slider[-7,-2.3,0];
uniform float FudgeFactor; slider[0,1,1];
uniform int MaxRaySteps; slider[0,56,10000]
uniform float MaxDistance; slider[0,1000,5000];
uniform bool EnableFloor; checkbox[false] Locked
uniform vec3 FloorNormal; slider[(-1,-1,-1),(0,0,1),(1,1,1)]
uniform float FloorHeight; slider[-50,0,50]

#group Coloring
uniform vec3 BaseColor; color[1.0,1.0,1.0];

vec4 orbitTrap = vec4(10000.0);
float DE(vec3 pos); // the frag that includes this defines it

// The DE with the floor, when it is on.
float sceneDE(vec3 p) {
	float d = DE(p);
	if (EnableFloor) d = min(d, abs(dot(normalize(FloorNormal), p) - FloorHeight));
	return d;
}

vec3 normalAt(vec3 p, float e) {
	vec2 h = vec2(e, 0.0);
	return normalize(vec3(sceneDE(p + h.xyy) - sceneDE(p - h.xyy), sceneDE(p + h.yxy) - sceneDE(p - h.yxy),
		sceneDE(p + h.yyx) - sceneDE(p - h.yyx)));
}

vec3 trace(vec3 from, vec3 dir, inout vec3 hit, inout vec3 hitNormal) {
	float eps = pow(10.0, Detail);
	float t = 0.0;
	for (int i = 0; i < MaxRaySteps; i++) {
		orbitTrap = vec4(10000.0);
		float d = sceneDE(from + t * dir) * FudgeFactor;
		t += d;
		if (d < eps * t) {
			hit = from + t * dir;
			hitNormal = normalAt(hit, max(eps * t * 0.5, 1e-7));
			return BaseColor * max(0.2, dot(hitNormal, -dir));
		}
		if (t > MaxDistance) break;
	}
	hitNormal = vec3(0.0);
	return vec3(0.0);
}

vec3 color(vec3 from, vec3 dir) {
	vec3 hit = vec3(0.0);
	vec3 hitNormal = vec3(0.0);
	return trace(from, dir, hit, hitNormal);
}
