#include "tests/gpu/renderer_fixture.h"

namespace pw::test {

std::unique_ptr<engine::Renderer>& RendererTest::shared() {
  static std::unique_ptr<engine::Renderer> renderer;
  return renderer;
}

void RendererTest::SetUpTestSuite() {
  if (shared()) return;
  engine::RendererOptions options;
  options.forceCpu = true;
  options.validation = engine::RendererOptions::Validation::kOn;
  auto created = engine::Renderer::create(options);
  ASSERT_TRUE(created.ok()) << created.message();
  shared() = std::move(*created);
}

void RendererTest::SetUp() {
  ASSERT_TRUE(shared()) << "the renderer could not be created";
  ASSERT_TRUE(renderer().validationEnabled());
  ASSERT_TRUE(renderer().isCpuDevice()) << renderer().deviceName();
  messagesBefore_ = renderer().validationMessageCount();
}

void RendererTest::TearDown() {
  if (!shared()) return;
  EXPECT_EQ(renderer().validationMessageCount(), messagesBefore_) << validationReport(renderer());
}

std::string validationReport(const engine::Renderer& renderer) {
  std::string report = "validation messages:";
  for (const std::string& m : renderer.validationMessages()) report += "\n  " + m;
  return report;
}

}  // namespace pw::test
