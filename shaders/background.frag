#version 330 core
// Vertical gradient (dark blue-grey below, lighter above) with a soft vignette.
in vec2 v_screen;

uniform vec3 u_top;
uniform vec3 u_bottom;

out vec4 frag_color;

// Tiny ordered-looking noise against 8-bit banding in video; deterministic per pixel.
float dither() {
  return fract(sin(dot(gl_FragCoord.xy, vec2(12.9898, 78.233))) * 43758.5453) - 0.5;
}

void main() {
  float t = smoothstep(0.0, 1.0, v_screen.y);
  vec3 color = mix(u_bottom, u_top, t);
  vec2 d = v_screen - vec2(0.5, 0.55);
  color *= 1.0 - 0.35 * dot(d, d);
  frag_color = vec4(color + dither() / 255.0, 1.0);
}
