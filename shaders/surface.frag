#version 330 core
// The book's lighting (book.frag: the same lights, Blinn-Phong, linear colour, sRGB out) with
// a colour per triangle instead of a texture. Keep the lights in step with book.frag.
in vec3 v_position;
in vec3 v_normal;

uniform samplerBuffer u_face_colours;  // linear RGB per triangle (gl_PrimitiveID)
uniform samplerBuffer u_face_normals;  // world, unit per triangle; (0, 0, 0) if degenerate
uniform mat4 u_view;
uniform bool u_smooth;      // interpolated vertex normals instead of the face's
uniform float u_specular;   // specular strength
uniform float u_shininess;  // Blinn-Phong exponent

out vec4 frag_color;

const vec3 key_direction = normalize(vec3(-0.45, 0.65, 0.75));  // toward the light, view space
const vec3 key_color = vec3(1.00, 0.96, 0.90) * 0.95;
const vec3 fill_direction = normalize(vec3(0.80, -0.15, 0.55));
const vec3 fill_color = vec3(0.70, 0.80, 1.00) * 0.38;
const vec3 rim_direction = normalize(vec3(0.20, 0.60, -0.80));
const vec3 rim_color = vec3(0.80, 0.85, 1.00) * 0.35;
const vec3 ambient = vec3(0.16, 0.17, 0.20);

vec3 to_srgb(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }

vec3 light(vec3 albedo, vec3 n, vec3 v, vec3 l, vec3 color, float specular) {
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float highlight = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), u_shininess) : 0.0;
  return color * (albedo * diffuse + vec3(specular * highlight));
}

void main() {
  vec3 albedo = texelFetch(u_face_colours, gl_PrimitiveID).rgb;
  vec3 v = normalize(-v_position);
  vec3 face = mat3(u_view) * texelFetch(u_face_normals, gl_PrimitiveID).xyz;
  // A degenerate triangle has no normal of its own: light it as if it faced the viewer.
  vec3 face_n = dot(face, face) > 0.0 ? normalize(face) : v;
  vec3 n = face_n;
  if (u_smooth && dot(v_normal, v_normal) > 0.0) n = normalize(v_normal);
  // A face seen from behind (an exploded lattice, an open shell) is lit as seen; the face,
  // not the interpolated normal, decides which side is seen.
  if (dot(face_n, v) < 0.0) n = -n;
  vec3 color = ambient * albedo;
  color += light(albedo, n, v, key_direction, key_color, u_specular);
  color += light(albedo, n, v, fill_direction, fill_color, 0.3 * u_specular);
  color += light(albedo, n, v, rim_direction, rim_color, 0.0);
  frag_color = vec4(to_srgb(color), 1.0);
}
