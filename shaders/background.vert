#version 330 core
// One triangle covering the whole screen, from gl_VertexID alone (no vertex buffer).
out vec2 v_screen;  // 0..1, (0, 0) at the bottom left

void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  v_screen = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
}
