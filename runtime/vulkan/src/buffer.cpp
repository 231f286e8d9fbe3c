#include "tilelight/vulkan/buffer.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <fmt/format.h>

#include <cstring>
#include <utility>

namespace tilelight {

Buffer::Buffer(const Context& context, BufferDesc desc) : desc_(std::move(desc)) {
  if (desc_.size == 0) {
    throw Error(fmt::format("buffer {} has size 0", desc_.name));
  }
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = desc_.size;
  info.usage = desc_.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;  // one queue
  VkBuffer buffer = VK_NULL_HANDLE;
  check(vkCreateBuffer(context.device(), &info, nullptr, &buffer), "vkCreateBuffer", desc_.name);
  buffer_ = UniqueBuffer(buffer, {context.device()});
  context.name_object(buffer, desc_.name);

  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(context.device(), buffer, &requirements);
  memory_ = allocate_memory(context, requirements, desc_.memory, desc_.name);
  check(vkBindBufferMemory(context.device(), buffer, memory_.get(), 0), "vkBindBufferMemory", desc_.name);

  if (is_host_visible(desc_.memory)) {
    void* mapped = nullptr;
    check(vkMapMemory(context.device(), memory_.get(), 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory", desc_.name);
    mapped_ = static_cast<std::byte*>(mapped);
  }
}

Buffer::Buffer(Buffer&& other) noexcept
    : desc_(std::move(other.desc_)),
      memory_(std::move(other.memory_)),
      buffer_(std::move(other.buffer_)),
      mapped_(std::exchange(other.mapped_, nullptr)) {
  other.desc_.size = 0;
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    // Buffer before memory, as the destructor would.
    buffer_ = std::move(other.buffer_);
    memory_ = std::move(other.memory_);
    desc_ = std::move(other.desc_);
    mapped_ = std::exchange(other.mapped_, nullptr);
    other.desc_.size = 0;
  }
  return *this;
}

std::span<std::byte> Buffer::bytes() const {
  if (mapped_ == nullptr) {
    throw Error(fmt::format("buffer {} is not host-visible", desc_.name));
  }
  return {mapped_, static_cast<std::size_t>(desc_.size)};
}

void Buffer::check_range(VkDeviceSize offset, std::size_t length, const char* what) const {
  if (mapped_ == nullptr) {
    throw Error(fmt::format("cannot {} buffer {}: it is not host-visible", what, desc_.name));
  }
  if (offset > desc_.size || length > desc_.size - offset) {
    throw Error(fmt::format("cannot {} {} bytes at offset {} of buffer {} ({} bytes)", what, length, offset, desc_.name,
                            desc_.size));
  }
}

void Buffer::write(std::span<const std::byte> data, VkDeviceSize offset) const {
  check_range(offset, data.size(), "write");
  if (!data.empty()) {
    std::memcpy(mapped_ + offset, data.data(), data.size());
  }
}

void Buffer::read(std::span<std::byte> out, VkDeviceSize offset) const {
  check_range(offset, out.size(), "read");
  if (!out.empty()) {
    std::memcpy(out.data(), mapped_ + offset, out.size());
  }
}

}  // namespace tilelight
