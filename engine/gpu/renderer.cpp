#include "engine/gpu/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "engine/gpu/barriers.h"
#include "engine/gpu/renderer_impl.h"
#include "engine/gpu/view_recorder.h"
#include "engine/gpu/vk_check.h"

namespace pw::engine {
namespace {

constexpr uint64_t kMaxTargetBytes = uint64_t{2} << 30;  // 2 GiB of colour, depth and read-back

struct ValidationChoice {
  bool wanted = false;
  bool required = false;  // asked for by name (kOn, PW_VALIDATION=1): a missing layer is an error
};

ValidationChoice validationChoice(RendererOptions::Validation v) {
  if (v != RendererOptions::Validation::kDefault) {
    const bool on = v == RendererOptions::Validation::kOn;
    return {on, on};
  }
  // PW_VALIDATION=1 is how tests and CI ask for validation: running without the layer
  // would let them pass unvalidated, so its absence is an error there too.
  const char* env = std::getenv("PW_VALIDATION");
  if (env && *env) {
    const bool on = std::strcmp(env, "0") != 0;
    return {on, on};
  }
#ifdef NDEBUG
  return {false, false};
#else
  return {true, false};  // Debug builds: a missing layer is a note
#endif
}

std::string sampleCountList(VkSampleCountFlags counts) {
  std::string list;
  for (int s = 1; s <= 64; s *= 2) {
    if (counts & s) list += (list.empty() ? "" : ", ") + std::to_string(s);
  }
  return list;
}

Result<OffscreenTargets> createOffscreenTargets(const gpu::Context& context, uint32_t width, uint32_t height,
                                                VkSampleCountFlagBits samples) {
  OffscreenTargets t;
  t.width = width;
  t.height = height;
  gpu::ImageSpec color;
  color.format = VK_FORMAT_R8G8B8A8_SRGB;
  color.width = width;
  color.height = height;
  color.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  auto colorImage = gpu::createImage(context, color);
  if (!colorImage) return colorImage.error();
  t.color = std::move(*colorImage);
  gpu::ImageSpec msaa = color;
  msaa.samples = samples;
  msaa.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  msaa.transient = true;
  if (samples != VK_SAMPLE_COUNT_1_BIT) {
    auto msaaImage = gpu::createImage(context, msaa);
    if (!msaaImage) return msaaImage.error();
    t.msaa = std::move(*msaaImage);
  }
  gpu::ImageSpec depth = msaa;
  depth.format = gpu::kDepthFormat;
  depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  depth.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  auto depthImage = gpu::createImage(context, depth);
  if (!depthImage) return depthImage.error();
  t.depth = std::move(*depthImage);
  auto readback = gpu::createBuffer(context, VkDeviceSize{width} * height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    gpu::MemoryUse::kReadback);
  if (!readback) return readback.error();
  t.readback = std::move(*readback);
  return t;
}

// Copies level 0 of `image` (in `layout`, last written or read at `stages`) into
// `buffer` and makes it visible to the host; the image ends in `after`.
void recordReadback(VkCommandBuffer cmd, VkImage image, VkExtent2D extent, VkImageLayout layout,
                    VkPipelineStageFlags2 stages, VkAccessFlags2 writes, VkBuffer buffer, VkImageLayout after) {
  gpu::transitionImage(cmd, {image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, stages, writes,
                             VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT});
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
  if (after != VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL) {
    gpu::transitionImage(cmd, {image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, after, VK_PIPELINE_STAGE_2_COPY_BIT,
                               VK_ACCESS_2_NONE, stages, VK_ACCESS_2_NONE});
  }
  gpu::copyToHostBarrier(cmd, buffer);
}

Image imageFromReadback(const gpu::Buffer& buffer, uint32_t width, uint32_t height) {
  Image image;
  image.width = int(width);
  image.height = int(height);
  image.rgba.resize(size_t(width) * size_t(height) * 4);
  std::memcpy(image.rgba.data(), buffer.mapped, image.rgba.size());
  return image;
}

}  // namespace

Status checkFrameSize(const gpu::Context& context, int width, int height, VkSampleCountFlagBits samples) {
  const int64_t maxSide = context.properties().limits.maxImageDimension2D;
  if (width < 1 || height < 1 || width > maxSide || height > maxSide) {
    return makeError("frame size " + std::to_string(width) + "x" + std::to_string(height) +
                     " is out of range: each side must be 1.." + std::to_string(maxSide) + " pixels on " +
                     context.properties().deviceName);
  }
  // Colour and depth per sample (4 + 4 bytes), the resolved image and the read-back copy.
  const uint64_t bytes = uint64_t(width) * uint64_t(height) * (uint64_t(samples) * 8 + 8);
  if (bytes > kMaxTargetBytes) {
    return makeError("frame size " + std::to_string(width) + "x" + std::to_string(height) + " with " +
                     std::to_string(int(samples)) + "x MSAA needs " + std::to_string(bytes >> 20) +
                     " MiB of render targets, more than the 2048 MiB allowed; use a smaller size or fewer MSAA samples");
  }
  return {};
}

Status checkCamera(const Camera& camera) {
  const glm::vec4 q(camera.orientation.x, camera.orientation.y, camera.orientation.z, camera.orientation.w);
  const bool finite = std::isfinite(camera.position.x) && std::isfinite(camera.position.y) &&
                      std::isfinite(camera.position.z) && std::isfinite(q.x) && std::isfinite(q.y) &&
                      std::isfinite(q.z) && std::isfinite(q.w) && std::isfinite(camera.fieldOfViewRad);
  if (!finite || glm::length(q) < 1e-6f) return makeError("the camera's position or orientation is not a finite number");
  if (!(camera.nearM > 0.0f) || !(camera.farM > camera.nearM) || !std::isfinite(camera.farM)) {
    return makeError("the camera's clip distances must satisfy 0 < near < far");
  }
  if (camera.intrinsics && !(camera.intrinsics->focalXPx > 0 && camera.intrinsics->focalYPx > 0)) {
    return makeError("the camera's focal lengths must be positive");
  }
  return {};
}

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() {
  // Offscreen frames are waited for as they are made; nothing can be in flight here
  // unless a Presenter outlived us, which its contract forbids.
}

Result<std::unique_ptr<Renderer>> Renderer::create(const RendererOptions& options) {
  auto impl = std::make_unique<Impl>();
  gpu::ContextOptions contextOptions;
  contextOptions.forceCpu = options.forceCpu;
  const ValidationChoice validation = validationChoice(options.validation);
  contextOptions.validation = validation.wanted;
  contextOptions.validationRequired = validation.required;
  contextOptions.instanceExtensions = options.instanceExtensions;
  auto context = gpu::Context::create(contextOptions);
  if (!context) return context.error();
  impl->context = std::move(*context);
  const gpu::Context& ctx = *impl->context;

  const bool cpuDevice = ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const bool keepFrameRate = options.profile == RenderProfile::kInteractive && cpuDevice;
  const int samples = options.msaaSamples > 0 ? options.msaaSamples : keepFrameRate ? 1 : 4;
  const VkSampleCountFlags supported =
      ctx.properties().limits.framebufferColorSampleCounts & ctx.properties().limits.framebufferDepthSampleCounts;
  if (samples < 1 || samples > 64 || (samples & (samples - 1)) != 0 || !(supported & samples)) {
    return makeError("MSAA " + std::to_string(samples) + "x is not available on " + ctx.properties().deviceName +
                     "; choose one of " + sampleCountList(supported));
  }
  impl->samples = static_cast<VkSampleCountFlagBits>(samples);

  VkFormatProperties depthProps;
  vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice(), gpu::kDepthFormat, &depthProps);
  if (!(depthProps.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)) {
    return makeError(std::string(ctx.properties().deviceName) + " cannot render to 32-bit float depth; use PW_DEVICE=cpu");
  }

