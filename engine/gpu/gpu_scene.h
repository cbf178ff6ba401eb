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
#include "engine/gpu/upload_queue.h"
#include "engine/scene/scene.h"

namespace pw::engine::gpu {

// The CPU half of an upload: the scene packed and copied into one staging buffer,
// with what the GPU half needs to know of it (the Scene itself may be gone by then).
struct SceneStaging {
  struct Range {
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
  };
  struct TextureInfo {
    uint32_t width = 1, height = 1;
    TextureWrap wrapS = TextureWrap::kRepeat, wrapT = TextureWrap::kRepeat;
    bool cutFromPhoto = false;  // Texture::sourceFromTexCoord: its sampler (pipelines.h)
    VkDeviceSize offset = 0;    // its pixels in the staging buffer
  };
  std::vector<DrawItem> opaque;
  std::vector<DrawItem> transparent;
  glm::vec3 backgroundLinear{0.0f};
  bool headlight = true;
  glm::uvec3 lightCounts{0};
  Range vertices, indices, lights, shapes, lightLists;
  std::vector<TextureInfo> textures;  // [0]: the white texel of untextured shapes
  std::shared_ptr<const Buffer> staging;
};

struct GpuScene {
  // The CPU half: packs `scene` and fills a staging buffer. Safe on any thread while
  // the renderer's thread draws (it only reads the Context and PipelineLibrary and
  // creates a buffer, which Vulkan allows from any thread). Errors name the shape or
  // texture at fault; a texture larger than the device allows is one of them.
  static Result<SceneStaging> stage(const Context& context, const PipelineLibrary& pipelines, const Scene& scene);

  // The GPU half, on the renderer's thread: creates the buffers, textures and
  // descriptor sets and submits the copies and mip blits through `uploads` without
  // waiting for them (frames submitted later draw the finished scene).
  static Result<std::shared_ptr<const GpuScene>> upload(const Context& context, const PipelineLibrary& pipelines,
                                                        SceneStaging staged, UploadQueue& uploads);

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
