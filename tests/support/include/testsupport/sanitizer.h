#pragma once
// Whether this process runs under AddressSanitizer, for tests whose measurements ASan changes by
// design (address-space limits, resident memory). A run-time answer, not a macro: in the
// sanitizer build only the product is compiled instrumented (cmake/Sanitizers.cmake), so test
// code cannot ask the compiler; the executable it runs in has the ASan runtime linked in all the
// same, and so does every program of that build a test starts.
namespace testsupport {

bool under_asan();

}  // namespace testsupport
