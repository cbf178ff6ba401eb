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

layout(std140, set = PW_SET_FRAME, binding = PW_BINDING_FRAME_UNIFORMS) uniform FrameBlock { FrameUniforms frame; };
layout(std430, set = PW_SET_SCENE, binding = PW_BINDING_LIGHTS) readonly buffer LightBlock { LightGpu lights[]; };
layout(std430, set = PW_SET_SCENE, binding = PW_BINDING_SHAPES) readonly buffer ShapeBlock { ShapeGpu shapes[]; };
layout(set = PW_SET_TEXTURE, binding = PW_BINDING_TEXTURE) uniform sampler2D shapeTexture;
layout(push_constant) uniform PushBlock { DrawPushConstants draw; };

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inWorldNormal;
layout(location = 2) in vec2 inTexCoord;
layout(location = 3) in vec4 inColor;

layout(location = 0) out vec4 outColor;

// The VRML97 spot factor (4.14.4): 1 inside beamWidth, 0 beyond cutOffAngle, linear between.
float spotFactor(const LightGpu light, const vec3 L) {
  const float spotAngle = acos(clamp(dot(-L, light.directionAmbient.xyz), -1.0, 1.0));
  const float beamWidth = light.spot.x;
  const float cutOffAngle = light.spot.y;
  if (spotAngle >= cutOffAngle) return 0.0;
  if (spotAngle <= beamWidth) return 1.0;
  return (spotAngle - cutOffAngle) / (beamWidth - cutOffAngle);
}

// One light's term of the sum above.
vec3 lightTerm(const LightGpu light, const vec3 P, const vec3 N, const vec3 V, const vec3 OD,
               const MaterialGpu m) {
  const uint type = uint(light.positionType.w + 0.5);
  vec3 L;
  float attenuation = 1.0;
  float spot = 1.0;
  if (type == kLightDirectional) {
    L = -light.directionAmbient.xyz;
  } else {
    const vec3 toLight = light.positionType.xyz - P;
    const float d = length(toLight);
    if (d > light.attenuationRadius.w) return vec3(0.0);  // beyond radius: no light at all
    L = d > 0.0 ? toLight / d : N;
    const vec3 a = light.attenuationRadius.xyz;
    attenuation = 1.0 / max(a.x + a.y * d + a.z * d * d, 1.0);
    if (type == kLightSpot) spot = spotFactor(light, L);
  }
  const float intensity = light.colorIntensity.a;
  vec3 sum = light.directionAmbient.w * OD * m.diffuseAmbient.a;  // ambient_i
  const float nDotL = dot(N, L);
  if (nDotL > 0.0) {
    sum += intensity * OD * nDotL;
    const vec3 halfway = L + V;
    const float halfLength = length(halfway);
    if (halfLength > 0.0) {
      const float nDotH = max(dot(N, halfway / halfLength), 0.0);
      const float exponent = m.specularShininess.a;
      sum += intensity * m.specularShininess.rgb * (exponent > 0.0 ? pow(nDotH, exponent) : 1.0);
    }
  }
  return attenuation * spot * light.colorIntensity.rgb * sum;
}

vec3 encodeSrgb(const vec3 linear) {
  const vec3 c = clamp(linear, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
  const MaterialGpu m = shapes[draw.shapeIndex].material;
  const uint flags = m.flags.x;
  vec3 OD = m.diffuseAmbient.rgb;
  float alpha = m.emissiveAlpha.a;
  if ((flags & kMaterialVertexColor) != 0u) {
    OD = inColor.rgb;
    alpha *= inColor.a;
  }
  if ((flags & kMaterialTextured) != 0u) {
    const vec4 texel = texture(shapeTexture, inTexCoord);  // _SRGB format: already linear
    OD = texel.rgb;
    if ((flags & kMaterialTextureAlpha) != 0u) alpha = texel.a;
  }

  vec3 color;
  if ((flags & kMaterialUnlit) != 0u) {
    color = OD;
  } else {
    vec3 N = normalize(inWorldNormal);
    if ((flags & kMaterialTwoSided) != 0u && !gl_FrontFacing) N = -N;
    const vec3 P = inWorldPosition;
    const vec3 V = normalize(frame.cameraPosition.xyz - P);
    color = m.emissiveAlpha.rgb;
    for (uint i = 0u; i < frame.counts.x; ++i) color += lightTerm(lights[i], P, N, V, OD, m);
    if (frame.headlightDirection.w > 0.5) {
      // The headlight: a directional light along the view, intensity 1, white, no ambient (6.29).
      LightGpu headlight;
      headlight.colorIntensity = vec4(1.0);
      headlight.positionType = vec4(0.0, 0.0, 0.0, float(kLightDirectional));
      headlight.directionAmbient = vec4(frame.headlightDirection.xyz, 0.0);
      headlight.attenuationRadius = vec4(1.0, 0.0, 0.0, 0.0);
      headlight.spot = vec4(0.0);
      color += lightTerm(headlight, P, N, V, OD, m);
    }
  }
  color = clamp(color, 0.0, 1.0);
  if (frame.counts.y != 0u) color = encodeSrgb(color);
  outColor = vec4(color, clamp(alpha, 0.0, 1.0));
}
