// The interface between the C++ renderer (engine/gpu) and the GLSL shaders: binding
// numbers, push constants and the layouts of uniform and storage buffers. Both sides
// include this one file; the C++ side checks sizes and offsets below, so a change on
// one side that the other does not follow fails to compile instead of misrendering.
//
// Every struct is made of vec4/uvec4/mat4 only, so std140 (uniform) and std430
// (storage) lay it out exactly as C++ does, with no hidden padding.
//
// Colours here are linear (the renderer decodes the scene's sRGB-encoded colours).
#ifndef PW_SHADER_INTERFACE_H
#define PW_SHADER_INTERFACE_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace pw::engine::gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = uint32_t;
#define PW_SHADER_CONST inline constexpr
#else
#define PW_SHADER_CONST const
#endif

// Descriptor sets: 0 per frame (camera, headlight: one FrameUniforms per scene view,
// chosen by a dynamic offset), 1 per scene (lights, shapes), 2 per texture. Macros, not
// constants, because GLSL layout() wants literals.
#define PW_SET_FRAME 0
#define PW_BINDING_FRAME_UNIFORMS 0
#define PW_SET_SCENE 1
#define PW_BINDING_LIGHTS 0
#define PW_BINDING_SHAPES 1
#define PW_BINDING_LIGHT_LISTS 2
#define PW_SET_TEXTURE 2
#define PW_BINDING_TEXTURE 0
// The image pipeline (image.vert, image.frag) has one set: the image and its sampler.
#define PW_SET_IMAGE 0
#define PW_BINDING_IMAGE 0

// Vertex input locations (one interleaved binding, see engine/gpu/scene_packing.h).
#define PW_LOCATION_POSITION 0
#define PW_LOCATION_NORMAL 1
#define PW_LOCATION_TEXCOORD 2
#define PW_LOCATION_COLOR 3

// LightGpu.positionType.w
PW_SHADER_CONST uint kLightDirectional = 0u;
PW_SHADER_CONST uint kLightPoint = 1u;
PW_SHADER_CONST uint kLightSpot = 2u;

// Specialization constants (constant_id; the vertex shader reads LIT and
// VERTEX_LIGHTING): each pipeline is compiled
// for one combination, so that the CPU device (lavapipe), which runs both sides of
// a branch it cannot prove uniform, never pays for texturing or lighting it skips.
#define PW_SPEC_TEXTURED 0     // sample set 2's texture
#define PW_SPEC_LIT 1          // VRML97 lighting; false: no Material, the colour at full intensity
#define PW_SPEC_ENCODE_SRGB 2  // a UNORM target: the shader applies the sRGB curve itself
#define PW_SPEC_PHOTO_TEXTURE 3  // the texture was cut from a photo: filter at its footprint (scene.frag)
// A texture cut from a photo keeps its detail layer's code in alpha: the composite is
// the base times 2^((code - 128) / this), code in 0..255 (engine/scene/texture_detail.h).
#define PW_DETAIL_CODES_PER_OCTAVE 64.0
#define PW_SPEC_VERTEX_LIGHTING 4  // light per vertex (scene.vert), not per pixel: CPU devices, interactive

// MaterialGpu.flags.x bits (decided per shape at run time: cheap either way).
PW_SHADER_CONST uint kMaterialUnlit = 1u;          // no Material node (the pipeline is unlit too)
PW_SHADER_CONST uint kMaterialTextured = 2u;       // has a texture (the pipeline samples it)
PW_SHADER_CONST uint kMaterialTextureAlpha = 4u;   // the texture's alpha replaces 1 - transparency
PW_SHADER_CONST uint kMaterialVertexColor = 8u;    // per-vertex colour replaces the diffuse colour
PW_SHADER_CONST uint kMaterialTwoSided = 16u;      // solid FALSE: light the back face with -N
PW_SHADER_CONST uint kMaterialIntensityTexture = 32u;  // a 1- or 2-component texture modulates the colour

// Set 0: one per scene view of a frame in flight.
struct FrameUniforms {
  mat4 viewProjection;     // world to Vulkan clip
  vec4 cameraPosition;     // xyz world metres; w: Camera::supersample (at least 1)
  vec4 headlightDirection; // xyz: direction the light travels (the view direction)
  uvec4 lightCounts;       // x: directional lights, first in the light buffer (they reach
                           // everything); y, z: 0 (the point and spot lights that reach a
                           // shape come with its draw); w: 1 when the headlight is on
};

