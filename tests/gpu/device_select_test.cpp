#include "engine/gpu/device_select.h"

#include <cstdlib>

#include <gtest/gtest.h>

namespace pw::engine::gpu {
namespace {

const DeviceCandidate kLavapipe{"llvmpipe", VK_PHYSICAL_DEVICE_TYPE_CPU, VK_API_VERSION_1_3, ""};
const DeviceCandidate kIntegrated{"Intel UHD", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, VK_API_VERSION_1_3, ""};
const DeviceCandidate kDiscrete{"RTX", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_3, ""};
const DeviceCandidate kOldDiscrete{"Old GPU", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_1, "Vulkan 1.3"};

TEST(DeviceSelect, PrefersDiscreteThenIntegratedThenCpu) {
  EXPECT_EQ(*chooseDevice({kLavapipe, kIntegrated, kDiscrete}, false), 2u);
  EXPECT_EQ(*chooseDevice({kLavapipe, kIntegrated}, false), 1u);
  EXPECT_EQ(*chooseDevice({kLavapipe}, false), 0u);
}

TEST(DeviceSelect, ForcedCpuPicksLavapipeEvenBesideAGpu) {
  EXPECT_EQ(*chooseDevice({kDiscrete, kLavapipe}, true), 1u);
}

TEST(DeviceSelect, DevicesLackingFeaturesAreSkippedNotFatal) {
  EXPECT_EQ(*chooseDevice({kOldDiscrete, kLavapipe}, false), 1u);
}

TEST(DeviceSelect, ErrorsSayWhatIsMissing) {
  auto none = chooseDevice({}, false);
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.message().find("mesa-vulkan-drivers"), std::string::npos);
  auto old = chooseDevice({kOldDiscrete}, false);
  ASSERT_FALSE(old.ok());
  EXPECT_NE(old.message().find("Old GPU lacks Vulkan 1.3"), std::string::npos) << old.message();
  auto noCpu = chooseDevice({kDiscrete}, true);
  ASSERT_FALSE(noCpu.ok());
  EXPECT_NE(noCpu.message().find("RTX (discrete GPU)"), std::string::npos) << noCpu.message();
}

TEST(DeviceSelect, EnvironmentVariable) {
  ::setenv("PW_DEVICE", "cpu", 1);
  EXPECT_TRUE(*cpuDeviceRequestedByEnvironment());
  ::setenv("PW_DEVICE", "", 1);
  EXPECT_FALSE(*cpuDeviceRequestedByEnvironment());
  ::setenv("PW_DEVICE", "gpu0", 1);
  auto bad = cpuDeviceRequestedByEnvironment();
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("PW_DEVICE=gpu0"), std::string::npos);
  ::setenv("PW_DEVICE", "cpu", 1);
}

}  // namespace
}  // namespace pw::engine::gpu
