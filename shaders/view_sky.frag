#version 450
// The sky behind the terrain: the frame's sky model baked into an equirectangular map of
// display values (view/sky_draw.cpp: radiance in the terrain's display units), the sun
// disc on top; below the horizon (past the DEM's edge) the horizon's own haze, so the
// field's edge fades into it; tone-mapped as the terrain is.
#include "display_code.glsl"

layout(binding = 1) uniform sampler2D sky_map;  // rgb32f; u: azimuth from north / 2 pi, v: elevation 0 .. pi/2
uniform mat4 inverse_view_proj;
uniform vec3 sun_dir;        // toward the sun (east, north, up)
uniform float sun_cos_radius;  // cos of the drawn disc's angular radius
uniform vec3 sun_display;    // the disc's display value
uniform int srgb;

in vec2 ndc;
out vec4 colour;

const float kPi = 3.14159265358979;

void main() {
  vec4 near = inverse_view_proj * vec4(ndc, -1.0, 1.0), far = inverse_view_proj * vec4(ndc, 1.0, 1.0);
  vec3 dir = normalize(far.xyz / far.w - near.xyz / near.w);
  float azimuth = atan(dir.x, dir.y);  // from north, clockwise
  float u = fract(azimuth / (2.0 * kPi) + 1.0);
  float e = asin(clamp(dir.z, 0.0, 1.0)) / (0.5 * kPi);
  vec3 v = texture(sky_map, vec2(u, e)).rgb;
  if (dir.z > 0.0 && dot(dir, sun_dir) >= sun_cos_radius) v = sun_display;
  colour = vec4(displayCode(v.r, srgb != 0), displayCode(v.g, srgb != 0), displayCode(v.b, srgb != 0), 255.0) / 255.0;
}
