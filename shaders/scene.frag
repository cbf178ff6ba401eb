// The scene's fragments: the colour (material, per-vertex colour or texture) lit by
// the VRML97 lighting equations (lighting.glsl) per pixel, or per vertex in the
// interactive profile on CPU devices; shapes without a Material are unlit (6.5).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shader_interface.h"

layout(constant_id = PW_SPEC_TEXTURED) const bool kTextured = false;
layout(constant_id = PW_SPEC_LIT) const bool kLit = true;
layout(constant_id = PW_SPEC_ENCODE_SRGB) const bool kEncodeSrgb = false;
layout(constant_id = PW_SPEC_PHOTO_TEXTURE) const bool kPhotoTexture = false;
layout(constant_id = PW_SPEC_VERTEX_LIGHTING) const bool kVertexLighting = false;

layout(std140, set = PW_SET_FRAME, binding = PW_BINDING_FRAME_UNIFORMS) uniform FrameBlock { FrameUniforms frame; };
layout(std430, set = PW_SET_SCENE, binding = PW_BINDING_LIGHTS) readonly buffer LightBlock { LightGpu lights[]; };
layout(std430, set = PW_SET_SCENE, binding = PW_BINDING_LIGHT_LISTS) readonly buffer LightListBlock { uint lightLists[]; };
layout(set = PW_SET_TEXTURE, binding = PW_BINDING_TEXTURE) uniform sampler2D shapeTexture;
layout(push_constant) uniform PushBlock { DrawPushConstants draw; };

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inWorldNormal;
layout(location = 2) in vec2 inTexCoord;
layout(location = 3) in vec4 inColor;
layout(location = 4) in vec3 inPhoto;
layout(location = 5) in vec3 inDiffuseLight;  // kVertexLighting: LightTerms for the side seen
layout(location = 6) in vec3 inSpecularLight;

layout(location = 0) out vec4 outColor;

#include "lighting.glsl"

vec3 litColor(const vec3 OD, const MaterialGpu m) {
  LightTerms terms;
  if (kVertexLighting) {
    terms = LightTerms(inDiffuseLight, inSpecularLight);
  } else {
    const bool back = (m.flags.x & kMaterialTwoSided) != 0u && !gl_FrontFacing;
    const vec3 N = normalize(inWorldNormal);
    terms = lightTerms(inWorldPosition, back ? -N : N, m);
  }
  return m.emissiveAlpha.rgb + OD * terms.diffuse + terms.specular;
}

// A texture cut from a photo holds no detail finer than one photo pixel; standard
// mipmapping would filter a screen pixel's whole footprint over it and so blur the
// photo's own pixels a second time (from the photo's camera, the walls' textures are
// minified 4-16x and come out one photo pixel softer). Along each screen axis the
// footprint J (in texels, or in photo pixels where those are larger) already carries
// one such pixel of blur; the filter supplies the rest, sqrt(J^2 - 1), by scaling that
// axis's gradient. Far away (J >> 1) this is ordinary mipmapping; from the photo's
// camera (J = 1) it samples the full-resolution texture as the photo was seen.
// The texture is uploaded as its base (what the photo shows) with the detail layer's
// code in alpha (engine/scene/texture_detail.h). Where a screen pixel covers less of
// the photo than one of its pixels, along either axis (a view closer than the photo
// was taken), the detail fades in: none at a photo pixel per screen pixel, all of it
// at half one. A supersampled frame (Camera::supersample) counts the pixels of the image
// it is averaged down to.
// A cut-out's texture (an object stood up: its alpha the object's coverage, no detail
// layer; kMaterialTextureAlpha) is read the same way, and its alpha kept.
vec4 samplePhotoTexture(const vec2 uv, const bool alphaIsCoverage) {
  const vec2 photo = inPhoto.xy / inPhoto.z;
  const vec2 texels = vec2(draw.textureSource[1].w, draw.textureSource[2].w);
  const vec2 uvX = dFdx(uv), uvY = dFdy(uv);
  const vec2 texelsX = uvX * texels, texelsY = uvY * texels, photoX = dFdx(photo), photoY = dFdy(photo);
  const float photoX2 = dot(photoX, photoX), photoY2 = dot(photoY, photoY);
  // Squared footprints: no square roots but the three the scales need.
  const float jX2 = max(min(dot(texelsX, texelsX), photoX2), 1e-12);
  const float jY2 = max(min(dot(texelsY, texelsY), photoY2), 1e-12);
  const float detail = clamp(2.0 - 2.0 * frame.cameraPosition.w * sqrt(min(photoX2, photoY2)), 0.0, 1.0);
  const float scaleX = sqrt(max(0.0, 1.0 - 1.0 / jX2));
  const float scaleY = sqrt(max(0.0, 1.0 - 1.0 / jY2));
  const vec4 texel = textureGrad(shapeTexture, uv, uvX * scaleX, uvY * scaleY);
  if (alphaIsCoverage) return texel;
  const float octaves = (texel.a * 255.0 - 128.0) / PW_DETAIL_CODES_PER_OCTAVE;
  return vec4(texel.rgb * exp2(detail * octaves), 1.0);
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
    const vec4 texel = kPhotoTexture ? samplePhotoTexture(inTexCoord, (flags & kMaterialTextureAlpha) != 0u)
                                     : texture(shapeTexture, inTexCoord);
    // VRML97 table 4.5: an RGB(A) texture replaces the diffuse colour, a grey one
    // (intensity) modulates it.
    OD = (flags & kMaterialIntensityTexture) != 0u ? OD * texel.r : texel.rgb;
    if ((flags & kMaterialTextureAlpha) != 0u) alpha = texel.a;
  }
  vec3 color = kLit ? litColor(OD, m) : OD;
  color = clamp(color, 0.0, 1.0);
  if (kEncodeSrgb) color = encodeSrgb(color);
  outColor = vec4(color, clamp(alpha, 0.0, 1.0));
}
