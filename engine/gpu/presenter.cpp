#include "engine/gpu/presenter.h"

#include <algorithm>
#include <optional>

#include "engine/gpu/barriers.h"
#include "engine/gpu/renderer_impl.h"
#include "engine/gpu/view_recorder.h"
#include "engine/gpu/vk_check.h"

namespace pw::engine {
namespace {

struct SwapchainImage {
  VkImage image = VK_NULL_HANDLE;  // owned by the swapchain
  gpu::OwnedImageView view;         // in the swapchain's format: the views' dynamic rendering
  gpu::OwnedImageView overlayView;  // in the overlay's UNORM format where that differs; else none
  gpu::OwnedFramebuffer framebuffer;   // for the overlay render pass
  gpu::OwnedSemaphore renderFinished;  // per image: present waits on it (one per frame would be reused too early)
};

bool isSrgb(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_R8G8B8A8_SRGB || f == VK_FORMAT_A8B8G8R8_SRGB_PACK32; }

// The UNORM format with the same bytes as an sRGB one; VK_FORMAT_UNDEFINED for others.
VkFormat unormOf(VkFormat f) {
  switch (f) {
    case VK_FORMAT_B8G8R8A8_SRGB:
      return VK_FORMAT_B8G8R8A8_UNORM;
    case VK_FORMAT_R8G8B8A8_SRGB:
      return VK_FORMAT_R8G8B8A8_UNORM;
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
      return VK_FORMAT_A8B8G8R8_UNORM_PACK32;
    default:
      return VK_FORMAT_UNDEFINED;
  }
}

// Where red and blue lie in a capturable swapchain format's 4 bytes; none for others.
std::optional<std::pair<int, int>> redBlueBytes(VkFormat f) {
  switch (f) {
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
      return std::pair(2, 0);
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
    case VK_FORMAT_A8B8G8R8_UNORM_PACK32:
      return std::pair(0, 2);
    default:
      return std::nullopt;
  }
}

// A read-back of one presented frame: the buffer the frame's commands copy into, and
// the frame slot whose fence says when it is there.
struct Capture {
  std::shared_ptr<gpu::Buffer> buffer;
  VkExtent2D extent{0, 0};
  size_t slot = 0;
};

}  // namespace

// Member order is teardown order, reversed: the swapchain's images before the
// swapchain, everything before the borrowed renderer.
struct Presenter::Impl {
  Renderer::Impl& renderer;
  gpu::Context& context;
  VkSurfaceKHR surface = VK_NULL_HANDLE;  // borrowed
  PresenterOptions options;
  VkSurfaceFormatKHR surfaceFormat{};
  VkFormat overlayFormat = VK_FORMAT_UNDEFINED;  // the overlay pass's: never an sRGB one where avoidable
  VkPresentModeKHR presentMode = VK_PRESENT_MODE_FIFO_KHR;
  gpu::OwnedRenderPass overlayPass;
  gpu::OwnedDescriptorPool framePool;
  std::vector<gpu::FrameSlot> frames;
  std::vector<gpu::OwnedSemaphore> imageAvailable;  // per frame slot
  gpu::OwnedSwapchain swapchain;
  std::vector<SwapchainImage> images;
  std::optional<gpu::GpuImage> msaaColor;
  std::optional<gpu::GpuImage> depth;
  VkExtent2D extent{0, 0};
  uint32_t minImageCount = 0;
  int requestedWidth = 0;
  int requestedHeight = 0;
  bool needsRecreate = true;
  bool transferSource = false;  // swapchain images can be copied from (captures)
  uint32_t frameIndex = 0;
  uint64_t presented = 0;
  ViewRecorder recorder;
  FrameStats stats;
  bool captureRequested = false;
  std::optional<Capture> capture;  // made by a drawn frame, not yet taken

  Impl(Renderer::Impl& r) : renderer(r), context(*r.context) {}
  ~Impl() {
    // Frames and presents may still be queued; nothing else orders their end before
    // the objects below go (presentation has no fence). Teardown only.
    if (context.device()) vkQueueWaitIdle(context.queue());
  }

