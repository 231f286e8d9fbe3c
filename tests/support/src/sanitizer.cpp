#include "testsupport/sanitizer.h"

#include <dlfcn.h>

namespace testsupport {

// The ASan runtime defines __asan_init in every executable it is linked into (GCC loads it as
// libasan.so ahead of everything, Clang links it statically and exports it), whichever of the
// executable's objects were compiled with -fsanitize=address.
bool under_asan() { return dlsym(RTLD_DEFAULT, "__asan_init") != nullptr; }

}  // namespace testsupport
