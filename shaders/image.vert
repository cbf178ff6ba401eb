// An ImageView: one triangle that covers the viewport (the view's rectangle); the
// fragment shader finds each pixel's place in the image from gl_FragCoord.
#version 450

void main() {
  // (-1,-1), (3,-1), (-1,3): the clip square [-1,1]^2 lies inside.
  const vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
