#version 330 core
// Simple headlight shading, enough to show the markers' round shape.
in vec3 v_normal;
in vec3 v_color;

out vec4 frag_color;

void main() {
  vec3 n = normalize(v_normal);
  float facing = abs(n.z);  // view space: +z points at the camera
  float upper = max(dot(n, normalize(vec3(-0.4, 0.7, 0.6))), 0.0);
  frag_color = vec4(v_color * (0.45 + 0.4 * facing + 0.25 * upper), 1.0);
}
