#pragma once
// GPU timestamps with names: the frame report's per-pass timings (G-buffer, classification,
// tile pass, ...). On lavapipe the timestamps are CPU clock readings taken when the command
// executes, which is still the right measure of where llvmpipe spends its time.

#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tilelight {

class Context;

struct Timestamp {
  std::string label;
  double ms = 0.0;          // milliseconds since the first timestamp written after reset()
  std::uint64_t ticks = 0;  // the raw counter: spans_ms() measures across pools with it
};

class TimestampQueries {
 public:
  TimestampQueries() = default;
  // A pool of `capacity` timestamp queries. Throws tilelight::Error if the queue family has no
  // timestamps (timestampValidBits == 0).
  TimestampQueries(const Context& context, std::string name, std::uint32_t capacity);

  // Records a reset of the whole pool into `cmd` and forgets the labels. Must come before the
  // first write() of a frame, outside a render pass.
  void reset(VkCommandBuffer cmd);

  // Records a timestamp named `label` into `cmd`, taken once the work before it has passed
  // `stage` (BOTTOM_OF_PIPE: when all earlier commands have finished). Labels are recorded in
  // call order. Throws tilelight::Error when the pool is full.
  void write(VkCommandBuffer cmd, std::string label,
             VkPipelineStageFlagBits stage = VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);

  // Results of every write() since reset(), in write order. Precondition: the commands that
  // wrote them have completed (wait on their fence or timeline first). Throws tilelight::Error
  // naming the pool if a result is not available. It passes no WAIT flag, but lavapipe still
  // blocks in vkGetQueryPoolResults until its queue is idle, so never call this while a
  // submitted batch waits on a host signal that the calling thread has yet to give: it would
  // wait on itself forever (found by this project's tests).
  std::vector<Timestamp> read() const;

  // Milliseconds from timestamp `from` to `to` (by label) in read(); throws if either is
  // missing.
  double elapsed_ms(std::string_view from, std::string_view to) const;

  // Milliseconds from `from` to `to`, which may come from another pool of the same queue (one
  // clock): e.g. a frame that starts in one submission and ends in the next.
  double span_ms(const Timestamp& from, const Timestamp& to) const;

  std::uint32_t capacity() const { return capacity_; }
  std::uint32_t size() const { return static_cast<std::uint32_t>(labels_.size()); }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  std::string name_;
  std::uint32_t capacity_ = 0;
  double period_ns_ = 0.0;
  std::uint32_t valid_bits_ = 0;
  std::vector<std::string> labels_;
  UniqueQueryPool pool_;
};

// Tick difference `to - from` for a counter with `valid_bits` bits, handling one wrap-around.
std::uint64_t timestamp_delta(std::uint64_t from, std::uint64_t to, std::uint32_t valid_bits);

}  // namespace tilelight
