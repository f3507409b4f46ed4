#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulb variants that artists know from Mandelbulber2. All are spherical power maps
// v -> r^n S(n theta + theta_phase, n phi + phi_phase). As for the classic bulb
// (mandelbulb.hpp), the running derivative is the Jacobian's largest stretch: n r^(n-1) along r
// and theta, times the ratio of the image's to the source's circle of latitude along phi,
// |sin(n theta + phase)| / |sin(theta)| (for the sine bulb, whose theta is a latitude, the
// cosines), at least 1 and clamped to n. For the cosine bulb at integer n that is a bound
// everywhere (|sin(n theta)| <= n |sin(theta)|); a phase or the sine bulb's latitude sends a
// pole to a whole circle, so near the poles the clamp is an estimate and `fraktal check`
// measures the rest.

// The seed's bulb (mandelbulb.hpp) with phase offsets added to the multiplied angles.
struct MandelbulbPhase {
    static constexpr std::string_view id = "mandelbulb_phase";
    static constexpr std::string_view label = "Mandelbulb with phase";
    static constexpr std::string_view help =
        "Mandelbulb power with theta and phi phase offsets (degrees) added after the multiplication.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps where a phase sends a pole to a circle, and across the atan2 seam";
    static constexpr Degree degree{"power"};
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 32.0, "Exponent n."},
        ParamDecl{"theta_phase", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to n theta, degrees."},
        ParamDecl{"phi_phase", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to n phi, degrees."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        float theta = atan(length(p.xz), p.y) * power + radians(theta_phase);
        float phi = atan(p.x, p.z) * power + radians(phi_phase);
        float sinTheta = length(p.xz) / r, sinImage = abs(sin(theta));
        float phiStretch = sinImage < power * sinTheta ? max(1.0, sinImage / sinTheta) : power;
        p.w *= power * pow(r, power - 1.0) * phiStretch;
        p.xyz = pow(r, power) * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0), theta_phase = a.f(1), phi_phase = a.f(2);
        double r = length(p.xyz);
        if (r > 0.0) {
            double theta = std::atan2(std::hypot(p.xyz.x, p.xyz.z), p.xyz.y) * power + glm::radians(theta_phase);
            double phi = std::atan2(p.xyz.x, p.xyz.z) * power + glm::radians(phi_phase);
            double sinTheta = std::hypot(p.xyz.x, p.xyz.z) / r, sinImage = abs(sin(theta));
            double phiStretch = sinImage < power * sinTheta ? max(1.0, sinImage / sinTheta) : power;
            p.w *= power * std::pow(r, power - 1.0) * phiStretch;
            p.xyz = std::pow(r, power) * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
        } else {
            p.w = 0.0;
        }
    }
};

// "Sine" bulb: theta is the latitude asin(z / r) (computed as atan2(z, rxy)), phi = atan2(y, x);
// x = r^n cos(n theta) cos(n phi), y = r^n cos(n theta) sin(n phi), z = r^n sin(n theta).
// Mandelbulber2's "mandelbulb" formula, whose offsets (beta_angle_offset on theta,
// alpha_angle_offset on phi, degrees) are added to the angles before the power multiplies them.
// The largest stretch is n r^(n-1) times that of the phi direction, |cos(n (theta + beta))| /
// cos(theta) (the image's circle of latitude over the input's), where that is above 1.
struct MandelbulbSine {
    static constexpr std::string_view id = "mandelbulb_sine";
    static constexpr std::string_view label = "Mandelbulb (sine)";
    static constexpr std::string_view help = "Mandelbulb with latitude theta = asin(z/r): z = r^n sin(n theta).";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps where the poles go to circles (unless the power is odd and there is no offset)";
    static constexpr Degree degree{"power"};
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 32.0, "Exponent n."},
        ParamDecl{"theta_offset",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -180.0,
                  180.0,
                  "Added to the latitude theta before the power multiplies it, degrees."},
        ParamDecl{"phi_offset",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -180.0,
                  180.0,
                  "Added to the azimuth phi before the power multiplies it, degrees."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        float theta = (atan(p.z, length(p.xy)) + radians(theta_offset)) * power;
        float phi = (atan(p.y, p.x) + radians(phi_offset)) * power;
        float cosTheta = length(p.xy) / r, cosImage = abs(cos(theta));
        float phiStretch = cosImage < power * cosTheta ? max(1.0, cosImage / cosTheta) : power;
        p.w *= power * pow(r, power - 1.0) * phiStretch;
        p.xyz = pow(r, power) * vec3(cos(theta) * cos(phi), cos(theta) * sin(phi), sin(theta));
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0);
        double r = length(p.xyz);
        if (r > 0.0) {
            double theta = (std::atan2(p.xyz.z, std::hypot(p.xyz.x, p.xyz.y)) + glm::radians(a.f(1))) * power;
            double phi = (std::atan2(p.xyz.y, p.xyz.x) + glm::radians(a.f(2))) * power;
            double cosTheta = std::hypot(p.xyz.x, p.xyz.y) / r, cosImage = abs(cos(theta));
            double phiStretch = cosImage < power * cosTheta ? max(1.0, cosImage / cosTheta) : power;
            p.w *= power * std::pow(r, power - 1.0) * phiStretch;
            p.xyz = std::pow(r, power) * vec3(cos(theta) * cos(phi), cos(theta) * sin(phi), sin(theta));
        } else {
            p.w = 0.0;
        }
    }
};

