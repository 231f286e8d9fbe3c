#pragma once
// Move-only ownership of one Vulkan handle. The deleter is stored next to the handle because
// most Vulkan objects need their parent (device, pool, instance) to be destroyed.

#include <vulkan/vulkan.h>

#include <utility>

namespace tilelight {

// Owns `T` (a Vulkan handle type) and destroys it with `Deleter` exactly once.
// A default-constructed or moved-from Handle is empty (VK_NULL_HANDLE) and destroys nothing.
// Precondition of destruction: the GPU no longer uses the object, and its parent is still
// alive (declare parents before children so that members are destroyed children first).
template <typename T, typename Deleter>
class Handle {
 public:
  Handle() = default;
  Handle(T handle, Deleter deleter) noexcept : handle_(handle), deleter_(std::move(deleter)) {}
  ~Handle() { reset(); }

  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  Handle(Handle&& other) noexcept
      : handle_(std::exchange(other.handle_, T{VK_NULL_HANDLE})), deleter_(std::move(other.deleter_)) {}

  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, T{VK_NULL_HANDLE});
      deleter_ = std::move(other.deleter_);
    }
    return *this;
  }

  T get() const noexcept { return handle_; }
  explicit operator bool() const noexcept { return handle_ != T{VK_NULL_HANDLE}; }
  const Deleter& deleter() const noexcept { return deleter_; }

  // Gives up ownership without destroying (used to leak deliberately when destroying is unsafe).
  T release() noexcept { return std::exchange(handle_, T{VK_NULL_HANDLE}); }

  // Destroys the owned object now, if any.
  void reset() noexcept {
    if (handle_ != T{VK_NULL_HANDLE}) {
      deleter_(std::exchange(handle_, T{VK_NULL_HANDLE}));
    }
  }

 private:
  T handle_ = T{VK_NULL_HANDLE};
  Deleter deleter_{};
};

}  // namespace tilelight
