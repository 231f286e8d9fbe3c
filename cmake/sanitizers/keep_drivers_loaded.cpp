// Keeps the Vulkan driver and layer libraries mapped until exit in sanitizer builds.
//
// The Vulkan loader dlcloses the driver (and any layer) when the instance is destroyed. A leak
// inside a library that is no longer mapped shows as "<unknown module>" in LeakSanitizer's
// report, and a suppression can only name a library that is still mapped at exit. Opening the
// libraries once more with RTLD_NODELETE keeps them mapped, so cmake/sanitizers/lsan.supp can
// suppress the driver's leaks by library name and nothing else.
#include <dlfcn.h>

namespace {

// Runs before main(), in sanitizer builds only (cmake/Sanitizers.cmake links this file).
__attribute__((constructor)) void keep_vulkan_libraries_loaded() {
  // Only a process linked with the Vulkan loader renders; the others are left alone.
  if (dlopen("libvulkan.so.1", RTLD_LAZY | RTLD_NOLOAD) == nullptr) return;
  // A library that is not installed is skipped: dlopen then only returns null.
  const char* const libraries[] = {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"};
  for (const char* library : libraries) dlopen(library, RTLD_LAZY | RTLD_NODELETE);
}

}  // namespace
