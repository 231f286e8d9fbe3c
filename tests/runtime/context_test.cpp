// The Vulkan context on lavapipe: default device choice, validation that reports nothing,
// clear errors for devices and MSAA counts that do not exist.
#include <gtest/gtest.h>

#include "tilelight/context.h"
#include "tilelight/error.h"

namespace tilelight {
namespace {

const std::vector<DeviceInfo> kDevices = {
    {0, "NVIDIA H100 PCIe", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_3},
    {1, "llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU, VK_API_VERSION_1_3},
};

TEST(DeviceSelection, DefaultIsTheCpuDevice) { EXPECT_EQ(select_device(kDevices, "").index, 1u); }

TEST(DeviceSelection, ByIndexAndByNameSubstring) {
    EXPECT_EQ(select_device(kDevices, "0").index, 0u);
    EXPECT_EQ(select_device(kDevices, "h100").index, 0u);
    EXPECT_EQ(select_device(kDevices, "LLVMPIPE").index, 1u);
}

TEST(DeviceSelection, UnknownDeviceListsTheDevices) {
    try {
        select_device(kDevices, "radeon");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(),
                     "--device radeon: no device name contains \"radeon\"; devices:\n  0: NVIDIA H100 PCIe\n  1: "
                     "llvmpipe (LLVM 15.0.6, 256 bits)");
    }
    EXPECT_THROW(select_device(kDevices, "7"), Error);
}

TEST(Msaa, AutoPrefersTwoElseFour) {
    EXPECT_EQ(choose_msaa(VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_2_BIT | VK_SAMPLE_COUNT_4_BIT, 0),
              VK_SAMPLE_COUNT_2_BIT);
    EXPECT_EQ(choose_msaa(VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT, 0), VK_SAMPLE_COUNT_4_BIT);
}

TEST(Msaa, MissingCountNamesTheValue) {
    try {
        choose_msaa(VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT, 2);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "--msaa 2: the device does not support 2 samples for the G-buffer (supported: 1, 4)");
    }
    EXPECT_THROW(choose_msaa(VK_SAMPLE_COUNT_4_BIT, 3), Error);
}

TEST(Context, LavapipeWithValidationReportsNothing) {
    ValidationLog* log = nullptr;
    {
        Context context({"", true});
        EXPECT_NE(context.device_info().name.find("llvmpipe"), std::string::npos) << context.device_info().name;
        EXPECT_NE(context.device(), VK_NULL_HANDLE);
        EXPECT_NE(context.queue(), VK_NULL_HANDLE);
        // lavapipe offers 1x and 4x only, so "auto" gives 4x there.
        EXPECT_EQ(choose_msaa(context.msaa_counts(), 0), VK_SAMPLE_COUNT_4_BIT);
        log = context.validation();
        ASSERT_NE(log, nullptr);
        EXPECT_TRUE(log->empty()) << log->summary();
    }
}

TEST(Context, UnknownDeviceFailsClearly) {
    EXPECT_THROW(Context({"no-such-gpu", false}), Error);
}

}  // namespace
}  // namespace tilelight
