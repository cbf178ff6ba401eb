// Per-pixel VRML97 lighting (ISO/IEC 14772-1, 4.14.4), in linear light:
//   I = OE + SUM_i( on_i * attenuation_i * spot_i * IL_i * (ambient_i + diffuse_i + specular_i) )
//   attenuation_i = 1 / max(a0 + a1 d + a2 d^2, 1)   (1 for directional lights)
//   ambient_i  = Ia_i * OD * Oa
//   diffuse_i  = I_i * OD * (N . L)
//   specular_i = I_i * OS * (N . normalize(L + V))^(shininess * 128)
// with OD the diffuse colour replaced by the per-vertex colour or the texture (4.14.3,
// table 4.5), and no fog. Shapes without a Material are unlit (6.5): the colour as is.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shader_interface.h"

layout(constant_id = PW_SPEC_TEXTURED) const bool kTextured = false;
layout(constant_id = PW_SPEC_LIT) const bool kLit = true;
layout(constant_id = PW_SPEC_ENCODE_SRGB) const bool kEncodeSrgb = false;
layout(constant_id = PW_SPEC_PHOTO_TEXTURE) const bool kPhotoTexture = false;

layout(std140, set = PW_SET_FRAME, binding = PW_BINDING_FRAME_UNIFORMS) uniform FrameBlock { FrameUniforms frame; };
layout(std430, set = PW_SET_SCENE, binding = PW_BINDING_LIGHTS) readonly buffer LightBlock { LightGpu lights[]; };
layout(set = PW_SET_TEXTURE, binding = PW_BINDING_TEXTURE) uniform sampler2D shapeTexture;
layout(push_constant) uniform PushBlock { DrawPushConstants draw; };

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inWorldNormal;
layout(location = 2) in vec2 inTexCoord;
layout(location = 3) in vec4 inColor;
layout(location = 4) in vec3 inPhoto;

layout(location = 0) out vec4 outColor;

// ambient_i + diffuse_i + specular_i for a unit vector L towards the light, times IL_i.
vec3 lightSum(const vec3 color, const float intensity, const float ambientIntensity, const vec3 L, const vec3 N,
              const vec3 V, const vec3 OD, const MaterialGpu m) {
  const float nDotL = dot(N, L);
  vec3 sum = ambientIntensity * OD * m.diffuseAmbient.a + intensity * OD * max(nDotL, 0.0);
  // Most materials have no specular colour. The test is on a push constant, so it is a
  // real branch on every device and those materials never pay for pow().
  if (m.flags.y != 0u) {
    const vec3 halfway = L + V;
    const float halfLength = length(halfway);
    const float nDotH = halfLength > 0.0 ? max(dot(N, halfway / halfLength), 0.0) : 0.0;
    const float exponent = m.specularShininess.a;
    const float highlight = exponent > 0.0 ? pow(nDotH, exponent) : 1.0;
    sum += nDotL > 0.0 ? intensity * m.specularShininess.rgb * highlight : vec3(0.0);
  }
  return color * sum;
}

// Point and spot lights: L, d and the attenuation (0 beyond the radius).
float pointAttenuation(const LightGpu light, const vec3 P, const vec3 N, out vec3 L) {
  const vec3 toLight = light.positionType.xyz - P;
  const float d = length(toLight);
  L = d > 0.0 ? toLight / d : N;
  const vec3 a = light.attenuationRadius.xyz;
  return d > light.attenuationRadius.w ? 0.0 : 1.0 / max(a.x + a.y * d + a.z * d * d, 1.0);
}

// The VRML97 spot factor (4.14.4): 1 inside beamWidth, 0 beyond cutOffAngle, linear
// in the angle between.
float spotFactor(const LightGpu light, const vec3 L) {
  const float spotAngle = acos(clamp(dot(-L, light.directionAmbient.xyz), -1.0, 1.0));
  const float beamWidth = light.spot.x;
  const float cutOffAngle = light.spot.y;
  if (spotAngle >= cutOffAngle) return 0.0;
  if (spotAngle <= beamWidth) return 1.0;
  return (spotAngle - cutOffAngle) / (beamWidth - cutOffAngle);
}

