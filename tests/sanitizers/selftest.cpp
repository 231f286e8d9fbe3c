// Proves that a sanitizer build catches each kind of bug it is there for, in our own code and
// despite the driver-only leak suppressions: each mode does one wrong thing, and its CTest test
// passes only when the sanitizer's report appears (tests/sanitizers/CMakeLists.txt).
#include <climits>
#include <cstdio>
#include <string_view>

namespace {

// volatile: the compiler can neither drop the allocation nor fold the arithmetic away.
int* volatile g_sink = nullptr;

int leak() {
  g_sink = new int[16];
  g_sink = nullptr;  // the only pointer is gone: LeakSanitizer reports it at exit
  return 0;
}

int heap_overflow() {
  int* values = new int[4];
  volatile int index = 4;
  values[index] = 1;  // one past the end
  delete[] values;
  return 0;
}

int signed_overflow() {
  volatile int big = INT_MAX;
  volatile int one = 1;
  return big + one;  // undefined behaviour; UBSan stops the process
}

}  // namespace

int main(int argc, char** argv) {
  std::string_view mode = argc > 1 ? argv[1] : "";
  if (mode == "leak") return leak();
  if (mode == "heap-overflow") return heap_overflow();
  if (mode == "signed-overflow") return signed_overflow();
  std::fprintf(stderr, "usage: %s leak|heap-overflow|signed-overflow\n", argv[0]);
  return 2;
}
