// vbim config as a library call (runs/config_run.hpp): which text is the verdict and which the
// document, and a bad config refused before either.
#include "runs/config_run.hpp"

#include <string>

#include <gtest/gtest.h>

#include "runtime/error.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace vbim::runs {
namespace {

namespace fs = std::filesystem;

TEST(ConfigRun, WithoutACheckTheDocumentIsTheDefaultConfig) {
  const ConfigResult r = configRun({});
  EXPECT_EQ(r.verdict, "");
  EXPECT_EQ(r.document.rfind("# vbim platform config: every timing constant", 0), 0u) << r.document.substr(0, 80);
  ConfigRequest markdown;
  markdown.markdown = true;
  const ConfigResult md = configRun(markdown);
  EXPECT_NE(md.document.find("| "), std::string::npos);
}

TEST(ConfigRun, APassingCheckIsOneVerdictLineAndNoDocumentUnlessAskedFor) {
  const fs::path d = vbim::testing::scratchDir("config_run");
  ASSERT_TRUE(vbim::testing::writeTextFile(d / "ok.toml", "gs.sky_height = 128\n"));
  const std::string ok = (d / "ok.toml").string();
  ConfigRequest request;
  request.check = ok;
  const ConfigResult check = configRun(request);
  EXPECT_EQ(check.verdict, ok + ": valid\n");
  EXPECT_EQ(check.document, "");
  request.effective = true;
  const ConfigResult effective = configRun(request);
  EXPECT_EQ(effective.verdict, ok + ": valid; the effective config follows\n");
  EXPECT_NE(effective.document.find("sky_height = 128"), std::string::npos);
  ASSERT_TRUE(vbim::testing::writeTextFile(d / "bad.toml", "nonsense = 1\n"));
  request.check = (d / "bad.toml").string();
  EXPECT_THROW(configRun(request), Error);
  fs::remove_all(d);
}

}  // namespace
}  // namespace vbim::runs
