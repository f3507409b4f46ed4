// One triangle that covers the viewport (no vertex buffer: positions from gl_VertexID). Draw with
// glDrawArrays(GL_TRIANGLES, 0, 3) and an empty vertex array object.
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