// "Cosine" bulb: theta is the polar angle acos(z / r) (computed as atan2(rxy, z)),
// phi = atan2(y, x); x = r^n sin(n theta) cos(n phi), y = r^n sin(n theta) sin(n phi),
// z = r^n cos(n theta): the White/Nylander bulb with z as its pole.
struct MandelbulbCosine {
    static constexpr std::string_view id = "mandelbulb_cosine";
    static constexpr std::string_view label = "Mandelbulb (cosine)";
    static constexpr std::string_view help = "Mandelbulb with polar theta = acos(z/r): z = r^n cos(n theta).";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{"power"};
    static DerivativeBound derivativeFor(Args a) { return sphericalPowerBound(a.f(0)); }
    static constexpr std::string_view jump = kNonIntegerPowerSeam;
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 32.0, "Exponent n."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        float theta = atan(length(p.xy), p.z) * power;
        float phi = atan(p.y, p.x) * power;
        float sinTheta = length(p.xy) / r, sinImage = abs(sin(theta));
        float phiStretch = sinImage < power * sinTheta ? max(1.0, sinImage / sinTheta) : power;
        p.w *= power * pow(r, power - 1.0) * phiStretch;
        p.xyz = pow(r, power) * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0);
        double r = length(p.xyz);
        if (r > 0.0) {
            double theta = std::atan2(std::hypot(p.xyz.x, p.xyz.y), p.xyz.z) * power;
            double phi = std::atan2(p.xyz.y, p.xyz.x) * power;
            double sinTheta = std::hypot(p.xyz.x, p.xyz.y) / r, sinImage = abs(sin(theta));
            double phiStretch = sinImage < power * sinTheta ? max(1.0, sinImage / sinTheta) : power;
            p.w *= power * std::pow(r, power - 1.0) * phiStretch;
            p.xyz = std::pow(r, power) * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
        } else {
            p.w = 0.0;
        }
    }
};

// Bristorbrot (Doug Bristor; Mandelbulber2 bristorbrot): a quadratic, Riemann-type power
// x' = x^2 - y^2 - z^2, y' = y (2x - t z), z' = z (2x + t y). The running derivative is its
// Jacobian's largest singular value, the square root of the largest eigenvalue of J^T J (a
// symmetric 3x3: the closed form of O. K. Smith, "Eigenvalues of a symmetric 3 x 3 matrix",
// CACM 4(4), 1961). Mandelbulber's degree-2 rule dr -> 2 r dr is that value on the x axis only;
// off it the estimate overshot 4-6x at the surface.
struct Bristorbrot {
    static constexpr std::string_view id = "bristorbrot";
    static constexpr std::string_view label = "Bristorbrot";
    static constexpr std::string_view help = "Quadratic hypercomplex power: (x^2 - y^2 - z^2, y (2x - z), z (2x + y)).";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"twist",
                  ParamType::Float,
                  {1.0, 0.0, 0.0},
                  -2.0,
                  2.0,
                  "Weight of the cross terms -z and +y (1: Bristor's)."},
    };

    static constexpr std::string_view glsl = R"(
    mat3 J = mat3(2.0 * p.xyz, vec3(-2.0 * p.y, 2.0 * p.x - twist * p.z, twist * p.z),
                  vec3(-2.0 * p.z, -twist * p.y, 2.0 * p.x + twist * p.y));
    mat3 M = transpose(J) * J;
    float q = (M[0][0] + M[1][1] + M[2][2]) / 3.0;
    float off = M[1][0] * M[1][0] + M[2][0] * M[2][0] + M[2][1] * M[2][1];
    vec3 diagonal = vec3(M[0][0], M[1][1], M[2][2]) - q;
    float spread = sqrt((dot(diagonal, diagonal) + 2.0 * off) / 6.0);
    float half_det = spread > 0.0 ? determinant((M - mat3(q)) / spread) * 0.5 : 0.0;
    float largest = q + 2.0 * spread * cos(acos(clamp(half_det, -1.0, 1.0)) / 3.0);
    p.w *= sqrt(max(largest, 0.0));
    p.xyz = vec3(p.x * p.x - p.y * p.y - p.z * p.z, p.y * (2.0 * p.x - twist * p.z), p.z * (2.0 * p.x + twist * p.y));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double twist = a.f(0);
        const vec3 v = p.xyz;
        glm::dmat3 J(2.0 * v, vec3(-2.0 * v.y, 2.0 * v.x - twist * v.z, twist * v.z),
                     vec3(-2.0 * v.z, -twist * v.y, 2.0 * v.x + twist * v.y));
        glm::dmat3 M = glm::transpose(J) * J;
        double q = (M[0][0] + M[1][1] + M[2][2]) / 3.0;
        double off = M[1][0] * M[1][0] + M[2][0] * M[2][0] + M[2][1] * M[2][1];
        const vec3 diagonal = vec3(M[0][0], M[1][1], M[2][2]) - q;
        double spread = std::sqrt((dot(diagonal, diagonal) + 2.0 * off) / 6.0);
        double half_det = spread > 0.0 ? glm::determinant((M - glm::dmat3(q)) / spread) * 0.5 : 0.0;
        double largest = q + 2.0 * spread * std::cos(std::acos(clamp(half_det, -1.0, 1.0)) / 3.0);
        p.w *= std::sqrt(max(largest, 0.0));
        p.xyz =
            vec3(v.x * v.x - v.y * v.y - v.z * v.z, v.y * (2.0 * v.x - twist * v.z), v.z * (2.0 * v.x + twist * v.y));
    }
};

