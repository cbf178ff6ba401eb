#include "engine/gpu/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

#include "engine/gpu/barriers.h"
#include "engine/gpu/vk_check.h"

namespace pw::engine::gpu {
namespace {

constexpr VkFormat kTextureFormat = VK_FORMAT_R8G8B8A8_SRGB;  // sampled as linear (the GPU decodes)

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) { return (value + alignment - 1) / alignment * alignment; }

// Where each piece lies in the one staging buffer.
struct StagingLayout {
  VkDeviceSize vertices = 0, indices = 0, lights = 0, shapes = 0, lightLists = 0;
  std::vector<VkDeviceSize> textures;  // [0]: the white texel
  VkDeviceSize total = 0;
};

// Fills the rest of the chain from level 0 by halving blits (linear filtering in
// linear space, as the format is sRGB), leaving every level SHADER_READ_ONLY.
void recordMipChain(VkCommandBuffer cmd, const GpuImage& image) {
  const uint32_t levels = image.spec.mipLevels;
  int32_t w = static_cast<int32_t>(image.spec.width), h = static_cast<int32_t>(image.spec.height);
  for (uint32_t level = 1; level < levels; ++level) {
    transitionImage(cmd, {image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                          VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 1});
    const int32_t nw = std::max(w / 2, 1), nh = std::max(h / 2, 1);
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
    blit.srcOffsets[1] = {w, h, 1};
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
    blit.dstOffsets[1] = {nw, nh, 1};
    vkCmdBlitImage(cmd, image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   1, &blit, VK_FILTER_LINEAR);
    w = nw;
    h = nh;
  }
  const ImageTransition done[2] = {
      {image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
       VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_ASPECT_COLOR_BIT, 0, levels - 1},
      {image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
       VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
       VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
       levels - 1, 1},
  };
  if (levels > 1) {
    transitionImages(cmd, done);
  } else {
    transitionImage(cmd, done[1]);
  }
}

// Lighting per vertex, a lamp's pool of light on a large face falls between its
// corners: lit faces longer than 1/40 of the scene are cut up (up to 16 x 16 pieces a
// triangle, 200000 triangles a mesh) when the scene has point or spot lights. Nothing
// when no face needs it.
std::optional<Scene> subdividedForVertexLighting(const Scene& scene) {
  const bool localLights = std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) {
    return l.on && l.type != LightType::kDirectional;
  });
  if (!localLights) return std::nullopt;
  const float target = std::max(glm::length(sceneBounds(scene).size()) / 40.0f, 1e-4f);
  Scene out = scene;  // shapes share their meshes; only cut ones are replaced
  std::map<std::pair<const Mesh*, int>, std::shared_ptr<const Mesh>> cut;
  bool any = false;
  for (Shape& shape : out.shapes) {
    if (!shape.mesh || shape.mesh->topology != Topology::kTriangles || !shape.appearance || !shape.appearance->material) continue;
    const Mesh& mesh = *shape.mesh;
    float longest = 0;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      glm::vec3 p[3];
      for (int c = 0; c < 3; ++c) {
        const uint32_t index = mesh.indices[t + c];
        if (index >= mesh.positions.size()) return std::nullopt;  // packScene reports it
        p[c] = glm::vec3(shape.transform * glm::vec4(mesh.positions[index], 1.0f));
      }
      longest = std::max({longest, glm::length(p[1] - p[0]), glm::length(p[2] - p[1]), glm::length(p[0] - p[2])});
    }
    if (!std::isfinite(longest)) continue;
    const size_t triangles = mesh.indices.size() / 3;
    int k = static_cast<int>(std::clamp(std::ceil(longest / target), 1.0f, 16.0f));
    while (k > 1 && triangles * static_cast<size_t>(k) * k > 200000) --k;
    if (k <= 1) continue;
    auto& slot = cut[{shape.mesh.get(), k}];
    if (!slot) slot = std::make_shared<const Mesh>(subdivideTriangles(mesh, k));
    shape.mesh = slot;
    any = true;
  }
  if (!any) return std::nullopt;
  return out;
}

}  // namespace

