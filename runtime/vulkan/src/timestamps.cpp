#include "tilelight/vulkan/timestamps.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace tilelight {
namespace {

std::uint64_t mask_of(std::uint32_t valid_bits) {
  return valid_bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << valid_bits) - 1;
}

}  // namespace

std::uint64_t timestamp_delta(std::uint64_t from, std::uint64_t to, std::uint32_t valid_bits) {
  // Unsigned subtraction wraps modulo 2^64; masking turns that into modulo 2^valid_bits.
  return (to - from) & mask_of(valid_bits);
}

TimestampQueries::TimestampQueries(const Context& context, std::string name, std::uint32_t capacity)
    : device_(context.device()),
      name_(std::move(name)),
      capacity_(capacity),
      period_ns_(static_cast<double>(context.limits().timestamp_period_ns)),
      valid_bits_(context.limits().timestamp_valid_bits) {
  if (valid_bits_ == 0) {
    throw Error(
        fmt::format("timestamps {}: the queue family of {} does not support timestamps", name_, context.device_name()));
  }
  if (capacity_ == 0) {
    throw Error(fmt::format("timestamps {}: capacity must be > 0", name_));
  }
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = capacity_;
  VkQueryPool pool = VK_NULL_HANDLE;
  check(vkCreateQueryPool(device_, &info, nullptr, &pool), "vkCreateQueryPool", name_);
  pool_ = UniqueQueryPool(pool, {device_});
  context.name_object(pool, name_);
}

void TimestampQueries::reset(VkCommandBuffer cmd) {
  vkCmdResetQueryPool(cmd, pool_.get(), 0, capacity_);
  labels_.clear();
}

void TimestampQueries::write(VkCommandBuffer cmd, std::string label, VkPipelineStageFlagBits stage) {
  if (labels_.size() >= capacity_) {
    throw Error(fmt::format("timestamps {}: all {} queries are used (writing \"{}\")", name_, capacity_, label));
  }
  vkCmdWriteTimestamp(cmd, stage, pool_.get(), size());
  labels_.push_back(std::move(label));
}

std::vector<Timestamp> TimestampQueries::read() const {
  std::vector<Timestamp> out;
  if (labels_.empty()) {
    return out;
  }
  // Pairs of (value, availability); no WAIT flag, because that wait would have no timeout.
  std::vector<std::uint64_t> raw(labels_.size() * 2);
  const VkResult result =
      vkGetQueryPoolResults(device_, pool_.get(), 0, size(), raw.size() * sizeof(std::uint64_t), raw.data(),
                            2 * sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
  if (result != VK_NOT_READY) {
    check(result, "vkGetQueryPoolResults", name_);
  }
  for (std::size_t i = 0; i < labels_.size(); ++i) {
    if (raw[2 * i + 1] == 0) {
      throw Error(
          fmt::format("timestamps {}: \"{}\" is not available yet; read timestamps after "
                      "the GPU finished the commands that wrote them",
                      name_, labels_[i]));
    }
  }
  for (std::size_t i = 0; i < labels_.size(); ++i) {
    const std::uint64_t ticks = timestamp_delta(raw[0], raw[2 * i], valid_bits_);
    out.push_back({labels_[i], static_cast<double>(ticks) * period_ns_ * 1e-6, raw[2 * i]});
  }
  return out;
}

double TimestampQueries::span_ms(const Timestamp& from, const Timestamp& to) const {
  return static_cast<double>(timestamp_delta(from.ticks, to.ticks, valid_bits_)) * period_ns_ * 1e-6;
}

double TimestampQueries::elapsed_ms(std::string_view from, std::string_view to) const {
  const std::vector<Timestamp> stamps = read();
  auto find = [&](std::string_view label) {
    const auto it = std::find_if(stamps.begin(), stamps.end(), [&](const Timestamp& t) { return t.label == label; });
    if (it == stamps.end()) {
      throw Error(fmt::format("timestamps {}: no timestamp named \"{}\"", name_, label));
    }
    return it->ms;
  };
  return find(to) - find(from);
}

}  // namespace tilelight
