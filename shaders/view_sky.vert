#version 450
// A full-screen triangle at the far plane; the fragment stage finds its view direction.
out vec2 ndc;
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1));
  ndc = p;
  gl_Position = vec4(p, 1.0, 1.0);
}