Result<std::shared_ptr<const GpuScene>> GpuScene::upload(const Context& context, const PipelineLibrary& pipelines,
                                                         const Scene& input) {
  const std::optional<Scene> subdivided = pipelines.vertexLighting() ? subdividedForVertexLighting(input) : std::nullopt;
  const Scene& scene = subdivided ? *subdivided : input;
  auto packedResult = packScene(scene);
  if (!packedResult) return packedResult.error();
  PackedScene& packed = *packedResult;
  const VkDevice device = context.device();
  auto out = std::make_shared<GpuScene>();
  out->backgroundLinear = packed.backgroundLinear;
  out->headlight = scene.navigation.headlight;
  out->lightCounts = packed.lightCounts;

  // Textures: the image size limit is the device's, so it is checked here.
  const uint32_t maxSide = context.properties().limits.maxImageDimension2D;
  VkFormatProperties formatProps;
  vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), kTextureFormat, &formatProps);
  const VkFormatFeatureFlags mipFeatures = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                           VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  const bool canBlitMips = (formatProps.optimalTilingFeatures & mipFeatures) == mipFeatures;
  std::vector<const Image*> images{nullptr};  // slot 0: white
  for (const PackedTexture& t : packed.textures) {
    const Image& image = *t.texture->image;
    if (static_cast<uint32_t>(image.width) > maxSide || static_cast<uint32_t>(image.height) > maxSide) {
      return makeError("texture " + (t.texture->url.empty() ? std::string("(made in code)") : t.texture->url) + ": " +
                       std::to_string(image.width) + "x" + std::to_string(image.height) + " is larger than this GPU's " +
                       std::to_string(maxSide) + " pixel limit; scale it down");
    }
    images.push_back(&image);
  }

  StagingLayout layout;
  const auto place = [&](VkDeviceSize bytes) {
    const VkDeviceSize at = alignUp(layout.total, 16);
    layout.total = at + bytes;
    return at;
  };
  const VkDeviceSize vertexBytes = packed.vertices.size() * sizeof(Vertex);
  const VkDeviceSize indexBytes = packed.indices.size() * sizeof(uint32_t);
  const VkDeviceSize lightBytes = packed.lights.size() * sizeof(LightGpu);
  const VkDeviceSize shapeBytes = packed.shapes.size() * sizeof(ShapeGpu);
  const VkDeviceSize lightListBytes = packed.lightLists.size() * sizeof(uint32_t);
  layout.vertices = place(vertexBytes);
  layout.indices = place(indexBytes);
  layout.lights = place(lightBytes);
  layout.shapes = place(shapeBytes);
  layout.lightLists = place(lightListBytes);
  for (const Image* image : images) layout.textures.push_back(place(image ? image->rgba.size() : 4));

  auto staging = createBuffer(context, layout.total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::kUpload);
  if (!staging) return staging.error();
  auto* bytes = static_cast<uint8_t*>(staging->mapped);
  const auto put = [&](VkDeviceSize at, const void* from, VkDeviceSize size) {
    if (size > 0) std::memcpy(bytes + at, from, size);  // empty vectors may have null data()
  };
  put(layout.vertices, packed.vertices.data(), vertexBytes);
  put(layout.indices, packed.indices.data(), indexBytes);
  put(layout.lights, packed.lights.data(), lightBytes);
  put(layout.shapes, packed.shapes.data(), shapeBytes);
  put(layout.lightLists, packed.lightLists.data(), lightListBytes);
  for (size_t i = 0; i < images.size(); ++i) {
    static const uint8_t kWhite[4] = {255, 255, 255, 255};
    std::memcpy(bytes + layout.textures[i], images[i] ? images[i]->rgba.data() : kWhite, images[i] ? images[i]->rgba.size() : 4);
  }

  const auto makeBuffer = [&](Buffer& target, VkDeviceSize size, VkBufferUsageFlags usage) -> Status {
    auto buffer = createBuffer(context, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kDeviceLocal);
    if (!buffer) return buffer.error();
    target = std::move(*buffer);
    return {};
  };
  PW_TRY(makeBuffer(out->vertices, vertexBytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT));
  PW_TRY(makeBuffer(out->indices, indexBytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT));
  PW_TRY(makeBuffer(out->lights, lightBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  PW_TRY(makeBuffer(out->shapes, shapeBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  PW_TRY(makeBuffer(out->lightLists, lightListBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  for (const Image* image : images) {
    ImageSpec spec;
    spec.format = kTextureFormat;
    spec.width = image ? static_cast<uint32_t>(image->width) : 1;
    spec.height = image ? static_cast<uint32_t>(image->height) : 1;
    spec.mipLevels = canBlitMips ? mipLevelCount(spec.width, spec.height) : 1;
    spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    auto gpuImage = createImage(context, spec);
    if (!gpuImage) return gpuImage.error();
    out->textures.push_back(std::move(*gpuImage));
  }

  PW_TRY(context.submitAndWait([&](VkCommandBuffer cmd) {
    const auto copy = [&](const Buffer& target, VkDeviceSize from, VkDeviceSize size) {
      if (size == 0) return;
      const VkBufferCopy region{from, 0, size};
      vkCmdCopyBuffer(cmd, staging->get(), target.get(), 1, &region);
    };
    copy(out->vertices, layout.vertices, vertexBytes);
    copy(out->indices, layout.indices, indexBytes);
    copy(out->lights, layout.lights, lightBytes);
    copy(out->shapes, layout.shapes, shapeBytes);
    copy(out->lightLists, layout.lightLists, lightListBytes);
    for (size_t i = 0; i < out->textures.size(); ++i) {
      const GpuImage& image = out->textures[i];
      transitionImage(cmd, {image.get(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                            VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT});
      VkBufferImageCopy region{};
      region.bufferOffset = layout.textures[i];
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {image.spec.width, image.spec.height, 1};
      vkCmdCopyBufferToImage(cmd, staging->get(), image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      recordMipChain(cmd, image);
    }
    VkMemoryBarrier2 visible{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    visible.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    visible.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    visible.dstStageMask = VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT |
                           VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    visible.dstAccessMask = VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT |
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &visible;
    vkCmdPipelineBarrier2(cmd, &dependency);
  }));

  // Descriptors: one scene set, one set per texture slot.
  const uint32_t textureSets = static_cast<uint32_t>(out->textures.size());
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3},
                                        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, textureSets}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1 + textureSets;
  poolInfo.poolSizeCount = 2;
  poolInfo.pPoolSizes = sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool));
  out->descriptorPool = OwnedDescriptorPool(device, pool);

  std::vector<VkDescriptorSetLayout> setLayouts(1 + textureSets, pipelines.textureSetLayout());
  setLayouts[0] = pipelines.sceneSetLayout();
  std::vector<VkDescriptorSet> sets(setLayouts.size());
  VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocInfo.descriptorPool = pool;
  allocInfo.descriptorSetCount = static_cast<uint32_t>(setLayouts.size());
  allocInfo.pSetLayouts = setLayouts.data();
  PW_VK_CHECK(vkAllocateDescriptorSets(device, &allocInfo, sets.data()));
  out->sceneSet = sets[0];
  out->textureSets.assign(sets.begin() + 1, sets.end());

  const VkDescriptorBufferInfo lightInfo{out->lights.get(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo shapeInfo{out->shapes.get(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo lightListInfo{out->lightLists.get(), 0, VK_WHOLE_SIZE};
  std::vector<VkDescriptorImageInfo> imageInfos(textureSets);
  std::vector<VkWriteDescriptorSet> writes;
  const auto bufferWrite = [&](uint32_t binding, const VkDescriptorBufferInfo* info) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = out->sceneSet;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    w.pBufferInfo = info;
    writes.push_back(w);
  };
  bufferWrite(PW_BINDING_LIGHTS, &lightInfo);
  bufferWrite(PW_BINDING_SHAPES, &shapeInfo);
  bufferWrite(PW_BINDING_LIGHT_LISTS, &lightListInfo);
  for (uint32_t slot = 0; slot < textureSets; ++slot) {
    const Texture* texture = slot == 0 ? nullptr : packed.textures[slot - 1].texture;
    imageInfos[slot].sampler = texture ? pipelines.sampler(texture->wrapS, texture->wrapT, texture->sourceFromTexCoord.has_value())
                                       : pipelines.sampler(TextureWrap::kRepeat, TextureWrap::kRepeat, false);
    imageInfos[slot].imageView = out->textures[slot].view.get();
    imageInfos[slot].imageLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = out->textureSets[slot];
    w.dstBinding = PW_BINDING_TEXTURE;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &imageInfos[slot];
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);

  out->opaque = std::move(packed.opaque);
  out->transparent = std::move(packed.transparent);
  return std::shared_ptr<const GpuScene>(std::move(out));
}

}  // namespace pw::engine::gpu
