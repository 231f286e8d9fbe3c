// What tilelight prints when a run fails: the stage, the cause, and a hint for the failures a
// user can do something about. Every exception type the runtime, the driver or the C++ library
// can throw has a message; none ends the program without one.
#include "tilelight/app/failure.h"
#include "tilelight/vulkan/error.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>

namespace tilelight::test {
namespace {

using app::failure_message;

TEST(FailureMessage, VulkanOutOfMemoryNamesTheStageTheObjectAndAWayOut) {
  const auto error = std::make_exception_ptr(
      VulkanError(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory", "G-buffer RT0 (albedo, specular)"));
  EXPECT_EQ(failure_message("creating the renderer (16384x16384)", error),
            "creating the renderer (16384x16384): vkAllocateMemory failed for G-buffer RT0 (albedo, specular): "
            "VK_ERROR_OUT_OF_DEVICE_MEMORY (out of memory: try a smaller --width/--height or fewer --msaa samples)");
}

TEST(FailureMessage, DeviceLostNamesTheFrame) {
  const auto error = std::make_exception_ptr(VulkanError(VK_ERROR_DEVICE_LOST, "vkQueueSubmit", "frame (submit A)"));
  EXPECT_EQ(failure_message("frame 17 of 500", error),
            "frame 17 of 500: vkQueueSubmit failed for frame (submit A): VK_ERROR_DEVICE_LOST (the device was "
            "lost: a driver fault or a GPU reset; no output was written)");
}

TEST(FailureMessage, HostAllocationFailureNamesTheStage) {
  EXPECT_EQ(failure_message("reading back the frames", std::make_exception_ptr(std::bad_alloc())),
            "reading back the frames: out of host memory (std::bad_alloc); try a smaller --width/--height");
}

TEST(FailureMessage, AMessageAboutAFlagPassesThroughUnchanged) {
  EXPECT_EQ(failure_message("creating the renderer (0x16)",
                            std::make_exception_ptr(OptionError("--width", "--width 0: too small"))),
            "--width 0: too small");
}

TEST(FailureMessage, TheErrorsTypeNotItsWordingDecidesWhetherTheStageIsSaid) {
  EXPECT_EQ(failure_message("frame 1 of 1", std::make_exception_ptr(Error("--looks like a flag"))),
            "frame 1 of 1: --looks like a flag");
}

TEST(FailureMessage, OurOtherErrorsGetTheStage) {
  EXPECT_EQ(failure_message("frame 1 of 1", std::make_exception_ptr(TimeoutError("GPU did not finish x within 1 s"))),
            "frame 1 of 1: GPU did not finish x within 1 s");
  EXPECT_EQ(failure_message("comparing the frames and writing the results to out",
                            std::make_exception_ptr(Error("cannot write PNG out/a.png: out of host memory"))),
            "comparing the frames and writing the results to out: cannot write PNG out/a.png: out of host memory");
}

TEST(FailureMessage, AnyOtherExceptionStillSaysWhere) {
  EXPECT_EQ(failure_message("the warm-up frame", std::make_exception_ptr(std::length_error("vector::reserve"))),
            "the warm-up frame: vector::reserve");
  EXPECT_EQ(failure_message("the warm-up frame", std::make_exception_ptr(42)),
            "the warm-up frame: an unknown exception");
}

}  // namespace
}  // namespace tilelight::test