// Set 1, binding 0: the scene's lights in world space (VRML97 4.14.4, 6.17, 6.36, 6.45).
struct LightGpu {
  vec4 colorIntensity;      // rgb linear colour, a: intensity
  vec4 positionType;        // xyz: location (point, spot); w: kLight* as a float (informative)
  vec4 directionAmbient;    // xyz: unit direction the light travels (directional, spot); w: ambientIntensity
  vec4 attenuationRadius;   // xyz: attenuation a0 a1 a2; w: radius in metres (point, spot)
  vec4 spot;                // x: beamWidth, y: cutOffAngle (radians, beamWidth <= cutOffAngle)
};

// VRML97 Material (6.27) plus how the shape is shaded.
struct MaterialGpu {
  vec4 diffuseAmbient;      // rgb: diffuseColor (linear), a: ambientIntensity
  vec4 emissiveAlpha;       // rgb: emissiveColor (linear; unlit: the colour), a: 1 - transparency
  vec4 specularShininess;   // rgb: specularColor (linear), a: exponent = shininess * 128
  uvec4 flags;              // x: kMaterial* bits; y: 1 when specularColor is not black
};

// Set 1, binding 1: one per shape, indexed by the push constant.
struct ShapeGpu {
  mat4 model;          // local to world
  mat4 normalMatrix;   // inverse transpose of the model's upper 3x3 (in a mat4 for layout)
};

// Per draw. The material travels here rather than in a buffer: push constants are
// uniform, so the fragment shader's branches on its flags are real branches even on
// lavapipe, and the per-pixel cost of fetching it from a storage buffer disappears.
struct DrawPushConstants {
  uint shapeIndex;
  // The point and spot lights within reach of the shape (their radius meets its
  // bounds): pointLightCount then spotLightCount indices into the light buffer, from
  // lightListOffset in the light-list buffer (set 1, binding 2).
  uint lightListOffset;
  uint pointLightCount;
  uint spotLightCount;
  MaterialGpu material;
  // A texture cut from a photo (Texture::sourceFromTexCoord): the homography from the
  // shader's (u, v), v = 0 at the top, to the photo's pixels, as three columns in xyz;
  // textureSource[1].w and [2].w are the texture's width and height in texels.
  vec4 textureSource[3];
};

// Per ImageView (image.frag): where the image lies in the frame and what is drawn
// beyond its edges. Frame position = offset + scale * image position, image pixel
// centres at integers (engine/gpu/view.h).
struct ImagePushConstants {
  vec4 transform;   // xy: frame pixels per image pixel (x, y), zw: offset in frame pixels
  vec4 imageSize;   // xy: width, height in pixels; zw: 0
  vec4 background;  // rgb linear, a: coverage (0: leave the frame as it is)
};

#ifdef __cplusplus
static_assert(sizeof(ImagePushConstants) == 48 && offsetof(ImagePushConstants, imageSize) == 16 &&
              offsetof(ImagePushConstants, background) == 32);
static_assert(sizeof(FrameUniforms) == 112 && offsetof(FrameUniforms, cameraPosition) == 64 &&
              offsetof(FrameUniforms, headlightDirection) == 80 && offsetof(FrameUniforms, lightCounts) == 96);
static_assert(sizeof(LightGpu) == 80 && offsetof(LightGpu, positionType) == 16 &&
              offsetof(LightGpu, directionAmbient) == 32 && offsetof(LightGpu, attenuationRadius) == 48 &&
              offsetof(LightGpu, spot) == 64);
static_assert(sizeof(MaterialGpu) == 64 && offsetof(MaterialGpu, emissiveAlpha) == 16 &&
              offsetof(MaterialGpu, specularShininess) == 32 && offsetof(MaterialGpu, flags) == 48);
static_assert(sizeof(ShapeGpu) == 128 && offsetof(ShapeGpu, normalMatrix) == 64);
static_assert(sizeof(DrawPushConstants) == 128 && offsetof(DrawPushConstants, material) == 16 &&
              offsetof(DrawPushConstants, textureSource) == 80);
static_assert(sizeof(DrawPushConstants) <= 128, "the smallest maxPushConstantsSize Vulkan allows");
}  // namespace pw::engine::gpu
#endif

#endif  // PW_SHADER_INTERFACE_H
