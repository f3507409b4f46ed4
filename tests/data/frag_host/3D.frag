#donotrun
// fraktal's own 3D setup in FragM's dialect, for the frag bench's host (bench/frag/frag_host.cpp)
// in the tests: 3D.frag's camera model (Eye, Target, Up, FOV: the ray through screen point
// (x, y), x across the aspect, y in [-1, 1], is Dir + FOV (x Right + y UpOrtho)), the init()
// hook and PI. Written for fraktal from that model, not copied from FragM.
#camera 3D

// Guarded: fraktal's MathUtils stand-in, which the tests' frags may include first, defines it too.
#ifndef PI
#define PI 3.141592653589793
#endif

#vertex
varying vec2 coord;
varying vec3 from;
varying vec3 Dir;
varying vec3 UpOrtho;
varying vec3 Right;

#group Camera
// Field of view: the ray spread per unit of screen
uniform float FOV; slider[0,0.4,2.0] NotLockable
uniform vec3 Eye; slider[(-50,-50,-50),(0,0,-10),(50,50,50)] NotLockable
uniform vec3 Target; slider[(-50,-50,-50),(0,0,0),(50,50,50)] NotLockable
uniform vec3 Up; slider[(0,0,0),(0,1,0),(0,0,0)] NotLockable
uniform vec2 pixelSize;

void main(void) {
	gl_Position = gl_Vertex;
	coord = gl_Vertex.xy * vec2(pixelSize.y / pixelSize.x, 1.0) * FOV;
	from = Eye;
	Dir = normalize(Target - Eye);
	UpOrtho = normalize(Up - dot(Dir, Up) * Dir);
	Right = normalize(cross(Dir, UpOrtho));
}
#endvertex

varying vec2 coord;
varying vec3 from;
varying vec3 Dir;
varying vec3 UpOrtho;
varying vec3 Right;

#ifdef providesInit
void init();
#else
void init() {}
#endif

vec3 color(vec3 from, vec3 dir);

void main() {
	init();
	gl_FragColor = vec4(color(from, normalize(Dir + coord.x * Right + coord.y * UpOrtho)), 1.0);
}