  auto pipelines = gpu::PipelineLibrary::create(ctx, !keepFrameRate, options.perVertexLighting.value_or(keepFrameRate));
  if (!pipelines) return pipelines.error();
  impl->pipelines = std::move(*pipelines);
  auto imagePipelines = gpu::ImagePipelines::create(ctx);
  if (!imagePipelines) return imagePipelines.error();
  impl->imagePipelines = std::move(*imagePipelines);
  impl->uploads = std::make_unique<gpu::UploadQueue>(ctx);
  auto pool = gpu::createFrameDescriptorPool(ctx, 1);
  if (!pool) return pool.error();
  impl->framePool = std::move(*pool);
  auto frame = gpu::createFrameSlot(ctx, *impl->pipelines, impl->framePool.get());
  if (!frame) return frame.error();
  impl->frame = std::move(*frame);
  std::unique_ptr<Renderer> renderer(new Renderer(std::move(impl)));
  auto defaultScene = renderer->addScene(Scene{});
  if (!defaultScene) return defaultScene.error();
  renderer->impl_->defaultScene = *defaultScene;
  return renderer;
}

Status Renderer::setScene(const Scene& scene) { return replaceScene(impl_->defaultScene, scene); }

StagedScene::StagedScene(std::unique_ptr<gpu::SceneStaging> staging) : staging_(std::move(staging)) {}
StagedScene::StagedScene(StagedScene&&) noexcept = default;
StagedScene& StagedScene::operator=(StagedScene&&) noexcept = default;
StagedScene::~StagedScene() = default;

