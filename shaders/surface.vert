#version 330 core
// A surface (any body, a deformed lattice): world positions streamed every frame, indexed by
// triangles uploaded once; per-vertex normals only when it is drawn smooth.
layout(location = 0) in vec3 a_position;  // world
layout(location = 1) in vec3 a_normal;    // world, unit (smooth); unused when flat

uniform mat4 u_view;        // world -> view (rigid)
uniform mat4 u_projection;  // view -> clip

out vec3 v_position;  // view space
out vec3 v_normal;    // view space

void main() {
  vec4 view_position = u_view * vec4(a_position, 1.0);
  v_position = view_position.xyz;
  v_normal = mat3(u_view) * a_normal;  // the view matrix is a rotation + translation
  gl_Position = u_projection * view_position;
}
