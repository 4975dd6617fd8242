#version 450
// A trail's colour, cut at the playback time inside the segment that crosses it (the
// time is interpolated along the segment with perspective, like its position).
uniform float drawn_until;  // seconds after the trail's first fix

in float time_s;
in vec3 display;
out vec4 colour;

void main() {
  if (time_s > drawn_until) discard;
  colour = vec4(display, 1.0);
}
