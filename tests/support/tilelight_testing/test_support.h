#pragma once
// Shared fixtures for the runtime tests: a lavapipe context with validation that must stay
// silent, and a per-test scratch folder.

#include "tilelight/vulkan/commands.h"
#include "tilelight/vulkan/context.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

namespace tilelight::test {

// A fresh validated context per test. Vulkan objects a test creates must be locals of the test
// body (destroyed before TearDown destroys the context). TearDown fails the test if the layer
// reported anything, including messages emitted while the device is destroyed (leaks).
class VulkanTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  Context& context() { return *context_; }
  CommandPool& pool() { return *pool_; }

 private:
  std::unique_ptr<Context> context_;
  std::unique_ptr<CommandPool> pool_;
  std::shared_ptr<const ValidationLog> log_;
};

// An empty folder for the current test: <build>/scratch/<suite>.<test>.
std::filesystem::path scratch_dir();

}  // namespace tilelight::test