  Status createOverlayPass();
  Status recreateSwapchain();
  // Records the copy of `image` (after the overlay pass) into a new capture buffer.
  Status recordCapture(VkCommandBuffer cmd, VkImage image, gpu::FrameSlot& slot);
};

Status Presenter::Impl::createOverlayPass() {
  VkAttachmentDescription attachment{};
  attachment.format = overlayFormat;
  attachment.samples = VK_SAMPLE_COUNT_1_BIT;
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // keep the resolved scene
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachment.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  attachment.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  const VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &reference;
  // The scene pass's resolve wrote the image at the colour-output stage; the overlay
  // reads (loads, blends) and writes it at the same stage.
  VkSubpassDependency dependencies[2]{};
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  // Presenting waits on a semaphore; a capture copies the image afterwards.
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &attachment;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = dependencies;
  VkRenderPass pass = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateRenderPass(context.device(), &info, nullptr, &pass));
  overlayPass = gpu::OwnedRenderPass(context.device(), pass);
  return {};
}

Status Presenter::Impl::recreateSwapchain() {
  const VkDevice device = context.device();
  if (requestedWidth <= 0 || requestedHeight <= 0) return {};  // minimised: keep skipping
  VkSurfaceCapabilitiesKHR caps;
  PW_VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context.physicalDevice(), surface, &caps));
  VkExtent2D size = caps.currentExtent;
  if (size.width == UINT32_MAX) {  // the surface takes the swapchain's size
    size.width = std::clamp(uint32_t(requestedWidth), caps.minImageExtent.width, caps.maxImageExtent.width);
    size.height = std::clamp(uint32_t(requestedHeight), caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (size.width == 0 || size.height == 0) return {};
  PW_TRY(checkFrameSize(context, int(size.width), int(size.height), renderer.samples));

  // Swapchain images may still be read by queued presents, and presentation has no
  // fence to wait for (before VK_EXT_swapchain_maintenance1): recreation, which only a
  // resize causes, waits for the queue.
  PW_VK_CHECK(vkQueueWaitIdle(context.queue()));
  for (gpu::FrameSlot& slot : frames) slot.inFlight.clear();
  PW_TRY(renderer.uploads->collect());

  uint32_t count = std::max(caps.minImageCount + 1, 2u);
  if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  // sRGB images with a UNORM overlay view: the images may be viewed in both formats.
  const VkFormat viewFormats[2] = {surfaceFormat.format, overlayFormat};
  VkImageFormatListCreateInfo formatList{VK_STRUCTURE_TYPE_IMAGE_FORMAT_LIST_CREATE_INFO};
  formatList.viewFormatCount = 2;
  formatList.pViewFormats = viewFormats;
  if (overlayFormat != surfaceFormat.format) {
    info.flags = VK_SWAPCHAIN_CREATE_MUTABLE_FORMAT_BIT_KHR;
    info.pNext = &formatList;
  }
  info.surface = surface;
  info.minImageCount = count;
  info.imageFormat = surfaceFormat.format;
  info.imageColorSpace = surfaceFormat.colorSpace;
  info.imageExtent = size;
  info.imageArrayLayers = 1;
  // Copying from the images is for captures (tests, screenshots of what the window
  // shows); surfaces nearly always allow it.
  transferSource = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) && redBlueBytes(surfaceFormat.format);
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (transferSource ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha &
                                                                       -caps.supportedCompositeAlpha);
  info.presentMode = presentMode;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain.get();
  VkSwapchainKHR handle = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &handle));
  images.clear();  // views and framebuffers of the old images go before the old swapchain
  swapchain = gpu::OwnedSwapchain(device, handle);
  extent = size;
  minImageCount = count;

  uint32_t imageCount = 0;
  PW_VK_CHECK(vkGetSwapchainImagesKHR(device, handle, &imageCount, nullptr));
  std::vector<VkImage> swapImages(imageCount);
  PW_VK_CHECK(vkGetSwapchainImagesKHR(device, handle, &imageCount, swapImages.data()));
  for (VkImage image : swapImages) {
    SwapchainImage entry;
    entry.image = image;
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = image;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = surfaceFormat.format;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    PW_VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
    entry.view = gpu::OwnedImageView(device, view);
    VkImageView overlayView = view;
    if (overlayFormat != surfaceFormat.format) {
      viewInfo.format = overlayFormat;
      PW_VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &overlayView));
      entry.overlayView = gpu::OwnedImageView(device, overlayView);
    }
    VkFramebufferCreateInfo fbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fbInfo.renderPass = overlayPass.get();
    fbInfo.attachmentCount = 1;
    fbInfo.pAttachments = &overlayView;
    fbInfo.width = size.width;
    fbInfo.height = size.height;
    fbInfo.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    PW_VK_CHECK(vkCreateFramebuffer(device, &fbInfo, nullptr, &framebuffer));
    entry.framebuffer = gpu::OwnedFramebuffer(device, framebuffer);
    VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    PW_VK_CHECK(vkCreateSemaphore(device, &semInfo, nullptr, &semaphore));
    entry.renderFinished = gpu::OwnedSemaphore(device, semaphore);
    images.push_back(std::move(entry));
  }

  msaaColor.reset();
  depth.reset();
  gpu::ImageSpec color;
  color.format = surfaceFormat.format;
  color.width = size.width;
  color.height = size.height;
  color.samples = renderer.samples;
  color.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  color.transient = true;
  if (renderer.samples != VK_SAMPLE_COUNT_1_BIT) {
    auto image = gpu::createImage(context, color);
    if (!image) return image.error();
    msaaColor = std::move(*image);
  }
  gpu::ImageSpec depthSpec = color;
  depthSpec.format = gpu::kDepthFormat;
  depthSpec.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  depthSpec.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  auto depthImage = gpu::createImage(context, depthSpec);
  if (!depthImage) return depthImage.error();
  depth = std::move(*depthImage);
  needsRecreate = false;
  return {};
}

