// A scene uploaded to the GPU: one vertex and one index buffer, the shape and light
// storage buffers, the textures with their mip chains, and their descriptor sets.
// Immutable once made; frames hold a shared_ptr to the one they draw, so replacing
// the Renderer's scene never frees buffers a frame in flight still reads.
#pragma once

#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/context.h"
#include "engine/gpu/pipelines.h"
#include "engine/gpu/resources.h"
#include "engine/gpu/scene_packing.h"
#include "engine/scene/scene.h"

namespace pw::engine::gpu {

struct GpuScene {
  // Uploads `scene` (blocking: one submission, waited for). Errors name the shape or
  // texture at fault; a texture larger than the device allows is one of them.
  static Result<std::shared_ptr<const GpuScene>> upload(const Context& context, const PipelineLibrary& pipelines,
                                                        const Scene& scene);

  // Draw lists and data the frame recorder reads on the CPU.
  std::vector<DrawItem> opaque;
  std::vector<DrawItem> transparent;
  glm::vec3 backgroundLinear{0.0f};
  bool headlight = true;  // the scene's NavigationInfo
  glm::uvec3 lightCounts{0};  // directional, point, spot (the light buffer's order)

  Buffer vertices;
  Buffer indices;
  Buffer lights;
  Buffer shapes;
  Buffer lightLists;
  std::vector<GpuImage> textures;  // [0] is a 1x1 white texture for untextured shapes
  OwnedDescriptorPool descriptorPool;  // after the buffers it describes: freed first
  VkDescriptorSet sceneSet = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> textureSets;  // by DrawItem::textureSlot
};

}  // namespace pw::engine::gpu
