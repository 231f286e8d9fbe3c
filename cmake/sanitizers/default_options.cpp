// Runtime options linked into every executable of a -DSANITIZE=ON build (cmake/Sanitizers.cmake).
// The sanitizer runtimes call these hooks before reading ASAN_OPTIONS / UBSAN_OPTIONS /
// LSAN_OPTIONS, so the environment still overrides any of them.

// The hooks are looked up by name from the sanitizer runtime: C linkage, exported, never
// dropped by the linker.
#define SHADERGEN_SANITIZER_HOOK extern "C" __attribute__((visibility("default"), used))

// Leaks are checked at exit (LeakSanitizer is on by default with ASan on Linux; stated so it
// stays on). check_initialization_order: static-initialisation-order bugs across our files.
SHADERGEN_SANITIZER_HOOK const char* __asan_default_options() {
  return "detect_leaks=1:check_initialization_order=1:strict_init_order=1";
}

// A UBSan report prints where it happened and ends the process (the code is also built with
// -fno-sanitize-recover=undefined), so it fails the test that reached it.
SHADERGEN_SANITIZER_HOOK const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

// Leaks inside the uninstrumented Vulkan driver stack are suppressed by library name only;
// cmake/sanitizers/lsan.supp says which and why.
SHADERGEN_SANITIZER_HOOK const char* __lsan_default_options() { return "suppressions=" SHADERGEN_LSAN_SUPPRESSIONS; }