Presenter::Presenter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Presenter::~Presenter() = default;

Result<std::unique_ptr<Presenter>> Presenter::create(Renderer& renderer, VkSurfaceKHR surface, int width, int height,
                                                     const PresenterOptions& options) {
  auto impl = std::make_unique<Impl>(renderer.impl());
  gpu::Context& ctx = impl->context;
  if (!ctx.swapchainSupported()) {
    return makeError("the renderer was created without VK_KHR_surface among its instance extensions, or " +
                     std::string(ctx.properties().deviceName) + " cannot present; pass the window's extensions");
  }
  if (surface == VK_NULL_HANDLE) return makeError("no window surface was given to present to");
  VkBool32 presentable = VK_FALSE;
  PW_VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physicalDevice(), ctx.queueFamily(), surface, &presentable));
  if (!presentable) {
    return makeError(std::string(ctx.properties().deviceName) + " cannot present to this window from its graphics queue");
  }
  if (options.framesInFlight < 1 || options.framesInFlight > 4) return makeError("frames in flight must be 1..4");
  impl->surface = surface;
  impl->options = options;
  impl->requestedWidth = width;
  impl->requestedHeight = height;

  uint32_t formatCount = 0;
  PW_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physicalDevice(), surface, &formatCount, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(formatCount);
  PW_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physicalDevice(), surface, &formatCount, formats.data()));
  if (formats.empty()) return makeError("the window surface offers no pixel formats");
  // sRGB images with a UNORM view for the overlay where the device can (mutable
  // format); else UNORM images, the views' shaders encoding sRGB (presenter.h).
  const bool mutableFormat = ctx.swapchainMutableFormatSupported();
  impl->surfaceFormat = formats[0];
  for (const VkSurfaceFormatKHR& f : formats) {
    const bool wanted = mutableFormat ? unormOf(f.format) != VK_FORMAT_UNDEFINED : redBlueBytes(f.format) && !isSrgb(f.format);
    if (wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
      impl->surfaceFormat = f;
      break;
    }
  }
  impl->overlayFormat = impl->surfaceFormat.format;
  if (mutableFormat && unormOf(impl->surfaceFormat.format) != VK_FORMAT_UNDEFINED) {
    impl->overlayFormat = unormOf(impl->surfaceFormat.format);
  }
  uint32_t modeCount = 0;
  PW_VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx.physicalDevice(), surface, &modeCount, nullptr));
  std::vector<VkPresentModeKHR> modes(modeCount);
  PW_VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx.physicalDevice(), surface, &modeCount, modes.data()));
  const auto has = [&](VkPresentModeKHR m) { return std::find(modes.begin(), modes.end(), m) != modes.end(); };
  impl->presentMode = VK_PRESENT_MODE_FIFO_KHR;  // the one mode every surface has
  if (options.mode == PresentMode::kLowLatency) {
    if (has(VK_PRESENT_MODE_MAILBOX_KHR)) {
      impl->presentMode = VK_PRESENT_MODE_MAILBOX_KHR;
    } else if (has(VK_PRESENT_MODE_IMMEDIATE_KHR)) {
      impl->presentMode = VK_PRESENT_MODE_IMMEDIATE_KHR;
    }
  }

  PW_TRY(impl->createOverlayPass());
  auto pool = gpu::createFrameDescriptorPool(ctx, uint32_t(options.framesInFlight));
  if (!pool) return pool.error();
  impl->framePool = std::move(*pool);
  for (int i = 0; i < options.framesInFlight; ++i) {
    auto slot = gpu::createFrameSlot(ctx, *impl->renderer.pipelines, impl->framePool.get());
    if (!slot) return slot.error();
    impl->frames.push_back(std::move(*slot));
    VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    PW_VK_CHECK(vkCreateSemaphore(ctx.device(), &semInfo, nullptr, &semaphore));
    impl->imageAvailable.emplace_back(ctx.device(), semaphore);
  }
  PW_TRY(impl->recreateSwapchain());
  return std::unique_ptr<Presenter>(new Presenter(std::move(impl)));
}

