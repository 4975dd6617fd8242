#version 450
// The exact sphere behind each square (perspective rays from the eye at the origin of
// view space), its depth, and its colour: a grey body under the frame's sky (hemisphere
// mix by the normal's elevation) and sun. Needs display_code.glsl's defines.
#include "display_code.glsl"

uniform mat4 proj;
uniform mat3 view_to_world;   // rotation part of the inverse view
uniform vec3 sun_dir;         // world
uniform vec3 sun_display;     // display value of the sun's irradiance on a facing white surface
uniform vec3 sky_display;     // of the sky's on a horizontal white surface
uniform float body_albedo;
uniform int srgb;

in vec3 view_pos;
flat in vec4 view_sphere;
out vec4 colour;

void main() {
  vec3 d = normalize(view_pos);
  vec3 c = view_sphere.xyz;
  float r = view_sphere.w;
  float b = dot(d, c), disc = b * b - dot(c, c) + r * r;
  if (disc < 0.0) discard;
  float t = b - sqrt(disc);
  if (t <= 0.0) discard;
  vec3 hit = t * d;
  vec4 clip = proj * vec4(hit, 1.0);
  gl_FragDepth = 0.5 * (clip.z / clip.w) + 0.5;
  vec3 n = view_to_world * ((hit - c) / r);
  vec3 v = body_albedo * (sky_display * (0.5 + 0.5 * n.z) + sun_display * max(dot(n, sun_dir), 0.0));
  colour = vec4(displayCode(v.r, srgb != 0), displayCode(v.g, srgb != 0), displayCode(v.b, srgb != 0), 255.0) / 255.0;
}
