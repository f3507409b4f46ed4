#info Returns one value of a built-in include's helper as the distance, chosen by Probe, so that
#info fraktal's tests read FragM's conventions back from the GPU.
#include "MathUtils.frag"
#include "Complex.frag"
#include "DE-Raytracer.frag"

// Which helper the DE returns
uniform int Probe; slider[0,0,6]

float DE(vec3 p) {
	// FragM's rotation matrices turn by -angle: (1,0,0) about z by 90 degrees goes to (0,-1,0).
	if (Probe == 0) return (rotationMatrix3(vec3(0.0, 0.0, 1.0), 90.0) * vec3(1.0, 0.0, 0.0)).y;
	if (Probe == 1) return (rotationMatrixXYZ(vec3(90.0, 0.0, 0.0)) * vec3(0.0, 1.0, 0.0)).z;
	if (Probe == 2) return (rotationMatrix(vec3(0.0, 1.0, 0.0), 90.0) * vec4(0.0, 0.0, 1.0, 1.0)).x;
	if (Probe == 3) return (translate(vec3(1.0, 2.0, 3.0)) * scale4(2.0) * vec4(1.0, 1.0, 1.0, 1.0)).z;
	if (Probe == 4) return cMul(vec2(0.0, 1.0), vec2(0.0, 1.0)).x;
	if (Probe == 5) return cDiv(vec2(2.0, 0.0), vec2(0.0, 1.0)).y;
	if (Probe == 6) return TWO_PI - PI;
	return 0.0;
}