void Presenter::resize(int width, int height) {
  if (width == impl_->requestedWidth && height == impl_->requestedHeight) return;
  impl_->requestedWidth = width;
  impl_->requestedHeight = height;
  impl_->needsRecreate = true;
}

Status Presenter::drawFrame(const Camera& camera, const FrameSettings& settings, const OverlayCallback& overlay) {
  SceneView view;
  view.scene = impl_->renderer.defaultScene;
  view.camera = camera;
  view.settings = settings;
  return drawFrame(std::vector<View>{view}, overlay);
}

Status Presenter::drawFrame(const std::vector<View>& views, const OverlayCallback& overlay, const glm::vec3& clearColor) {
  Impl& p = *impl_;
  const VkDevice device = p.context.device();
  if (p.needsRecreate || !p.swapchain) {
    PW_TRY(p.recreateSwapchain());
    if (p.needsRecreate) return {};  // minimised: nothing to draw into
  }
  // Before anything is acquired: a bad view is an error that leaves no image acquired.
  PW_TRY(p.recorder.prepare(p.renderer, views, p.extent));
  PW_TRY(p.renderer.uploads->collect());
  gpu::FrameSlot& slot = p.frames[p.frameIndex];
  PW_TRY(slot.waitAndReset(device));

  const VkSemaphore acquired = p.imageAvailable[p.frameIndex].get();
  uint32_t imageIndex = 0;
  const VkResult acquire = vkAcquireNextImageKHR(device, p.swapchain.get(), UINT64_MAX, acquired, VK_NULL_HANDLE, &imageIndex);
  if (acquire == VK_ERROR_OUT_OF_DATE_KHR) {
    p.needsRecreate = true;  // the semaphore was not signalled; skip this frame
    return {};
  }
  if (acquire == VK_SUBOPTIMAL_KHR) p.needsRecreate = true;  // draw it anyway, recreate after
  PW_VK_CHECK(acquire);
  SwapchainImage& image = p.images[imageIndex];

  const VkCommandBuffer cmd = slot.commands;
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  PW_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  FrameTarget target;
  target.image = image.image;
  target.view = image.view.get();
  if (p.msaaColor) {
    target.msaa = p.msaaColor->get();
    target.msaaView = p.msaaColor->view.get();
  }
  target.depth = p.depth->get();
  target.depthView = p.depth->view.get();
  target.format = p.surfaceFormat.format;
  target.extent = p.extent;
  target.encodeSrgbInShader = !isSrgb(p.surfaceFormat.format);
  const Status recorded = p.recorder.record(cmd, p.renderer, slot, target, clearColor);
  p.stats = p.recorder.stats();

  VkRenderPassBeginInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  passInfo.renderPass = p.overlayPass.get();
  passInfo.framebuffer = image.framebuffer.get();
  passInfo.renderArea = {{0, 0}, p.extent};
  vkCmdBeginRenderPass(cmd, &passInfo, VK_SUBPASS_CONTENTS_INLINE);
  if (overlay) overlay(cmd);
  vkCmdEndRenderPass(cmd);
  if (p.captureRequested && p.transferSource) PW_TRY(p.recordCapture(cmd, image.image, slot));
  PW_VK_CHECK(vkEndCommandBuffer(cmd));
  PW_TRY(recorded);

  const VkFence fence = slot.fence.get();
  PW_VK_CHECK(vkResetFences(device, 1, &fence));
  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = acquired;
  wait.stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.semaphore = image.renderFinished.get();
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = 1;
  submit.pWaitSemaphoreInfos = &wait;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  submit.signalSemaphoreInfoCount = 1;
  submit.pSignalSemaphoreInfos = &signal;
  PW_VK_CHECK(vkQueueSubmit2(p.context.queue(), 1, &submit, fence));

  const VkSemaphore finished = image.renderFinished.get();
  const VkSwapchainKHR swapchain = p.swapchain.get();
  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &finished;
  present.swapchainCount = 1;
  present.pSwapchains = &swapchain;
  present.pImageIndices = &imageIndex;
  const VkResult presented = vkQueuePresentKHR(p.context.queue(), &present);
  p.frameIndex = (p.frameIndex + 1) % uint32_t(p.frames.size());
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
    p.needsRecreate = true;
  } else {
    PW_VK_CHECK(presented);
  }
  ++p.presented;
  return {};
}

