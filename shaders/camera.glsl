// shaders/camera.glsl — the camera's projections (Camera::Projection, core/camera.hpp, whose
// rayDirection is the CPU mirror). Every projection maps normalised device coordinates (x right,
// y up, -1..1 across the image) to a ray direction in the camera's frame:
//   perspective      the pinhole: (ndcX tan(fovY/2) aspect, ndcY tan(fovY/2), forward);
//   fisheye          equidistant: the angle from the view axis grows with the distance from the
//                    centre, fovY/2 at the top edge (Mandelbulber2's fish eye);
//   equirectangular  longitude ndcX fovY and latitude ndcY fovY/2, whatever the image's aspect:
//                    at 180 degrees the image is the whole sphere (Mandelbulber2's equirectangular,
//                    a 360 panorama; its pixels are square in angle in a 2:1 image).
// A pixel's footprint is fovY / height radians for the last two, or 2 fovY / width across an
// equirectangular image narrower than 2:1 (Camera::pixelAngle).
const int PROJECTION_PERSPECTIVE = 0, PROJECTION_FISHEYE = 1, PROJECTION_EQUIRECTANGULAR = 2;
uniform int u_projection;
uniform float u_halfFovY;  // half the vertical field of view, radians

// A pixel's footprint per unit distance (Camera::pixelAngle).
float projectionPixelAngle(float tanHalfFovY, float halfFovY, int projection, ivec2 size) {
    if (projection == PROJECTION_PERSPECTIVE) return 2.0 * tanHalfFovY / float(size.y);
    float angle = 2.0 * halfFovY / float(size.y);
    return projection == PROJECTION_EQUIRECTANGULAR ? max(angle, 4.0 * halfFovY / float(size.x)) : angle;
}

vec3 projectionRay(float ndcX, float ndcY, float aspect, vec3 right, vec3 up, vec3 forward, float tanHalfFovY,
                   float halfFovY, int projection) {
    if (projection == PROJECTION_FISHEYE) {
        vec2 v = vec2(ndcX * aspect, ndcY);
        float r = length(v), theta = r * halfFovY;
        vec2 across = r > 0.0 ? v / r * sin(theta) : vec2(0.0);
        return normalize(forward * cos(theta) + right * across.x + up * across.y);
    }
    if (projection == PROJECTION_EQUIRECTANGULAR) {
        float longitude = ndcX * 2.0 * halfFovY, latitude = ndcY * halfFovY;
        return normalize((forward * cos(longitude) + right * sin(longitude)) * cos(latitude) + up * sin(latitude));
    }
    return normalize(forward + right * (ndcX * tanHalfFovY * aspect) + up * (ndcY * tanHalfFovY));
}

// The inverse: the device coordinates of the direction v (a point less the camera's position).
// False where the projection shows no such direction (behind a pinhole).
bool projectDirection(vec3 v, vec3 right, vec3 up, vec3 forward, float tanHalfFovY, float halfFovY, int projection,
                      float aspect, out vec2 ndc) {
    float x = dot(v, right), y = dot(v, up), z = dot(v, forward);
    ndc = vec2(-2.0);
    if (projection == PROJECTION_FISHEYE) {
        float across = length(vec2(x, y)), r = atan(across, z) / halfFovY;
        vec2 at = across > 0.0 ? vec2(x, y) / across * r : vec2(0.0);
        ndc = vec2(at.x / aspect, at.y);
        return true;
    }
    if (projection == PROJECTION_EQUIRECTANGULAR) {
        ndc = vec2(atan(x, z) / (2.0 * halfFovY), atan(y, length(vec2(x, z))) / halfFovY);
        return true;
    }
    if (z <= 0.0) return false;
    ndc = vec2(x / (z * tanHalfFovY * aspect), y / (z * tanHalfFovY));
    return true;
}
