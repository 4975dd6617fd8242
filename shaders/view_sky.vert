#version 450
// A full-screen triangle at the far plane, with the view ray through each corner. On a
// plane of constant depth a perspective camera's unprojected points are affine in NDC, so
// the ray interpolated across the triangle is each fragment's own (up to length).
uniform mat4 inverse_view_proj;
out vec3 ray;
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1));
  vec4 near = inverse_view_proj * vec4(p, -1.0, 1.0), far = inverse_view_proj * vec4(p, 1.0, 1.0);
  ray = far.xyz / far.w - near.xyz / near.w;
  gl_Position = vec4(p, 1.0, 1.0);
}
