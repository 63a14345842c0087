#version 330 core
// The book: world-space triangles built on the CPU from the 8 corners every frame.
layout(location = 0) in vec3 a_position;  // world
layout(location = 1) in vec3 a_normal;    // world, unit, outward face normal
layout(location = 2) in vec2 a_uv;        // v = 0 at the image's top row

uniform mat4 u_view;        // world -> view (rigid)
uniform mat4 u_projection;  // view -> clip

out vec3 v_position;  // view space
out vec3 v_normal;    // view space
out vec2 v_uv;

void main() {
  vec4 view_position = u_view * vec4(a_position, 1.0);
  v_position = view_position.xyz;
  v_normal = mat3(u_view) * a_normal;  // the view matrix is a rotation + translation
  v_uv = a_uv;
  gl_Position = u_projection * view_position;
}
