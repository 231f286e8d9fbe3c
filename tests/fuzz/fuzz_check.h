// fuzz_check.h - the property checks the fuzz entry points make beyond "no crash".
#pragma once

#include <cstdio>
#include <cstdlib>

namespace shadergen::fuzz {

// A broken property is a finding: print it and abort, so libFuzzer saves the input and a
// replay test fails with the message.
inline void require(bool holds, const char* property) {
  if (holds) return;
  std::fprintf(stderr, "fuzz: property violated: %s\n", property);
  std::abort();
}

}  // namespace shadergen::fuzz
