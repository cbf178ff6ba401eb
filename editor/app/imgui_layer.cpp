#include "editor/app/imgui_layer.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <algorithm>
#include <atomic>
#include <cfloat>

#include "editor/app/window.h"
#include "engine/gpu/vk_check.h"
#include "engine/vrml/vrml_text.h"

namespace pw::app {
namespace {

constexpr float kFontSizePx = 14.0f;

// ImGui's CheckVkResultFn takes no user data, so the first failure is kept here (one
// ImGui context per process) and turned into an error by ImGuiLayer::status().
std::atomic<int> firstFailure{VK_SUCCESS};

void checkVkResult(VkResult result) {
  if (result < 0) {
    int expected = VK_SUCCESS;
    firstFailure.compare_exchange_strong(expected, result);
  }
}

}  // namespace

Result<std::unique_ptr<ImGuiLayer>> ImGuiLayer::create(Window& window, engine::Renderer& renderer,
                                                       engine::Presenter& presenter) {
  std::unique_ptr<ImGuiLayer> layer(new ImGuiLayer());
  firstFailure = VK_SUCCESS;
  const VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
  const VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, nullptr,
                                            VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT, 16, 1, &poolSize};
  VkDescriptorPool pool = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateDescriptorPool(renderer.device(), &poolInfo, nullptr, &pool));
  layer->pool_ = engine::gpu::OwnedDescriptorPool(renderer.device(), pool);

  ImGui::CreateContext();
  layer->context_ = true;
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  ImGui::StyleColorsDark();
  // Monospaced, as ImGui's own font: overlays line text up in columns with spaces.
  if (const auto font = engine::vrml::fontFile("TYPEWRITER", "PLAIN"); font && font->stem() == "DejaVuSansMono") {
    io.Fonts->AddFontFromFileTTF(font->c_str(), kFontSizePx);
  }
  if (io.Fonts->Fonts.empty()) io.Fonts->AddFontDefault();

  // No callbacks: the backend's would write io.KeysDown as events arrive. It is told of
  // nothing else either (focus, the pointer entering): beginFrame sets the pointer,
  // buttons, keys and modifiers itself each frame, and GLFW releases what was held when
  // the window loses the focus.
  layer->window_ = window.handle();
  layer->glfw_ = ImGui_ImplGlfw_InitForVulkan(window.handle(), false);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = renderer.instance();
  info.PhysicalDevice = renderer.physicalDevice();
  info.Device = renderer.device();
  info.QueueFamily = renderer.queueFamily();
  info.Queue = renderer.queue();
  info.DescriptorPool = layer->pool_.get();
  info.MinImageCount = std::max(2u, presenter.minImageCount());
  info.ImageCount = std::max(info.MinImageCount, presenter.imageCount());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = checkVkResult;
  layer->vulkan_ = ImGui_ImplVulkan_Init(&info, presenter.overlayRenderPass());
  if (!layer->glfw_ || !layer->vulkan_) return makeError("cannot start the ImGui overlay");
  bool uploaded = false;
  PW_TRY(renderer.submitAndWait([&](VkCommandBuffer cmd) { uploaded = ImGui_ImplVulkan_CreateFontsTexture(cmd); }));
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  if (!uploaded) return makeError("cannot upload the ImGui overlay's font");
  PW_TRY(layer->status());
  return layer;
}

ImGuiLayer::~ImGuiLayer() {
  if (vulkan_) ImGui_ImplVulkan_Shutdown();
  if (glfw_) ImGui_ImplGlfw_Shutdown();
  if (context_) ImGui::DestroyContext();
}

void ImGuiLayer::beginFrame(const UiFrameInput& input, bool live) {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();  // the display size and time; its polled mouse is replaced below
  ImGuiIO& io = ImGui::GetIO();
  const bool held = std::find(input.buttons.begin(), input.buttons.end(), true) != input.buttons.end();
  const bool outside = live && !held && window_ && !glfwGetWindowAttrib(window_, GLFW_HOVERED);
  io.MousePos = input.cursorPx && !outside ? ImVec2(float(input.cursorPx->x), float(input.cursorPx->y))
                                           : ImVec2(-FLT_MAX, -FLT_MAX);
  static_assert(sizeof(io.MouseDown) / sizeof(io.MouseDown[0]) == std::tuple_size_v<decltype(input.buttons)>);
  std::copy(input.buttons.begin(), input.buttons.end(), io.MouseDown);
  io.MouseWheel = float(input.wheel.y);
  io.MouseWheelH = float(input.wheel.x);
  static_assert(sizeof(io.KeysDown) / sizeof(io.KeysDown[0]) == std::tuple_size_v<decltype(input.keys)>);
  std::copy(input.keys.begin(), input.keys.end(), io.KeysDown);
  const auto& keys = input.keys;
  io.KeyCtrl = keys[GLFW_KEY_LEFT_CONTROL] || keys[GLFW_KEY_RIGHT_CONTROL];
  io.KeyShift = keys[GLFW_KEY_LEFT_SHIFT] || keys[GLFW_KEY_RIGHT_SHIFT];
  io.KeyAlt = keys[GLFW_KEY_LEFT_ALT] || keys[GLFW_KEY_RIGHT_ALT];
  io.KeySuper = keys[GLFW_KEY_LEFT_SUPER] || keys[GLFW_KEY_RIGHT_SUPER];
  for (unsigned c : input.characters) io.AddInputCharacter(c);
  ImGui::NewFrame();
}

void ImGuiLayer::endFrame() { ImGui::Render(); }

void ImGuiLayer::record(VkCommandBuffer cmd) const { ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd); }

Status ImGuiLayer::status() const {
  const int failure = firstFailure.load();
  if (failure == VK_SUCCESS) return {};
  return makeError(std::string("the ImGui overlay's Vulkan backend failed: ") +
                   engine::gpu::vkResultName(static_cast<VkResult>(failure)));
}

}  // namespace pw::app
