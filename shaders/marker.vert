#version 330 core
// Markers (angular-momentum arrow, body axes): world-space solids with a colour each.
layout(location = 0) in vec3 a_position;  // world
layout(location = 1) in vec3 a_normal;    // world
layout(location = 2) in vec3 a_color;     // sRGB

uniform mat4 u_view;
uniform mat4 u_projection;

out vec3 v_normal;  // view space
out vec3 v_color;

void main() {
  v_normal = mat3(u_view) * a_normal;
  v_color = a_color;
  gl_Position = u_projection * u_view * vec4(a_position, 1.0);
}
