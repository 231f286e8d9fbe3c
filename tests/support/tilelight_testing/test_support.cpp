#include "tilelight_testing/test_support.h"

#include "tilelight_testing/context_test_seam.h"

#include <testsupport/scratch_dir.h>

#include <cstdlib>
#include <string_view>

namespace tilelight::test {

void VulkanTest::SetUp() {
  ContextOptions options;
  options.validation = true;
  // Synchronization validation is slow; TILELIGHT_SYNC_VALIDATION=1 turns it on for a run.
  const char* sync = std::getenv("TILELIGHT_SYNC_VALIDATION");
  options.synchronization_validation = sync != nullptr && std::string_view(sync) == "1";
  context_ = std::make_unique<Context>(options);
  log_ = ContextTestSeam::shared_validation_log(*context_);
  pool_ = std::make_unique<CommandPool>(*context_, "test pool");
}

void VulkanTest::TearDown() {
  pool_.reset();
  context_.reset();
  if (log_) {
    EXPECT_EQ(log_->count(), 0u) << log_->summary();
  }
}

std::filesystem::path scratch_dir() { return testsupport::scratch_dir(TILELIGHT_TEST_SCRATCH); }

}  // namespace tilelight::test
