#include "engine/gpu/view_recorder.h"

#include <algorithm>
#include <cmath>

#include "engine/gpu/barriers.h"
#include "engine/scene/color_space.h"
#include "engine/gpu/image_pass.h"
#include "engine/gpu/renderer_impl.h"

namespace pw::engine {
namespace {

// The part of `rect` inside a target of `extent`; empty (0 x 0) when none is.
VkRect2D clipToTarget(const PixelRect& rect, VkExtent2D extent) {
  const int64_t x0 = std::max<int64_t>(rect.x, 0), y0 = std::max<int64_t>(rect.y, 0);
  const int64_t x1 = std::min<int64_t>(int64_t(rect.x) + rect.width, extent.width);
  const int64_t y1 = std::min<int64_t>(int64_t(rect.y) + rect.height, extent.height);
  if (x1 <= x0 || y1 <= y0) return {{0, 0}, {0, 0}};
  return {{int32_t(x0), int32_t(y0)}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}};
}

// A rectangle the device can take as a viewport (Vulkan 27.9: size up to
// maxViewportDimensions, edges within viewportBoundsRange).
Status checkViewport(const gpu::Context& context, const PixelRect& rect, const std::string& what) {
  const VkPhysicalDeviceLimits& limits = context.properties().limits;
  const auto within = [&](int64_t from, int64_t size, uint32_t maxSize) {
    return size <= maxSize && from >= limits.viewportBoundsRange[0] && from + size <= limits.viewportBoundsRange[1];
  };
  if (!within(rect.x, rect.width, limits.maxViewportDimensions[0]) ||
      !within(rect.y, rect.height, limits.maxViewportDimensions[1])) {
    return makeError(what + ": the rectangle " + std::to_string(rect.width) + "x" + std::to_string(rect.height) + " at (" +
                     std::to_string(rect.x) + ", " + std::to_string(rect.y) + ") is beyond the device's viewport limits (" +
                     std::to_string(limits.maxViewportDimensions[0]) + " pixels a side, coordinates within " +
                     std::to_string(int(limits.viewportBoundsRange[0])) + ".." +
                     std::to_string(int(limits.viewportBoundsRange[1])) + ")");
  }
  return {};
}

// Colour writes of one rendering instance before the next one's loads, clears and
// blends on the same image (rasterization order holds only within an instance).
void colorWritesBeforeNextView(VkCommandBuffer cmd) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  barrier.srcAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  barrier.dstAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.memoryBarrierCount = 1;
  dependency.pMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

void clearFrame(VkCommandBuffer cmd, const FrameTarget& target, const glm::vec3& clearColor) {
  const glm::vec3 clear = target.encodeSrgbInShader ? clearColor : srgbToLinear(clearColor);
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = target.view;
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.clearValue.color = {{clear.r, clear.g, clear.b, 1.0f}};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, target.extent};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  vkCmdBeginRendering(cmd, &rendering);
  vkCmdEndRendering(cmd);
}

}  // namespace

Status ViewRecorder::prepare(const Renderer::Impl& renderer, const std::vector<View>& views, VkExtent2D extent) {
  prepared_.clear();
  const gpu::Context& context = *renderer.context;
  for (size_t i = 0; i < views.size(); ++i) {
    const std::string what = "view " + std::to_string(i);
    Prepared p;
    p.view = &views[i];
    VkExtent2D targetExtent = extent;
    PixelRect rect;
    if (const auto* scene = std::get_if<SceneView>(&views[i])) {
      const auto found = renderer.scenes.find(scene->scene.id);
      if (found == renderer.scenes.end()) {
        return makeError(what + ": scene handle " + std::to_string(scene->scene.id) + " names no scene (never added, or removed)");
      }
      p.scene = found->second;
      if (Status s = checkCamera(scene->camera); !s) return makeError(what + ": " + s.message());
      if (scene->target) {
        const auto image = renderer.images.find(scene->target.id);
        if (image == renderer.images.end() || !image->second->isRenderTarget()) {
          return makeError(what + ": target " + std::to_string(scene->target.id) +
                           " is not a render target (Renderer::addRenderTarget), or was removed");
        }
        p.image = image->second;
        targetExtent = {p.image->width(), p.image->height()};
      }
      rect = scene->rect;
    } else {
      const auto& image = std::get<ImageView>(views[i]);
      const auto found = renderer.images.find(image.image.id);
      if (found == renderer.images.end()) {
        return makeError(what + ": image handle " + std::to_string(image.image.id) + " names no image (never added, or removed)");
      }
      p.image = found->second;
      const ImageTransform& t = image.transform;
      if (!(t.scale > 0) || !std::isfinite(t.scale) || !std::isfinite(t.offset.x) || !std::isfinite(t.offset.y)) {
        return makeError(what + ": the image transform's scale must be a positive number and its offset finite");
      }
      rect = image.rect;
    }
    if (rect.width < 0 || rect.height < 0) return makeError(what + ": the rectangle's width and height must not be negative");
    if (rect.whole()) rect = {0, 0, int(targetExtent.width), int(targetExtent.height)};
    PW_TRY(checkViewport(context, rect, what));
    p.where.rect = rect;
    p.where.area = clipToTarget(rect, targetExtent);
    if (p.where.area.extent.width == 0) continue;  // wholly outside its target: nothing to draw
    prepared_.push_back(std::move(p));
  }
  return {};
}

