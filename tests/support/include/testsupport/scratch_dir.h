// A fresh, empty folder for the running GoogleTest test: <root>/<suite>.<test>, emptied first,
// so a test sees only what it wrote and leaves its output to look at after the run.
//
// Header-only (tests::support, which every test links), so the test itself needs GoogleTest.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace testsupport {

// Precondition: called from inside a running test.
inline std::filesystem::path scratch_dir(const std::filesystem::path& root) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = root / (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace testsupport
