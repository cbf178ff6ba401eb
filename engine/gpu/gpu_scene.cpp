#include "engine/gpu/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

#include "engine/gpu/barriers.h"
#include "engine/gpu/vk_check.h"
#include "engine/scene/texture_detail.h"

namespace pw::engine::gpu {
namespace {

constexpr VkFormat kTextureFormat = VK_FORMAT_R8G8B8A8_SRGB;  // sampled as linear (the GPU decodes)

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) { return (value + alignment - 1) / alignment * alignment; }

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

Result<SceneStaging> GpuScene::stage(const Context& context, const PipelineLibrary& pipelines, const Scene& input) {
  const std::optional<Scene> subdivided = pipelines.vertexLighting() ? subdividedForVertexLighting(input) : std::nullopt;
  const Scene& scene = subdivided ? *subdivided : input;
  auto packedResult = packScene(scene);
  if (!packedResult) return packedResult.error();
  PackedScene& packed = *packedResult;
  SceneStaging out;
  out.backgroundLinear = packed.backgroundLinear;
  out.headlight = scene.navigation.headlight;
  out.lightCounts = packed.lightCounts;

  // Textures: the image size limit is the device's, so it is checked here.
  const uint32_t maxSide = context.properties().limits.maxImageDimension2D;
  std::vector<const Image*> images{nullptr};  // slot 0: white
  out.textures.push_back({1, 1, TextureWrap::kRepeat, TextureWrap::kRepeat, false, 0});
  for (const PackedTexture& t : packed.textures) {
    const Image& image = *t.texture->image;
    if (static_cast<uint32_t>(image.width) > maxSide || static_cast<uint32_t>(image.height) > maxSide) {
      return makeError("texture " + (t.texture->url.empty() ? std::string("(made in code)") : t.texture->url) + ": " +
                       std::to_string(image.width) + "x" + std::to_string(image.height) + " is larger than this GPU's " +
                       std::to_string(maxSide) + " pixel limit; scale it down");
    }
    images.push_back(&image);
    out.textures.push_back({static_cast<uint32_t>(image.width), static_cast<uint32_t>(image.height), t.texture->wrapS,
                            t.texture->wrapT, t.texture->sourceFromTexCoord.has_value(), 0});
  }

  VkDeviceSize total = 0;
  const auto place = [&](SceneStaging::Range& range, VkDeviceSize bytes) {
    range.offset = alignUp(total, 16);
    range.size = bytes;
    total = range.offset + bytes;
  };
  place(out.vertices, packed.vertices.size() * sizeof(Vertex));
  place(out.indices, packed.indices.size() * sizeof(uint32_t));
  place(out.lights, packed.lights.size() * sizeof(LightGpu));
  place(out.shapes, packed.shapes.size() * sizeof(ShapeGpu));
  place(out.lightLists, packed.lightLists.size() * sizeof(uint32_t));
  for (size_t i = 0; i < images.size(); ++i) {
    SceneStaging::Range range;
    place(range, images[i] ? images[i]->rgba.size() : 4);
    out.textures[i].offset = range.offset;
  }

  auto stagingBuffer = createBuffer(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::kUpload);
  if (!stagingBuffer) return stagingBuffer.error();
  out.staging = std::make_shared<const Buffer>(std::move(*stagingBuffer));
  auto* bytes = static_cast<uint8_t*>(out.staging->mapped);
  const auto put = [&](const SceneStaging::Range& range, const void* from) {
    if (range.size > 0) std::memcpy(bytes + range.offset, from, range.size);  // empty vectors may have null data()
  };
  put(out.vertices, packed.vertices.data());
  put(out.indices, packed.indices.data());
  put(out.lights, packed.lights.data());
  put(out.shapes, packed.shapes.data());
  put(out.lightLists, packed.lightLists.data());
  for (size_t i = 0; i < images.size(); ++i) {
    static const uint8_t kWhite[4] = {255, 255, 255, 255};
    if (i > 0 && packed.textures[i - 1].cutFromPhoto) {
      stageBaseAndDetail(*packed.textures[i - 1].texture, bytes + out.textures[i].offset);
    } else {
      std::memcpy(bytes + out.textures[i].offset, images[i] ? images[i]->rgba.data() : kWhite,
                  images[i] ? images[i]->rgba.size() : 4);
    }
  }
  out.opaque = std::move(packed.opaque);
  out.transparent = std::move(packed.transparent);
  return out;
}

Result<std::shared_ptr<const GpuScene>> GpuScene::upload(const Context& context, const PipelineLibrary& pipelines,
                                                         SceneStaging staged, UploadQueue& uploads) {
  const VkDevice device = context.device();
  auto out = std::make_shared<GpuScene>();
  out->backgroundLinear = staged.backgroundLinear;
  out->headlight = staged.headlight;
  out->lightCounts = staged.lightCounts;
  const auto makeBuffer = [&](Buffer& target, const SceneStaging::Range& range, VkBufferUsageFlags usage) -> Status {
    auto buffer = createBuffer(context, range.size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kDeviceLocal);
    if (!buffer) return buffer.error();
    target = std::move(*buffer);
    return {};
  };
  PW_TRY(makeBuffer(out->vertices, staged.vertices, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT));
  PW_TRY(makeBuffer(out->indices, staged.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT));
  PW_TRY(makeBuffer(out->lights, staged.lights, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  PW_TRY(makeBuffer(out->shapes, staged.shapes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  PW_TRY(makeBuffer(out->lightLists, staged.lightLists, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  const bool blitMips = canBlitMips(context, kTextureFormat);
  for (const SceneStaging::TextureInfo& t : staged.textures) {
    ImageSpec spec;
    spec.format = kTextureFormat;
    spec.width = t.width;
    spec.height = t.height;
    spec.mipLevels = blitMips ? mipLevelCount(spec.width, spec.height) : 1;
    spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    auto gpuImage = createImage(context, spec);
    if (!gpuImage) return gpuImage.error();
    out->textures.push_back(std::move(*gpuImage));
  }

  // Not waited for: the copies and blits run while the caller goes on; the staging
  // buffer and the new scene stay alive until they are done (upload_queue.h).
  const std::shared_ptr<const Buffer> staging = staged.staging;
  const auto keepAlive = std::make_shared<std::pair<std::shared_ptr<const Buffer>, std::shared_ptr<const GpuScene>>>(
      staging, out);
  PW_TRY(uploads.submit([&](VkCommandBuffer cmd) {
    const auto copy = [&](const Buffer& target, const SceneStaging::Range& range) {
      if (range.size == 0) return;
      const VkBufferCopy region{range.offset, 0, range.size};
      vkCmdCopyBuffer(cmd, staging->get(), target.get(), 1, &region);
    };
    copy(out->vertices, staged.vertices);
    copy(out->indices, staged.indices);
    copy(out->lights, staged.lights);
    copy(out->shapes, staged.shapes);
    copy(out->lightLists, staged.lightLists);
    for (size_t i = 0; i < out->textures.size(); ++i) {
      const GpuImage& image = out->textures[i];
      transitionImage(cmd, {image.get(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                            VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT});
      VkBufferImageCopy region{};
      region.bufferOffset = staged.textures[i].offset;
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
  }, keepAlive));

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
    const SceneStaging::TextureInfo& t = staged.textures[slot];
    imageInfos[slot].sampler = pipelines.sampler(t.wrapS, t.wrapT, t.cutFromPhoto);
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

  out->opaque = std::move(staged.opaque);
  out->transparent = std::move(staged.transparent);
  return std::shared_ptr<const GpuScene>(std::move(out));
}

}  // namespace pw::engine::gpu