vec3 litColor(const vec3 OD, const MaterialGpu m) {
  vec3 N = normalize(inWorldNormal);
  if ((m.flags.x & kMaterialTwoSided) != 0u && !gl_FrontFacing) N = -N;
  const vec3 P = inWorldPosition;
  const vec3 V = normalize(frame.cameraPosition.xyz - P);
  vec3 color = m.emissiveAlpha.rgb;
  // Lights are sorted by kind; the counts come from a uniform, so every loop is a real
  // loop on every device, and a kind the scene lacks costs nothing.
  uint i = 0u;
  for (uint end = frame.lightCounts.x; i < end; ++i) {
    const LightGpu light = lights[i];
    color += lightSum(light.colorIntensity.rgb, light.colorIntensity.a, light.directionAmbient.w,
                      -light.directionAmbient.xyz, N, V, OD, m);
  }
  for (uint end = i + frame.lightCounts.y; i < end; ++i) {
    const LightGpu light = lights[i];
    vec3 L;
    const float attenuation = pointAttenuation(light, P, N, L);
    color += attenuation * lightSum(light.colorIntensity.rgb, light.colorIntensity.a, light.directionAmbient.w, L, N,
                                    V, OD, m);
  }
  for (uint end = i + frame.lightCounts.z; i < end; ++i) {
    const LightGpu light = lights[i];
    vec3 L;
    const float attenuation = pointAttenuation(light, P, N, L) * spotFactor(light, L);
    color += attenuation * lightSum(light.colorIntensity.rgb, light.colorIntensity.a, light.directionAmbient.w, L, N,
                                    V, OD, m);
  }
  if (frame.lightCounts.w != 0u) {
    // The headlight: a white directional light along the view, intensity 1, no ambient (6.29).
    color += lightSum(vec3(1.0), 1.0, 0.0, -frame.headlightDirection.xyz, N, V, OD, m);
  }
  return color;
}

// A texture cut from a photo holds no detail finer than one photo pixel; standard
// mipmapping would filter a screen pixel's whole footprint over it and so blur the
// photo's own pixels a second time (from the photo's camera, the walls' textures are
// minified 4-16x and come out one photo pixel softer). Along each screen axis the
// footprint J (in texels, or in photo pixels where those are larger) already carries
// one such pixel of blur; the filter supplies the rest, sqrt(J^2 - 1), by scaling that
// axis's gradient. Far away (J >> 1) this is ordinary mipmapping; from the photo's
// camera (J = 1) it samples the full-resolution texture as the photo was seen.
vec4 samplePhotoTexture(const vec2 uv) {
  const vec2 photo = inPhoto.xy / inPhoto.z;
  const vec2 texels = vec2(draw.textureSource[1].w, draw.textureSource[2].w);
  const vec2 uvX = dFdx(uv), uvY = dFdy(uv);
  const vec2 texelsX = uvX * texels, texelsY = uvY * texels, photoX = dFdx(photo), photoY = dFdy(photo);
  // Squared footprints: no square roots but the two the scales need.
  const float jX2 = max(min(dot(texelsX, texelsX), dot(photoX, photoX)), 1e-12);
  const float jY2 = max(min(dot(texelsY, texelsY), dot(photoY, photoY)), 1e-12);
  const float scaleX = sqrt(max(0.0, 1.0 - 1.0 / jX2));
  const float scaleY = sqrt(max(0.0, 1.0 - 1.0 / jY2));
  return textureGrad(shapeTexture, uv, uvX * scaleX, uvY * scaleY);
}

vec3 encodeSrgb(const vec3 linear) {
  const vec3 c = clamp(linear, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
  const MaterialGpu m = draw.material;
  const uint flags = m.flags.x;
  vec3 OD = m.diffuseAmbient.rgb;
  float alpha = m.emissiveAlpha.a;
  if ((flags & kMaterialVertexColor) != 0u) {
    OD = inColor.rgb;
    alpha *= inColor.a;
  }
  if (kTextured) {
    // _SRGB format: already linear. A specialization constant, not a push constant:
    // lavapipe ran both sides of a run-time branch around texture(), 40% of a frame.
    const vec4 texel = kPhotoTexture ? samplePhotoTexture(inTexCoord) : texture(shapeTexture, inTexCoord);
    OD = texel.rgb;
    if ((flags & kMaterialTextureAlpha) != 0u) alpha = texel.a;
  }
  vec3 color = kLit ? litColor(OD, m) : OD;
  color = clamp(color, 0.0, 1.0);
  if (kEncodeSrgb) color = encodeSrgb(color);
  outColor = vec4(color, clamp(alpha, 0.0, 1.0));
}