Result<StagedScene> Renderer::stageScene(const Scene& scene) const {
  auto staged = gpu::GpuScene::stage(*impl_->context, *impl_->pipelines, scene);
  if (!staged) return staged.error();
  return StagedScene(std::make_unique<gpu::SceneStaging>(std::move(*staged)));
}

Result<SceneHandle> Renderer::addScene(const Scene& scene) {
  auto staged = stageScene(scene);
  if (!staged) return staged.error();
  return addScene(std::move(*staged));
}

Status Renderer::replaceScene(SceneHandle handle, const Scene& scene) {
  if (!impl_->scenes.contains(handle.id)) {
    return makeError("scene handle " + std::to_string(handle.id) + " names no scene (never added, or removed)");
  }
  auto staged = stageScene(scene);
  if (!staged) return staged.error();
  return replaceScene(handle, std::move(*staged));
}

Result<SceneHandle> Renderer::addScene(StagedScene staged) {
  Impl& s = *impl_;
  if (!staged.staging_) return makeError("this staged scene was already used");
  PW_TRY(s.uploads->collect());
  auto uploaded = gpu::GpuScene::upload(*s.context, *s.pipelines, std::move(*staged.staging_), *s.uploads);
  staged.staging_.reset();
  if (!uploaded) return uploaded.error();
  const SceneHandle handle{s.nextHandle++};
  s.scenes.emplace(handle.id, std::move(*uploaded));
  return handle;
}

Status Renderer::replaceScene(SceneHandle handle, StagedScene staged) {
  Impl& s = *impl_;
  const auto found = s.scenes.find(handle.id);
  if (found == s.scenes.end()) return makeError("scene handle " + std::to_string(handle.id) + " names no scene (never added, or removed)");
  if (!staged.staging_) return makeError("this staged scene was already used");
  PW_TRY(s.uploads->collect());
  auto uploaded = gpu::GpuScene::upload(*s.context, *s.pipelines, std::move(*staged.staging_), *s.uploads);
  staged.staging_.reset();
  if (!uploaded) return uploaded.error();
  found->second = std::move(*uploaded);  // frames still drawing the old one keep it alive
  return {};
}

Status Renderer::removeScene(SceneHandle handle) {
  Impl& s = *impl_;
  if (handle == s.defaultScene) return makeError("the default scene cannot be removed; setScene(Scene{}) empties it");
  if (s.scenes.erase(handle.id) == 0) return makeError("scene handle " + std::to_string(handle.id) + " names no scene (never added, or removed)");
  return {};
}

SceneHandle Renderer::defaultScene() const { return impl_->defaultScene; }

Result<ImageHandle> Renderer::addImage(const Image& image) {
  Impl& s = *impl_;
  PW_TRY(s.uploads->collect());
  auto uploaded = gpu::ViewImage::upload(*s.context, *s.imagePipelines, image, *s.uploads);
  if (!uploaded) return uploaded.error();
  const ImageHandle handle{s.nextHandle++};
  s.images.emplace(handle.id, std::move(*uploaded));
  return handle;
}

Result<ImageHandle> Renderer::addRenderTarget(int width, int height) {
  Impl& s = *impl_;
  PW_TRY(checkFrameSize(*s.context, width, height, s.samples));
  PW_TRY(s.uploads->collect());
  auto target = gpu::ViewImage::renderTarget(*s.context, *s.imagePipelines, uint32_t(width), uint32_t(height),
                                             s.samples, *s.uploads);
  if (!target) return target.error();
  const ImageHandle handle{s.nextHandle++};
  s.images.emplace(handle.id, std::move(*target));
  return handle;
}

Status Renderer::removeImage(ImageHandle handle) {
  if (impl_->images.erase(handle.id) == 0) {
    return makeError("image handle " + std::to_string(handle.id) + " names no image (never added, or removed)");
  }
  return {};
}

Result<glm::ivec2> Renderer::imageSize(ImageHandle handle) const {
  const auto found = impl_->images.find(handle.id);
  if (found == impl_->images.end()) return makeError("image handle " + std::to_string(handle.id) + " names no image (never added, or removed)");
  return glm::ivec2(int(found->second->width()), int(found->second->height()));
}

