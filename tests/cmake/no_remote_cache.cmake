# Included by ctest (TEST_INCLUDE_FILES of tests/) before any test runs. CI sets
# SHADERGEN_REMOTE_CACHE for its builds (README, "Sharing the cache"), but the tests count
# compiled and cached sources exactly and name their own servers, so no test may see it:
# dropping it from ctest's environment drops it from every test's.
unset(ENV{SHADERGEN_REMOTE_CACHE})
