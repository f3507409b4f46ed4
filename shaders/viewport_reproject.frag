// shaders/viewport_reproject.frag — writes the reprojected distances along the NEW camera's rays;
// the depth test keeps the nearest surface where quads overlap. Needs viewport_common.glsl only
// for the layout; u_newCameraPosition is the new camera.
in vec3 v_start;
in vec3 v_ownHit;
in vec3 v_color;
in float v_hit;
uniform vec3 u_newCameraPosition;
layout(location = 0) out vec4 o_distance;  // t, hit weight, t of the carried hit
layout(location = 1) out vec4 o_color;

void main() {
    o_distance = vec4(length(v_start - u_newCameraPosition), v_hit, length(v_ownHit - u_newCameraPosition), 1.0);
    o_color = vec4(v_color, 1.0);
}
