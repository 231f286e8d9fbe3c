// Handle: move-only ownership, exactly-once destruction.
#include "tilelight/vulkan/handle.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace tilelight {
namespace {

struct RecordingDeleter {
  std::vector<VkFence>* destroyed = nullptr;
  void operator()(VkFence fence) const { destroyed->push_back(fence); }
};

VkFence fake(std::uintptr_t value) { return reinterpret_cast<VkFence>(value); }

TEST(Handle, DestroysOnceAndMovesOwnership) {
  std::vector<VkFence> destroyed;
  {
    Handle<VkFence, RecordingDeleter> a(fake(1), {&destroyed});
    Handle<VkFence, RecordingDeleter> b(std::move(a));
    EXPECT_FALSE(a);
    EXPECT_EQ(b.get(), fake(1));
    Handle<VkFence, RecordingDeleter> c(fake(2), {&destroyed});
    c = std::move(b);  // destroys 2, takes 1
    EXPECT_EQ(destroyed, std::vector<VkFence>{fake(2)});
    EXPECT_EQ(c.get(), fake(1));
  }
  EXPECT_EQ(destroyed, (std::vector<VkFence>{fake(2), fake(1)}));
}

TEST(Handle, ReleaseGivesUpOwnership) {
  std::vector<VkFence> destroyed;
  {
    Handle<VkFence, RecordingDeleter> a(fake(3), {&destroyed});
    EXPECT_EQ(a.release(), fake(3));
    EXPECT_FALSE(a);
  }
  EXPECT_TRUE(destroyed.empty());
}

static_assert(!std::is_copy_constructible_v<Handle<VkFence, RecordingDeleter>>);
static_assert(!std::is_copy_assignable_v<Handle<VkFence, RecordingDeleter>>);
static_assert(std::is_nothrow_move_constructible_v<Handle<VkFence, RecordingDeleter>>);

}  // namespace
}  // namespace tilelight
