// shaders/viewport_reproject.vert — reprojection (seed 4.2): one vertex per pixel of the previous
// frame, placed where that pixel's centre ray got to, drawn with the new view-projection as a
// grid of quads (core/viewport/reproject_pass.cpp builds the index buffer). The camera uniforms
// of viewport_common.glsl hold the PREVIOUS camera here. Erosion fix 1: the vertex takes the
// smallest distance of its 3x3 neighbourhood, so silhouettes do not erode.
layout(binding = 0) uniform sampler2D u_oldCentre;  // x: t, y: status
layout(binding = 1) uniform sampler2D u_oldImage;
uniform mat4 u_newClipFromWorld;

out vec3 v_start;    // start point (neighbourhood minimum)
out vec3 v_ownHit;   // the pixel's own point
out vec3 v_color;
out float v_hit;

void main() {
    ivec2 px = ivec2(gl_VertexID % u_size.x, gl_VertexID / u_size.x);
    vec4 own = texelFetch(u_oldCentre, px, 0);
    float tMin = own.x;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            tMin = min(tMin, texelFetch(u_oldCentre, clamp(px + ivec2(dx, dy), ivec2(0), u_size - 1), 0).x);
    vec3 rd = cameraRay(vec2(px) + 0.5);
    v_start = u_cameraPosition + rd * tMin;
    v_ownHit = u_cameraPosition + rd * own.x;
    v_color = texelFetch(u_oldImage, px, 0).rgb;
    v_hit = own.y == float(STATUS_HIT) ? 1.0 : 0.0;
    gl_Position = u_newClipFromWorld * vec4(v_start, 1.0);
}
