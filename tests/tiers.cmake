# Which tier each test is in, by its ctest name (docs/ci.md, "Tiers"). Read when CMake
# configures (tests added with add_test) and by ctest (GoogleTest cases, known only after the
# build): plain CMake language, no commands but set, list, foreach, if and function.
#
#   default    what the README's test command runs: every test not in `long`
#   long       sweeps and repeated frame configurations; scripts/run-tests.sh --all and CI
#   sanitizer  the default-tier cases the ASan/UBSan build runs; its product-code line coverage
#              must stay >= 95 % of the whole suite's (scripts/coverage.sh measures both)
#   quick      the edit loop, scripts/run-tests.sh --quick: the default tier less its slowest
#
# A pattern is a regular expression over the whole name; keep each list sorted by area, and
# say why a case is where it is. A test in several lists takes the first that applies.

# Sweeps and repeated frame configurations: the same frame again at another camera, MSAA mode,
# path or light pass, where one configuration of each kind stays in the default tier.
set(TESTS_LONG_PATTERNS
)

# Default-tier cases the sanitizer build leaves out: each adds little coverage of product code
# over the cases kept (docs/ci.md lists them with their times).
set(TESTS_NOT_SANITIZER_PATTERNS
)

# Default-tier cases the quick loop leaves out: the slowest.
set(TESTS_NOT_QUICK_PATTERNS
)

# tests_tier_labels(<name> <out>): the tier labels of the test called <name>.
function(tests_tier_labels name out)
  foreach(pattern IN LISTS TESTS_LONG_PATTERNS)
    if(name MATCHES "${pattern}")
      set(${out} long PARENT_SCOPE)
      return()
    endif()
  endforeach()
  set(tiers default)
  set(sanitizer TRUE)
  foreach(pattern IN LISTS TESTS_NOT_SANITIZER_PATTERNS)
    if(name MATCHES "${pattern}")
      set(sanitizer FALSE)
      break()
    endif()
  endforeach()
  if(sanitizer)
    list(APPEND tiers sanitizer)
  endif()
  set(quick TRUE)
  foreach(pattern IN LISTS TESTS_NOT_QUICK_PATTERNS)
    if(name MATCHES "${pattern}")
      set(quick FALSE)
      break()
    endif()
  endforeach()
  if(quick)
    list(APPEND tiers quick)
  endif()
  set(${out} "${tiers}" PARENT_SCOPE)
endfunction()
