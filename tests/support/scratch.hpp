// Test support: where a test writes its files. Under the temporary directory (TMPDIR), which ctest
// sets to the build tree's test-scratch/ for every test (cmake/VbimTargets.cmake, tests/CMakeLists.txt),
// so that tests of several build trees, or anything that cleans /tmp, never meet; each name carries
// the test program's pid as well. The script tests made with add_test get the same TMPDIR
// (vbim_use_test_scratch, tests/CMakeLists.txt), so their mktemp -d lands there too.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace vbim::testing {

// TMPDIR/vbim_<what>_<pid>, with whatever an earlier run left there removed; not made.
inline std::filesystem::path scratchPath(const std::string& what) {
  const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("vbim_" + what + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  return p;
}

// The same, made (an empty directory).
inline std::filesystem::path scratchDir(const std::string& what) {
  const std::filesystem::path p = scratchPath(what);
  std::filesystem::create_directories(p);
  return p;
}

// The running test's own: scratchDir("<what>_<test name>"), for a fixture's SetUp.
inline std::filesystem::path testScratchDir(const std::string& what) {
  return scratchDir(what + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

}  // namespace vbim::testing
