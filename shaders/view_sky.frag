#version 450
// The sky behind the terrain: the frame's sky model baked into an equirectangular map of
// 8-bit display codes (view/sky_draw.cpp: radiance in the terrain's display units, coded
// with the terrain's tone curve), the sun disc on top; below the horizon (past the DEM's
// edge) the horizon's own haze, so the field's edge fades into it.

layout(binding = 1) uniform sampler2D sky_map;  // rgba8; u: azimuth from north / 2 pi, v: elevation 0 .. pi/2
uniform vec3 sun_dir;          // toward the sun (east, north, up)
uniform float sun_cos_radius;  // cos of the drawn disc's angular radius
uniform vec3 sun_code;         // the disc's display code / 255

in vec3 ray;
out vec4 colour;

const float kPi = 3.14159265358979;

void main() {
  vec3 dir = normalize(ray);
  float azimuth = atan(dir.x, dir.y);  // from north, clockwise
  float u = fract(azimuth / (2.0 * kPi) + 1.0);
  float e = asin(clamp(dir.z, 0.0, 1.0)) / (0.5 * kPi);
  vec3 v = texture(sky_map, vec2(u, e)).rgb;
  if (dir.z > 0.0 && dot(dir, sun_dir) >= sun_cos_radius) v = sun_code;
  colour = vec4(v, 1.0);
}
