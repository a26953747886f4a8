// A test's output against a committed golden file: equal, or (VBIM_UPDATE_GOLDEN=1, as
// scripts/update-golden.sh sets it) the file is rewritten and the test skipped.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace vbim::testing {

inline void expectMatchesGolden(const std::string& got, const std::string& path, const std::string& what) {
  if (const char* u = std::getenv("VBIM_UPDATE_GOLDEN"); u != nullptr && std::string(u) == "1") {
    std::ofstream(path, std::ios::binary) << got;
    GTEST_SKIP() << "wrote " << path;
  }
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << path << " is missing: run scripts/update-golden.sh";
  std::stringstream want;
  want << in.rdbuf();
  EXPECT_EQ(got, want.str()) << what
                             << " differs from the committed file (after a deliberate change: "
                                "scripts/update-golden.sh, review, commit)";
}

}  // namespace vbim::testing
