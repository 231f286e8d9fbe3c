// phase_clock.h - wall time of the consecutive phases of a build, for `--stats`.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace shadergen {

// Wall time of one phase of a build ("parse spec", "preprocess", "compile or load", ...).
struct PhaseTime {
  std::string name;
  double ms = 0.0;
};

// Each lap() records the time since the previous lap (or construction) under a name.
class PhaseClock {
 public:
  explicit PhaseClock(std::vector<PhaseTime>& out) : out_(out), last_(Clock::now()) {}

  void lap(std::string name) {
    auto now = Clock::now();
    out_.push_back({std::move(name), std::chrono::duration<double, std::milli>(now - last_).count()});
    last_ = now;
  }

  // Starts the next phase now: the time since the last lap belongs to no phase.
  void restart() { last_ = Clock::now(); }

 private:
  using Clock = std::chrono::steady_clock;
  std::vector<PhaseTime>& out_;
  Clock::time_point last_;
};

}  // namespace shadergen
