// A Renderer on the CPU device (lavapipe) with validation on, shared by the tests of
// one binary (creating one costs a second on lavapipe), and the check that every GPU
// test ends with no validation message.
#pragma once

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "engine/gpu/renderer.h"

namespace pw::test {

class RendererTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite();
  static void TearDownTestSuite() { shared().reset(); }
  void SetUp() override;
  void TearDown() override;

  static engine::Renderer& renderer() { return *shared(); }
  static std::unique_ptr<engine::Renderer>& shared();

 private:
  size_t messagesBefore_ = 0;
};

// Every validation message the renderer has collected, one per line.
std::string validationReport(const engine::Renderer& renderer);

}  // namespace pw::test
