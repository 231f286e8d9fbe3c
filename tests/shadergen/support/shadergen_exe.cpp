// The path of the shadergen executable is this file's own compile definition
// (tests_shadergen_exe_source() in tests/shadergen/CMakeLists.txt), not its target's: a build
// path on a target's command line would give every one of its sources a command line of its
// own per build folder, and ccache could hand the sanitizer build none of the test build's
// objects (docs/ci.md).
#include "test_helpers.h"

namespace sgtest {

fs::path shadergen_exe() { return fs::path(SHADERGEN_EXE); }

}  // namespace sgtest
