// Scene vertices: local to world by the shape's transform, world to clip by the frame's
// camera. Shared by the triangle, line and point pipelines. In the interactive profile
// on CPU devices (kVertexLighting) the VRML97 lighting is worked out here, per vertex.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shader_interface.h"

layout(location = PW_LOCATION_POSITION) in vec3 inPosition;
layout(location = PW_LOCATION_NORMAL) in vec3 inNormal;
layout(location = PW_LOCATION_TEXCOORD) in vec2 inTexCoord;
layout(location = PW_LOCATION_COLOR) in vec4 inColor;

layout(std140, set = PW_SET_FRAME, binding = PW_BINDING_FRAME_UNIFORMS) uniform FrameBlock { FrameUniforms frame; };
layout(std430, set = PW_SET_SCENE, binding = PW_BINDING_SHAPES) readonly buffer ShapeBlock { ShapeGpu shapes[]; };
layout(std430, set = PW_SET_SCENE, binding = PW_BINDING_LIGHTS) readonly buffer LightBlock { LightGpu lights[]; };
layout(std430, set = PW_SET_SCENE, binding = PW_BINDING_LIGHT_LISTS) readonly buffer LightListBlock { uint lightLists[]; };
layout(push_constant) uniform PushBlock { DrawPushConstants draw; };

layout(constant_id = PW_SPEC_LIT) const bool kLit = true;
layout(constant_id = PW_SPEC_VERTEX_LIGHTING) const bool kVertexLighting = false;

#include "lighting.glsl"

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outWorldNormal;
layout(location = 2) out vec2 outTexCoord;
layout(location = 3) out vec4 outColor;
layout(location = 4) out vec3 outPhoto;  // homogeneous photo pixel (textures cut from a photo)
layout(location = 5) out vec3 outDiffuseLight;  // kVertexLighting: LightTerms
layout(location = 6) out vec3 outSpecularLight;

void main() {
  const vec4 world = shapes[draw.shapeIndex].model * vec4(inPosition, 1.0);
  outWorldPosition = world.xyz;
  outWorldNormal = mat3(shapes[draw.shapeIndex].normalMatrix) * inNormal;
  // VRML texture coordinates have t = 0 at the bottom of the image (6.48); our images
  // are stored top row first, so Vulkan's v = 0 is the top.
  outTexCoord = vec2(inTexCoord.x, 1.0 - inTexCoord.y);
  // Linear in (u, v, 1), so interpolated perspective-correctly it is exact per pixel.
  outPhoto = mat3(draw.textureSource[0].xyz, draw.textureSource[1].xyz, draw.textureSource[2].xyz) * vec3(outTexCoord, 1.0);
  outColor = inColor;
  gl_Position = frame.viewProjection * world;
  if (kLit && kVertexLighting) {
    vec3 N = normalize(outWorldNormal);
    // A two-sided surface is lit on the side that faces the eye (the fragment shader
    // tells by gl_FrontFacing; per vertex the normal against the view does).
    const bool twoSided = (draw.material.flags.x & kMaterialTwoSided) != 0u;
    if (twoSided && dot(N, frame.cameraPosition.xyz - world.xyz) < 0.0) N = -N;
    const LightTerms terms = lightTerms(world.xyz, N, draw.material);
    outDiffuseLight = terms.diffuse;
    outSpecularLight = terms.specular;
  } else {
    outDiffuseLight = outSpecularLight = vec3(0.0);
  }
  // Points need a size (Vulkan 27.10: undefined otherwise); ignored for other topologies.
  gl_PointSize = 1.0;
}
