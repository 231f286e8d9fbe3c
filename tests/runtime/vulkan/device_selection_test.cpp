// Device selection: the rules on made-up device lists, then the real lavapipe instance.
#include "tilelight/vulkan/device_selection.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <gtest/gtest.h>

namespace tilelight {
namespace {

DeviceInfo device(std::uint32_t index, std::string name, VkPhysicalDeviceType type, std::string unusable = {}) {
  DeviceInfo info;
  info.index = index;
  info.name = std::move(name);
  info.type = type;
  info.api_version = VK_MAKE_API_VERSION(0, 1, 3, 230);
  info.unusable_reason = std::move(unusable);
  return info;
}

using device_list = std::vector<DeviceInfo>;

const device_list kDevices = {
    device(0, "NVIDIA H100 PCIe", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
    device(1, "Some CPU rasteriser", VK_PHYSICAL_DEVICE_TYPE_CPU),
    device(2, "llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU),
    device(3, "Old GPU", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, "Vulkan 1.1.0 < 1.2"),
};

std::string error_of(const std::vector<DeviceInfo>& devices, std::string_view request) {
  try {
    select_device(devices, request);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(DeviceSelection, DefaultPrefersLlvmpipeThenCpuThenFirstUsable) {
  EXPECT_EQ(select_device(kDevices, "").index, 2u);
  const std::vector<DeviceInfo> no_llvmpipe = {kDevices[0], kDevices[1]};
  EXPECT_EQ(select_device(no_llvmpipe, "").index, 1u);
  const std::vector<DeviceInfo> gpus_only = {kDevices[3], kDevices[0]};
  EXPECT_EQ(select_device(gpus_only, "").index, 0u);  // index 3 is unusable
}

TEST(DeviceSelection, AutoPrefersDiscreteThenIntegratedThenTheDefault) {
  EXPECT_EQ(select_device(kDevices, "auto").index, 0u);
  const device_list integrated_and_cpu = {device(0, "Some iGPU", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU), kDevices[2]};
  EXPECT_EQ(select_device(integrated_and_cpu, "auto").index, 0u);
  const device_list cpus_only = {kDevices[1], kDevices[2]};
  EXPECT_EQ(select_device(cpus_only, "auto").index, 2u);  // lavapipe, as the default
  const device_list unusable_gpu = {kDevices[3], kDevices[2]};
  EXPECT_EQ(select_device(unusable_gpu, "auto").index, 2u);
  EXPECT_TRUE(DeviceRequest::parse("auto").automatic);
  EXPECT_FALSE(DeviceRequest::parse("auto").is_default());
}

TEST(DeviceSelection, ByIndexOrCaseInsensitiveNameSubstring) {
  EXPECT_EQ(select_device(kDevices, "0").index, 0u);
  EXPECT_EQ(select_device(kDevices, "h100").index, 0u);
  EXPECT_EQ(select_device(kDevices, "LLVMPIPE").index, 2u);
}

TEST(DeviceSelection, UnknownNameListsEveryDevice) {
  EXPECT_EQ(error_of(kDevices, "radeon"),
            "no Vulkan device matches \"radeon\"; available Vulkan devices:\n"
            "  [0] NVIDIA H100 PCIe (discrete GPU, Vulkan 1.3.230)\n"
            "  [1] Some CPU rasteriser (cpu, Vulkan 1.3.230)\n"
            "  [2] llvmpipe (LLVM 15.0.6, 256 bits) (cpu, Vulkan 1.3.230)\n"
            "  [3] Old GPU (integrated GPU, Vulkan 1.3.230) - unusable: Vulkan 1.1.0 < 1.2\n");
}

TEST(DeviceSelection, UnusableOrMissingIndexSaysWhy) {
  EXPECT_NE(error_of(kDevices, "7").find("Vulkan device index 7 does not exist"), std::string::npos);
  EXPECT_NE(error_of(kDevices, "3")
                .find("Vulkan device 3 (Old GPU) cannot be used: Vulkan 1.1.0 "
                      "< 1.2"),
            std::string::npos);
  EXPECT_NE(error_of(kDevices, "old").find("no usable Vulkan device matches \"old\""), std::string::npos);
  EXPECT_NE(error_of({}, "").find("no Vulkan devices found"), std::string::npos);
}

TEST(DeviceSelection, ParseRequest) {
  EXPECT_TRUE(DeviceRequest::parse("").is_default());
  EXPECT_EQ(DeviceRequest::parse("12").index, 12u);
  EXPECT_EQ(DeviceRequest::parse("rtx 4090").name, "rtx 4090");
  EXPECT_FALSE(DeviceRequest::parse("rtx").index);
}

TEST(DeviceSelectionOnLavapipe, DefaultIsLlvmpipe) {
  Context context;
  EXPECT_NE(context.device_name().find("llvmpipe"), std::string::npos) << context.device_name();
  EXPECT_EQ(context.device_info().type, VK_PHYSICAL_DEVICE_TYPE_CPU);
  EXPECT_FALSE(context.available_devices().empty());
}

TEST(DeviceSelectionOnLavapipe, UnknownDeviceErrorListsTheRealDevices) {
  ContextOptions options;
  options.device = "no-such-gpu";
  try {
    Context context(options);
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("no Vulkan device matches \"no-such-gpu\"; available Vulkan devices:\n"), std::string::npos)
        << text;
    EXPECT_NE(text.find("llvmpipe"), std::string::npos) << text;
  }
}

TEST(DeviceSelectionOnLavapipe, ByNameAndIndex) {
  ContextOptions options;
  options.device = "LLVMpipe";
  Context by_name(options);
  EXPECT_NE(by_name.device_name().find("llvmpipe"), std::string::npos);
  options.device = std::to_string(by_name.device_info().index);
  Context by_index(options);
  EXPECT_EQ(by_index.device_name(), by_name.device_name());
}

}  // namespace
}  // namespace tilelight
