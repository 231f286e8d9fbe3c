#pragma once
// A VkBuffer with its own memory. Host-visible buffers stay mapped for their whole life
// (persistent mapping): the index and indirect buffers are rewritten every frame, and mapping
// is not free.

#include "tilelight/vulkan/memory.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstddef>
#include <span>
#include <string>
#include <type_traits>

namespace tilelight {

class Context;

struct BufferDesc {
  VkDeviceSize size = 0;  // bytes; must be > 0
  VkBufferUsageFlags usage = 0;
  MemoryUse memory = MemoryUse::DeviceLocal;
  std::string name;  // for errors and validation messages
};

class Buffer {
 public:
  Buffer() = default;  // empty: handle() == VK_NULL_HANDLE
  // Creates, allocates, binds and (for host-visible uses) maps. Throws tilelight::Error.
  Buffer(const Context& context, BufferDesc desc);

  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer() = default;  // memory is unmapped implicitly when freed

  VkBuffer handle() const { return buffer_.get(); }
  VkDeviceSize size() const { return desc_.size; }
  VkBufferUsageFlags usage() const { return desc_.usage; }
  const std::string& name() const { return desc_.name; }
  bool host_visible() const { return mapped_ != nullptr; }

  // The mapped bytes. Precondition: host_visible(). The memory is HOST_COHERENT, so writes need
  // no flush; but writes made after a submit that reads them still need a HOST -> device
  // barrier in that submit (see docs/design.md, deferred draw patching).
  std::span<std::byte> bytes() const;

  // The mapped memory as an array of T. Precondition: host_visible(); T trivially copyable.
  // The element count is size() / sizeof(T), rounded down.
  template <typename T>
  std::span<T> as() const {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::span<std::byte> raw = bytes();
    return {reinterpret_cast<T*>(raw.data()), raw.size() / sizeof(T)};
  }

  // Copies into / out of the mapped memory at `offset`. Throws tilelight::Error if the buffer
  // is not host-visible or the range does not fit.
  void write(std::span<const std::byte> data, VkDeviceSize offset = 0) const;
  void read(std::span<std::byte> out, VkDeviceSize offset = 0) const;

  template <typename T>
  void write_values(std::span<const T> values, VkDeviceSize offset = 0) const {
    static_assert(std::is_trivially_copyable_v<T>);
    write(std::as_bytes(values), offset);
  }

 private:
  void check_range(VkDeviceSize offset, std::size_t length, const char* what) const;

  BufferDesc desc_;
  // Memory before buffer, so that the buffer is destroyed before its memory is freed.
  UniqueDeviceMemory memory_;
  UniqueBuffer buffer_;
  std::byte* mapped_ = nullptr;
};

}  // namespace tilelight
