# tests_precompile_headers(<target>): the headers nearly every test includes (GoogleTest,
# nlohmann/json and the standard library's containers, streams and <filesystem>), parsed once
# per test executable instead of once per test file. Parsing them was most of a test file's
# compile time (docs/ci.md, "Build"); the generated code, the product libraries and what
# scripts/lint.sh lints are compiled without it. A test file still includes what it uses: the
# header is only a faster way to the same declarations. -DSHADERGEN_TEST_PCH=OFF turns it off
# (to check the tests' own includes, or for a compiler whose PCH misbehaves).
include_guard(GLOBAL)
option(SHADERGEN_TEST_PCH "Precompile the headers every test executable uses" ON)

function(tests_precompile_headers target)
  if(NOT SHADERGEN_TEST_PCH)
    return()
  endif()
  target_precompile_headers(${target} PRIVATE
    <gtest/gtest.h>
    <nlohmann/json.hpp>
    <algorithm>
    <array>
    <chrono>
    <cstdint>
    <filesystem>
    <fstream>
    <functional>
    <map>
    <memory>
    <optional>
    <set>
    <sstream>
    <string>
    <string_view>
    <vector>)
endfunction()