// Buddhi's Mandelbulb 4 (Mandelbulber2's mandelbulb4): the point turned about z by (n - 1) times
// its azimuth atan2(y, x) plus alpha, then about y by (n - 1) times atan2(z, x) plus beta, then
// about x by (n - 1) times atan2(z, y) plus gamma (Mandelbulber2's CRotationMatrix RotateX, RotateY,
// RotateZ in that order, which turns the vector about z first), and scaled by r^(n - 1). The
// running derivative is Mandelbulber2's n r^(n - 1). atan2(0, 0) is 0, as in C.
struct Mandelbulb4 {
    static constexpr std::string_view id = "mandelbulb4";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Mandelbulb 4";
    static constexpr std::string_view help =
        "Buddhi's bulb: the point turned about z, y and x by (n - 1) times its angle in each plane, scaled by "
        "r^(n - 1).";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps across the atan2 seams when the power is not a whole number, and where a plane's pair "
        "passes through 0";
    static constexpr Degree degree{"power"};
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 32.0, "Exponent n."},
        ParamDecl{"alpha", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to the xy angle, degrees."},
        ParamDecl{"beta", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to the xz angle, degrees."},
        ParamDecl{"gamma", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to the yz angle, degrees."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    float rp = pow(r, power - 1.0);
    p.w *= power * rp;
    vec3 v = p.xyz;
    float turnZ = ((v.x == 0.0 && v.y == 0.0) ? 0.0 : atan(v.y, v.x)) + radians(alpha);
    float turnY = ((v.x == 0.0 && v.z == 0.0) ? 0.0 : atan(v.z, v.x)) + radians(beta);
    float turnX = ((v.y == 0.0 && v.z == 0.0) ? 0.0 : atan(v.z, v.y)) + radians(gamma);
    vec3 angle = vec3(turnX, turnY, turnZ) * (power - 1.0);
    vec3 cs = cos(angle), sn = sin(angle);
    v.xy = vec2(cs.z * v.x - sn.z * v.y, sn.z * v.x + cs.z * v.y);
    v.xz = vec2(cs.y * v.x + sn.y * v.z, -sn.y * v.x + cs.y * v.z);
    v.yz = vec2(cs.x * v.y - sn.x * v.z, sn.x * v.y + cs.x * v.z);
    p.xyz = v * rp;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0), alpha = a.f(1), beta = a.f(2), gamma = a.f(3);
        const double r = length(p.xyz), rp = std::pow(r, power - 1.0);
        p.w *= power * rp;
        vec3 v = p.xyz;
        const vec3 angle = vec3(std::atan2(v.z, v.y) + glm::radians(gamma), std::atan2(v.z, v.x) + glm::radians(beta),
                                std::atan2(v.y, v.x) + glm::radians(alpha)) *
                           (power - 1.0);
        const vec3 cs = glm::cos(angle), sn = glm::sin(angle);
        v = vec3(cs.z * v.x - sn.z * v.y, sn.z * v.x + cs.z * v.y, v.z);
        v = vec3(cs.y * v.x + sn.y * v.z, v.y, -sn.y * v.x + cs.y * v.z);
        v = vec3(v.x, cs.x * v.y - sn.x * v.z, sn.x * v.y + cs.x * v.z);
        p.xyz = v * rp;
    }
};

}  // namespace fraktal::blocks
