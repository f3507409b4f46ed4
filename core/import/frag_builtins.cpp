#include "core/import/frag_builtins.hpp"

#include <array>

namespace fraktal::frag {

namespace {

// Guarded, so that a frag that defines them itself first keeps its own.
constexpr const char* kConstants = R"(#ifndef PI
#define PI 3.14159265358979
#endif
#ifndef TWO_PI
#define TWO_PI 6.28318530717959
#endif
)";

// A raytracer's part that a DE sees: the constants and the orbit trap the DE lowers (FragM's
// raytracers declare it and start it at 10000 for every DE call; fraktal's shader does the
// same and reads it as the orbit colouring's trap).
constexpr const char* kRaytracerStandIn = R"(#ifndef ORBIT_TRAP_DECLARED
#define ORBIT_TRAP_DECLARED
vec4 orbitTrap = vec4(10000.0);
#endif
)";

// MathUtils.frag's functions, by what they compute. Angles are in degrees, as FragM's sliders
// give them. FragM's rotation matrices turn a vector by -angle about the axis when multiplied
// as M * v (their rows are written where GLSL expects columns); frags are tuned to that, so these
// keep it: M = cos I + (1 - cos) v v^T - sin [v]x, where [v]x x = cross(v, x).
constexpr const char* kMathUtils = R"(mat3 rotationMatrix3(vec3 v, float angle) {
    float c = cos(radians(angle));
    float s = sin(radians(angle));
    mat3 cross = mat3(0.0, v.z, -v.y, -v.z, 0.0, v.x, v.y, -v.x, 0.0);
    return c * mat3(1.0) + (1.0 - c) * outerProduct(v, v) - s * cross;
}

// Turns about x by v.x, then y by v.y, then z by v.z degrees (each as rotationMatrix3).
mat3 rotationMatrixXYZ(vec3 v) {
    return rotationMatrix3(vec3(1.0, 0.0, 0.0), v.x) * rotationMatrix3(vec3(0.0, 1.0, 0.0), v.y) *
           rotationMatrix3(vec3(0.0, 0.0, 1.0), v.z);
}

// The same turn in homogeneous coordinates.
mat4 rotationMatrix(vec3 v, float angle) {
    return mat4(rotationMatrix3(v, angle));
}

mat4 translate(vec3 v) {
    mat4 m = mat4(1.0);
    m[3] = vec4(v, 1.0);
    return m;
}

mat4 scale4(float s) {
    return mat4(vec4(s, 0.0, 0.0, 0.0), vec4(0.0, s, 0.0, 0.0), vec4(0.0, 0.0, s, 0.0), vec4(0.0, 0.0, 0.0, 1.0));
}

// A hash of a 2D point into [0, 1).
float rand(vec2 co) {
    return fract(sin(dot(co, vec2(12.9898, 78.233))) * 43758.5453);
}
)";

// Complex.frag: complex numbers as vec2 (x real, y imaginary).
constexpr const char* kComplex = R"(vec2 cMul(vec2 a, vec2 b) {
    return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

vec2 cConj(vec2 z) {
    return vec2(z.x, -z.y);
}

vec2 cDiv(vec2 a, vec2 b) {
    return cMul(a, cConj(b)) / dot(b, b);
}

vec2 cSqr(vec2 z) {
    return vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y);
}

vec2 cExp(vec2 z) {
    return exp(z.x) * vec2(cos(z.y), sin(z.y));
}

vec2 cLog(vec2 z) {
    return vec2(log(length(z)), atan(z.y, z.x));
}

// z to a real power, on the principal branch.
vec2 cPower(vec2 z, float n) {
    float r = length(z);
    float a = atan(z.y, z.x);
    return pow(r, n) * vec2(cos(n * a), sin(n * a));
}

vec2 cSqrt(vec2 z) {
    return cPower(z, 0.5);
}
)";

// The include names of FragM's renderers and camera: fraktal renders, so they reduce to the
// stand-in.
constexpr std::array kRaytracers = {"3D.frag",
                                    "3DKn-1.0.5.frag",
                                    "DE-Raytracer.frag",
                                    "DE-Raytracer-v0.9.1.frag",
                                    "DE-Raytracer-v0.9.10.frag",
                                    "DE-Raytracer-Slicer.frag",
                                    "DE-Kn2.frag",
                                    "DE-Kn2cr11.frag",
                                    "DE-Kn8.frag",
                                    "Fast-Raytracer.frag",
                                    "Soft-Raytracer.frag",
                                    "Sky-Pathtracer.frag",
                                    "Path-Raytracer.frag",
                                    "Subblue-Raytracer.frag",
                                    "IBL-Raytracer.frag",
                                    "IBL-Pathtracer.frag",
                                    "BufferShader.frag",
                                    "Fast-Raytracer-with-Textures.frag",
                                    "Brute-Raytracer.frag",
                                    "Brute3D.frag"};

}  // namespace

const std::map<std::string, std::string, std::less<>>& builtinIncludes() {
    static const std::map<std::string, std::string, std::less<>> includes = [] {
        std::map<std::string, std::string, std::less<>> m;
        m["MathUtils.frag"] = std::string(kConstants) + kMathUtils;
        m["Complex.frag"] = kComplex;
        for (const char* name : kRaytracers) m[name] = std::string(kConstants) + kRaytracerStandIn;
        return m;
    }();
    return includes;
}

bool isRaytracerInclude(std::string_view name) {
    for (const char* known : kRaytracers)
        if (name == known) return true;
    return name.find("Raytracer") != std::string_view::npos || name.find("Pathtracer") != std::string_view::npos ||
           name.starts_with("DE-Kn") || name.starts_with("3D") || name.starts_with("Brute") ||
           name.starts_with("BufferShader");
}

}  // namespace fraktal::frag
