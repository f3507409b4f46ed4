#donotrun
// fraktal's test stand-in for FragM's 3D.frag: a camera in a vertex section, the
// init() hook and PI. Written for fraktal's tests; it only needs to parse.
#buffer RGBA32F
#buffershader "BufferShader.frag"
#info Test 3D setup
#camera 3D

#define PI  3.141592653589793

#vertex
varying vec3 from;
varying vec3 dir;

#group Camera
// Field of view: the ray spread per unit of screen
uniform float FOV; slider[0,0.4,2.0] NotLockable
uniform vec3 Eye; slider[(-50,-50,-50),(0,0,-10),(50,50,50)] NotLockable
uniform vec3 Target; slider[(-50,-50,-50),(0,0,0),(50,50,50)] NotLockable
uniform vec3 Up; slider[(0,0,0),(0,1,0),(0,0,0)] NotLockable

#ifdef providesInit
void init();
#else
void init() {}
#endif

void main(void) {
	gl_Position = gl_Vertex;
	from = Eye;
	dir = normalize(Target - Eye);
	init();
}
#endvertex

varying vec3 from;
varying vec3 dir;
uniform vec2 pixelSize;

#ifdef providesInit
void init();
#else
void init() {}
#endif

vec3 color(vec3 from, vec3 dir);

void main() {
	init();
	gl_FragColor = vec4(color(from, dir), 1.0);
}
