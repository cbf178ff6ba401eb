#include "engine/gpu/scene_pass.h"

#include <algorithm>
#include <cstring>

#include "engine/gpu/barriers.h"
#include "engine/scene/color_space.h"
#include "engine/gpu/frustum.h"

namespace pw::engine::gpu {
namespace {

// Binds pipelines, textures and cull state only when they change.
class DrawState {
 public:
  DrawState(VkCommandBuffer cmd, PipelineLibrary& pipelines, const GpuScene& scene, const SceneTargets& targets)
      : cmd_(cmd), pipelines_(pipelines), scene_(scene), targets_(targets) {}

  Status draw(const DrawItem& d) {
    if (d.variant.index() != variant_) {
      auto pipeline = pipelines_.pipeline(targets_.format, targets_.samples, d.variant);
      if (!pipeline) return pipeline.error();
      vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, *pipeline);
      variant_ = d.variant.index();
    }
    if (static_cast<int64_t>(d.textureSlot) != texture_) {
      vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.layout(), PW_SET_TEXTURE, 1,
                              &scene_.textureSets[d.textureSlot], 0, nullptr);
      texture_ = d.textureSlot;
    }
    const int cull = d.cullBackFaces ? 1 : 0;
    if (cull != cull_) {
      vkCmdSetCullMode(cmd_, d.cullBackFaces ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE);
      cull_ = cull;
    }
    const int front = d.clockwiseFront ? 1 : 0;
    if (front != front_) {
      // The projection keeps the screen's up as world up, so counter-clockwise in the
      // world stays counter-clockwise in Vulkan's framebuffer (y down) area test.
      vkCmdSetFrontFace(cmd_, d.clockwiseFront ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
      front_ = front;
    }
    const DrawPushConstants push{d.shapeIndex,        d.lightListOffset,
                                 d.pointLightCount,   d.spotLightCount,
                                 d.material,          {d.textureSource[0], d.textureSource[1], d.textureSource[2]}};
    vkCmdPushConstants(cmd_, pipelines_.layout(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(push), &push);
    vkCmdDrawIndexed(cmd_, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
    return {};
  }

 private:
  VkCommandBuffer cmd_;
  PipelineLibrary& pipelines_;
  const GpuScene& scene_;
  const SceneTargets& targets_;
  int variant_ = -1;
  int64_t texture_ = -1;
  int cull_ = -1;
  int front_ = -1;
};

}  // namespace

Status recordSceneView(VkCommandBuffer cmd, PipelineLibrary& pipelines, const GpuScene& scene, FrameSlot& slot,
                       uint32_t viewIndex, const SceneTargets& targets, const ViewArea& where, const Camera& camera,
                       const FrameSettings& settings, DrawScratch& scratch, FrameStats& stats) {
  const int width = where.rect.width, height = where.rect.height;
  const glm::mat4 viewProjection = projectionMatrix(camera, width, height) * viewMatrix(camera);
  FrameUniforms uniforms{};
  uniforms.viewProjection = viewProjection;
  uniforms.cameraPosition = glm::vec4(camera.position, std::max(1.0f, camera.supersample));
  const bool headlight = settings.headlight.value_or(scene.headlight);
  uniforms.headlightDirection = glm::vec4(forwardOf(camera), 0.0f);
  uniforms.lightCounts = glm::uvec4(scene.lightCounts.x, 0u, 0u, headlight ? 1u : 0u);
  std::memcpy(slot.uniformsFor(viewIndex), &uniforms, sizeof(uniforms));  // host-coherent; the submit makes it visible

  // Depth and the multisampled colour image start each view discarded (UNDEFINED), and
  // so does the result with discardResult; the source stages order the layout
  // transitions after the writes (and read-back copies) of earlier views and frames,
  // and after a swapchain's acquire semaphore, waited for at the colour-output stage.
  const VkPipelineStageFlags2 depthStages =
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  const ImageTransition depthIn{targets.depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                depthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, depthStages,
                                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                                VK_IMAGE_ASPECT_DEPTH_BIT};
  const ImageTransition colorIn{targets.color, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT};
  ImageTransition resultIn = colorIn;
  resultIn.image = targets.resolve;
  const bool multisampled = targets.resolve != VK_NULL_HANDLE;
  if (multisampled && targets.discardResult) {
    const ImageTransition all[3] = {colorIn, depthIn, resultIn};
    transitionImages(cmd, all);
  } else if (multisampled || targets.discardResult) {
    const ImageTransition both[2] = {colorIn, depthIn};  // colour: multisampled, or the result itself
    transitionImages(cmd, both);
  } else {
    transitionImage(cmd, depthIn);
  }

  const glm::vec3 background =
      settings.backgroundColor ? srgbToLinear(*settings.backgroundColor) : scene.backgroundLinear;
  const glm::vec3 clear = targets.encodeSrgbInShader ? linearToSrgb(background) : background;
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = targets.colorView;
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  color.storeOp = targets.resolve ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
  color.clearValue.color = {{clear.r, clear.g, clear.b, 1.0f}};
  if (targets.resolve) {
    color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
    color.resolveImageView = targets.resolveView;
    color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  }
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = targets.depthView;
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = where.area;  // the clears and the resolve stay inside it
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &rendering);

  Status status;
  if (!scene.opaque.empty() || !scene.transparent.empty()) {
    const VkViewport viewport{float(where.rect.x), float(where.rect.y), float(width), float(height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &where.area);
    const VkDeviceSize zero = 0;
    const VkBuffer vertexBuffer = scene.vertices.get();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &zero);
    vkCmdBindIndexBuffer(cmd, scene.indices.get(), 0, VK_INDEX_TYPE_UINT32);
    const VkDescriptorSet sets[] = {slot.frameSet, scene.sceneSet};
    const uint32_t uniformsOffset = slot.dynamicOffset(viewIndex);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.layout(), PW_SET_FRAME, 2, sets, 1,
                            &uniformsOffset);

    const Frustum frustum = frustumFromViewProjection(viewProjection);
    DrawState state(cmd, pipelines, scene, targets);
    for (const DrawItem& d : scene.opaque) {
      if (!intersects(frustum, d.worldBounds)) {
        ++stats.culledShapes;
        continue;
      }
      if (status = state.draw(d); !status) break;
      ++stats.drawCalls;
    }
    // Transparent shapes back to front by their bounds' centres (VRML leaves the order
    // to the browser; this is the usual painter's approximation).
    scratch.transparent.clear();
    for (const DrawItem& d : scene.transparent) {
      if (!intersects(frustum, d.worldBounds)) {
        ++stats.culledShapes;
        continue;
      }
      const glm::vec3 offset = d.worldBounds.center() - camera.position;
      scratch.transparent.emplace_back(glm::dot(offset, offset), &d);
    }
    // std::sort, not stable_sort, which would allocate a buffer every frame; ties go
    // by shape index so the order is the same on every run.
    std::sort(scratch.transparent.begin(), scratch.transparent.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first > b.first : a.second->shapeIndex < b.second->shapeIndex;
    });
    for (const auto& [distance, d] : scratch.transparent) {
      if (!status) break;
      status = state.draw(*d);
      ++stats.drawCalls;
    }
  }
  vkCmdEndRendering(cmd);
  return status;
}

}  // namespace pw::engine::gpu
