#version 330 core
// Blinn-Phong with a key light, a fill light, a rim light and ambient, all fixed relative
// to the camera so whatever face is turned towards the viewer is lit. Lighting is done in
// linear colour and converted back to sRGB for the 8-bit output.
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;

uniform sampler2D u_texture;
uniform float u_specular;   // specular strength: cloth covers > paper
uniform float u_shininess;  // Blinn-Phong exponent

out vec4 frag_color;

const vec3 key_direction = normalize(vec3(-0.45, 0.65, 0.75));  // toward the light, view space
const vec3 key_color = vec3(1.00, 0.96, 0.90) * 0.95;
const vec3 fill_direction = normalize(vec3(0.80, -0.15, 0.55));
const vec3 fill_color = vec3(0.70, 0.80, 1.00) * 0.38;
const vec3 rim_direction = normalize(vec3(0.20, 0.60, -0.80));
const vec3 rim_color = vec3(0.80, 0.85, 1.00) * 0.35;
const vec3 ambient = vec3(0.16, 0.17, 0.20);

vec3 to_linear(vec3 c) { return pow(c, vec3(2.2)); }
vec3 to_srgb(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }

vec3 light(vec3 albedo, vec3 n, vec3 v, vec3 l, vec3 color, float specular) {
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float highlight = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), u_shininess) : 0.0;
  return color * (albedo * diffuse + vec3(specular * highlight));
}

void main() {
  vec3 albedo = to_linear(texture(u_texture, v_uv).rgb);
  vec3 n = normalize(v_normal);
  vec3 v = normalize(-v_position);
  // An exploded book can show a face from behind; light it as seen.
  if (dot(n, v) < 0.0) n = -n;
  vec3 color = ambient * albedo;
  color += light(albedo, n, v, key_direction, key_color, u_specular);
  color += light(albedo, n, v, fill_direction, fill_color, 0.3 * u_specular);
  color += light(albedo, n, v, rim_direction, rim_color, 0.0);
  frag_color = vec4(to_srgb(color), 1.0);
}