Result<Image> Renderer::readImage(ImageHandle handle) {
  Impl& s = *impl_;
  const auto found = s.images.find(handle.id);
  if (found == s.images.end()) return makeError("image handle " + std::to_string(handle.id) + " names no image (never added, or removed)");
  const gpu::ViewImage& image = *found->second;
  auto buffer = gpu::createBuffer(*s.context, VkDeviceSize{image.width()} * image.height() * 4,
                                  VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::kReadback);
  if (!buffer) return buffer.error();
  // Waiting for this submission waits for everything queued before it (frames drawing
  // into a render target, the image's upload).
  PW_TRY(s.context->submitAndWait([&](VkCommandBuffer cmd) {
    recordReadback(cmd, image.color.get(), {image.width(), image.height()}, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
                       VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT,
                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT, buffer->get(),
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  }));
  PW_TRY(gpu::invalidate(*s.context, *buffer));
  return imageFromReadback(*buffer, image.width(), image.height());
}

Result<Image> Renderer::renderToImage(const Camera& camera, int width, int height, const FrameSettings& settings) {
  SceneView view;
  view.scene = impl_->defaultScene;
  view.camera = camera;
  view.settings = settings;
  return renderViews({view}, width, height);
}

Result<Image> Renderer::renderViews(const std::vector<View>& views, int width, int height, const glm::vec3& clearColor) {
  Impl& s = *impl_;
  const gpu::Context& ctx = *s.context;
  PW_TRY(checkFrameSize(ctx, width, height, s.samples));
  PW_TRY(s.recorder.prepare(s, views, {uint32_t(width), uint32_t(height)}));
  PW_TRY(s.uploads->collect());
  if (!s.offscreen || s.offscreen->width != uint32_t(width) || s.offscreen->height != uint32_t(height)) {
    PW_TRY(s.frame.waitAndReset(ctx.device()));  // the old targets may be in use
    s.offscreen.reset();
    auto targets = createOffscreenTargets(ctx, uint32_t(width), uint32_t(height), s.samples);
    if (!targets) return targets.error();
    s.offscreen = std::move(*targets);
  }
  OffscreenTargets& t = *s.offscreen;
  gpu::FrameSlot& frame = s.frame;
  PW_TRY(frame.waitAndReset(ctx.device()));

  const VkCommandBuffer cmd = frame.commands;
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  PW_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  FrameTarget target;
  target.image = t.color.get();
  target.view = t.color.view.get();
  if (t.msaa) {
    target.msaa = t.msaa->get();
    target.msaaView = t.msaa->view.get();
  }
  target.depth = t.depth.get();
  target.depthView = t.depth.view.get();
  target.format = t.color.spec.format;
  target.extent = {uint32_t(width), uint32_t(height)};
  const Status recorded = s.recorder.record(cmd, s, frame, target, clearColor);
  s.stats = s.recorder.stats();
  recordReadback(cmd, t.color.get(), target.extent, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                 VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, t.readback.get(),
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);  // the next frame starts from UNDEFINED
  PW_VK_CHECK(vkEndCommandBuffer(cmd));
  PW_TRY(recorded);

  const VkFence fence = frame.fence.get();
  PW_VK_CHECK(vkResetFences(ctx.device(), 1, &fence));
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  PW_VK_CHECK(vkQueueSubmit2(ctx.queue(), 1, &submit, fence));
  PW_TRY(frame.waitAndReset(ctx.device()));
  PW_TRY(gpu::invalidate(ctx, t.readback));
  return imageFromReadback(t.readback, uint32_t(width), uint32_t(height));
}

Status Renderer::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
  return impl_->context->submitAndWait(record);
}

size_t Renderer::validationMessageCount() const { return impl_->context->validationLog().count(); }
std::vector<std::string> Renderer::validationMessages() const { return impl_->context->validationLog().messages(); }
bool Renderer::validationEnabled() const { return impl_->context->validationEnabled(); }

Status Renderer::validationStatus() const {
  const size_t count = validationMessageCount();
  if (count == 0) return {};
  const std::vector<std::string> messages = validationMessages();
  std::string first = messages.empty() ? std::string("(not kept)") : messages.front();
  std::replace_if(first.begin(), first.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
  return makeError(std::to_string(count) + " Vulkan validation message" + (count == 1 ? "" : "s") +
                   " (validation is on); the first: " + first);
}
std::string Renderer::deviceName() const { return impl_->context->properties().deviceName; }
bool Renderer::isCpuDevice() const { return impl_->context->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
int Renderer::msaaSamples() const { return static_cast<int>(impl_->samples); }
bool Renderer::anisotropicFiltering() const { return impl_->pipelines->anisotropic(); }
bool Renderer::perVertexLighting() const { return impl_->pipelines->vertexLighting(); }
FrameStats Renderer::lastFrameStats() const { return impl_->stats; }
std::vector<std::string> Renderer::notes() const { return impl_->context->notes(); }
VkInstance Renderer::instance() const { return impl_->context->instance(); }
VkPhysicalDevice Renderer::physicalDevice() const { return impl_->context->physicalDevice(); }
VkDevice Renderer::device() const { return impl_->context->device(); }
VkQueue Renderer::queue() const { return impl_->context->queue(); }
uint32_t Renderer::queueFamily() const { return impl_->context->queueFamily(); }

}  // namespace pw::engine
