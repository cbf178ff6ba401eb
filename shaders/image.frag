// An ImageView's pixels: the image under the pan/zoom transform (engine/gpu/view.h),
// sampled with the sampler the draw chose (trilinear, or nearest when magnified), in
// linear light (an _SRGB image); beyond the image's edges, the background.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shader_interface.h"

layout(constant_id = PW_SPEC_ENCODE_SRGB) const bool kEncodeSrgb = false;

layout(set = PW_SET_IMAGE, binding = PW_BINDING_IMAGE) uniform sampler2D image;
layout(push_constant) uniform PushBlock { ImagePushConstants view; };

layout(location = 0) out vec4 outColor;

vec3 encodeSrgb(const vec3 linear) {
  const vec3 c = clamp(linear, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
  // gl_FragCoord.xy is the pixel's centre in frame pixels (i + 0.5, j + 0.5).
  const vec2 imagePoint = (gl_FragCoord.xy - view.transform.zw) / view.transform.xy;
  const vec2 size = view.imageSize.xy;
  // Image pixel i covers [i - 0.5, i + 0.5); texture coordinates put its centre at (i + 0.5) / size.
  const vec2 uv = (imagePoint + 0.5) / size;
  // Sampled everywhere, chosen after: derivatives stay defined, and lavapipe would
  // run both sides of a branch anyway.
  const vec4 texel = texture(image, uv);
  const bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0)));
  vec4 color = inside ? texel : view.background;
  if (kEncodeSrgb) color.rgb = encodeSrgb(color.rgb);
  outColor = color;
}