Status Presenter::Impl::recordCapture(VkCommandBuffer cmd, VkImage image, gpu::FrameSlot& slot) {
  Capture c;
  c.extent = extent;
  c.slot = static_cast<size_t>(&slot - frames.data());
  auto buffer = gpu::createBuffer(context, VkDeviceSize{extent.width} * extent.height * 4,
                                  VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::kReadback);
  if (!buffer) return buffer.error();
  c.buffer = std::make_shared<gpu::Buffer>(std::move(*buffer));
  // After the overlay pass the image is PRESENT_SRC, its writes made visible to
  // transfers by the pass's external dependency; copied, it goes back for the present.
  gpu::transitionImage(cmd, {image, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                             VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                             VK_ACCESS_2_TRANSFER_READ_BIT});
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, c.buffer->get(), 1, &region);
  gpu::transitionImage(cmd, {image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                             VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE});
  gpu::copyToHostBarrier(cmd, c.buffer->get());
  slot.inFlight.push_back(c.buffer);  // an untaken capture replaced by a newer one lives until this frame is done
  capture = std::move(c);
  captureRequested = false;
  return {};
}

void Presenter::captureNextFrame() { impl_->captureRequested = true; }

Result<Image> Presenter::takeCapture() {
  Impl& p = *impl_;
  if (!p.capture) {
    if (!p.transferSource) {
      return makeError("this window's swapchain (format " + std::to_string(int(p.surfaceFormat.format)) +
                       ") cannot be copied from; captures are not available");
    }
    return makeError(p.captureRequested ? "no frame has been drawn since captureNextFrame() (is the window minimised?)"
                                        : "no capture was asked for: call captureNextFrame() before drawFrame()");
  }
  const Capture c = std::move(*p.capture);
  p.capture.reset();
  const VkFence fence = p.frames[c.slot].fence.get();
  PW_VK_CHECK(vkWaitForFences(p.context.device(), 1, &fence, VK_TRUE, UINT64_MAX));
  PW_TRY(gpu::invalidate(p.context, *c.buffer));
  const auto [red, blue] = *redBlueBytes(p.surfaceFormat.format);
  Image out;
  out.width = int(c.extent.width);
  out.height = int(c.extent.height);
  out.rgba.resize(size_t(out.width) * size_t(out.height) * 4);
  const auto* from = static_cast<const uint8_t*>(c.buffer->mapped);
  for (size_t i = 0; i < out.rgba.size(); i += 4) {
    out.rgba[i] = from[i + red];
    out.rgba[i + 1] = from[i + 1];
    out.rgba[i + 2] = from[i + blue];
    out.rgba[i + 3] = 255;  // the window is opaque whatever alpha the overlay left
  }
  return out;
}

Status Presenter::waitIdle() {
  for (gpu::FrameSlot& slot : impl_->frames) {
    const VkFence fence = slot.fence.get();
    PW_VK_CHECK(vkWaitForFences(impl_->context.device(), 1, &fence, VK_TRUE, UINT64_MAX));
    slot.inFlight.clear();
  }
  return {};
}

VkRenderPass Presenter::overlayRenderPass() const { return impl_->overlayPass.get(); }
uint32_t Presenter::imageCount() const { return static_cast<uint32_t>(impl_->images.size()); }
uint32_t Presenter::minImageCount() const { return impl_->minImageCount; }
VkFormat Presenter::format() const { return impl_->surfaceFormat.format; }
VkExtent2D Presenter::extent() const { return impl_->extent; }
uint64_t Presenter::framesPresented() const { return impl_->presented; }
FrameStats Presenter::lastFrameStats() const { return impl_->stats; }

}  // namespace pw::engine