Status ViewRecorder::record(VkCommandBuffer cmd, Renderer::Impl& renderer, gpu::FrameSlot& slot,
                            const FrameTarget& target, const glm::vec3& clearColor) {
  stats_ = {};
  const uint32_t sceneViews = static_cast<uint32_t>(std::count_if(
      prepared_.begin(), prepared_.end(), [](const Prepared& p) { return std::holds_alternative<SceneView>(*p.view); }));
  PW_TRY(slot.reserveViews(*renderer.context, sceneViews));

  // A first scene view over the whole frame takes the frame image in and clears it
  // itself (the walkthrough's frame: one barrier, one rendering instance). Otherwise
  // the image's earlier contents are discarded here and it is cleared; the source
  // stages order that after the last frame's writes and copies (read-back, capture)
  // and after the swapchain's acquire semaphore, waited for at the colour-output stage.
  const bool firstCoversFrame = !prepared_.empty() && std::holds_alternative<SceneView>(*prepared_[0].view) &&
                                !prepared_[0].image && prepared_[0].where.area.extent.width == target.extent.width &&
                                prepared_[0].where.area.extent.height == target.extent.height;
  bool written = false;
  if (!firstCoversFrame) {
    gpu::transitionImage(cmd, {target.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                               VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT});
    clearFrame(cmd, target, clearColor);
    written = true;
  }

  uint32_t sceneIndex = 0;
  for (const Prepared& p : prepared_) {
    const bool first = !written;  // then the frame image is still UNDEFINED (firstCoversFrame)
    if (written) colorWritesBeforeNextView(cmd);
    written = true;
    ++stats_.views;
    if (const auto* view = std::get_if<SceneView>(p.view)) {
      gpu::SceneTargets targets;
      targets.samples = renderer.samples;
      if (p.image) {  // a render target: sampled between uses, drawn into here
        const gpu::ViewImage& rt = *p.image;
        gpu::transitionImage(cmd, {rt.color.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                   VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT});
        const gpu::GpuImage& drawn = rt.msaa ? *rt.msaa : rt.color;
        targets.color = drawn.get();
        targets.colorView = drawn.view.get();
        if (rt.msaa) {
          targets.resolve = rt.color.get();
          targets.resolveView = rt.color.view.get();
        }
        targets.depth = rt.depth->get();
        targets.depthView = rt.depth->view.get();
        targets.format = gpu::kViewImageFormat;
        targets.extent = {rt.width(), rt.height()};
      } else {
        targets.color = target.msaa ? target.msaa : target.image;
        targets.colorView = target.msaa ? target.msaaView : target.view;
        if (target.msaa) {
          targets.resolve = target.image;
          targets.resolveView = target.view;
        }
        targets.depth = target.depth;
        targets.depthView = target.depthView;
        targets.format = target.format;
        targets.extent = target.extent;
        targets.encodeSrgbInShader = target.encodeSrgbInShader;
        targets.discardResult = first;
      }
      const Status recorded = gpu::recordSceneView(cmd, *renderer.pipelines, *p.scene, slot, sceneIndex++, targets,
                                                   p.where, view->camera, view->settings, scratch_, stats_);
      if (p.image) {
        gpu::transitionImage(cmd, {p.image->color.get(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                   VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
        slot.inFlight.push_back(p.image);
      }
      slot.inFlight.push_back(p.scene);
      PW_TRY(recorded);
    } else {
      const auto& imageView = std::get<ImageView>(*p.view);
      gpu::ImageDraw draw;
      draw.target = target.view;
      draw.format = target.format;
      draw.area = p.where.area;
      draw.set = p.image->set(resolvedFilter(imageView.filter, imageView.transform.scale));
      draw.imageSize = {p.image->width(), p.image->height()};
      draw.opaqueImage = p.image->opaque;
      draw.transform = imageView.transform;
      draw.background = imageView.background;
      slot.inFlight.push_back(p.image);
      PW_TRY(gpu::recordImageView(cmd, *renderer.imagePipelines, draw));
    }
  }
  prepared_.clear();  // it points into the caller's views; the slot keeps what they use
  return {};
}

}  // namespace pw::engine
