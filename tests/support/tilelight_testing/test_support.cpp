#include "tilelight_testing/test_support.h"

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
  log_ = context_->shared_validation_log();
  pool_ = std::make_unique<CommandPool>(*context_, "test pool");
}

void VulkanTest::TearDown() {
  pool_.reset();
  context_.reset();
  if (log_) {
    EXPECT_EQ(log_->count(), 0u) << log_->summary();
  }
}

std::filesystem::path scratch_dir() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir =
      std::filesystem::path(TILELIGHT_TEST_SCRATCH) / (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace tilelight::test
