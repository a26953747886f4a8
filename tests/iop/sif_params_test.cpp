// SIF0 timing, the IOP parameter table (TOML errors, docs listing every key).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "config/params_toml.hpp"
#include "iop/params.hpp"
#include "iop/sif.hpp"
#include "runtime/scheduler.hpp"

namespace vbim::iop {
namespace {

Task<void> send(Scheduler& s, SifChannel& sif, std::size_t bytes, Tick& done) {
  co_await sif.transfer(bytes);
  done = s.now();
}

TEST(Sif, SetupPlusBytesAtBandwidthOneAtATime) {
  Scheduler s;
  SifParams p;
  SifChannel sif(s, p);
  // 65,536 bytes at 20 MB/s = 3.2768 ms = 483,183.8 ticks -> 483,184; + 30 us = 4,424 ticks.
  EXPECT_EQ(sif.transferTicks(65'536), 483'184 + 4'424);
  Tick a = 0, b = 0;
  s.spawn("a", send(s, sif, 65'536, a));
  s.spawn("b", send(s, sif, 2048, b));
  s.run();
  EXPECT_EQ(a, sif.transferTicks(65'536));
  EXPECT_EQ(b, a + sif.transferTicks(2048));  // waits for the channel
  EXPECT_EQ(sif.transfers(), 2);
}

TEST(IopParams, DefaultsAndTomlErrors) {
  IopParams p;
  ParamTable t;
  describeParams(t, p);
  config::applyToml(t, "[drive]\nspindle = \"clv\"\nfull_seek_us = 150000\n[sif]\nsetup_us = 10\n", "platform.toml");
  EXPECT_EQ(p.drive.spindle, "clv");
  EXPECT_EQ(p.drive.full_seek_us, 150'000);
  EXPECT_EQ(p.sif.setup_us, 10);
  try {
    config::applyToml(t, "[drive]\nfull_seek_us = -1\n", "platform.toml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("platform.toml:2: key 'drive.full_seek_us'"), std::string::npos) << e.what();
  }
  try {
    config::applyToml(t, "[ring]\nbanks = 4\n", "platform.toml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("platform.toml:2: key 'ring.banks': unknown key"), std::string::npos);
  }
  p.ring.bufmax_sectors = 3;
  p.ring.bankmax = 5;
  EXPECT_THROW(validate(p), ConfigError);
}

// sceCdStRead streams 2,048-byte sectors (datapattern SCECdSecS2048), so the IOP DMA of a sector
// moves 512 words at 12 IOP cycles each, not the 2,064-byte raw DVD sector's 516.
TEST(IopParams, SectorDmaIsChargedForTheStreamedSector) {
  EXPECT_EQ(DriveParams{}.dma_iop_cycles_per_sector, 6'144);
  EXPECT_EQ(DriveParams{}.dma_iop_cycles_per_sector, static_cast<std::int64_t>(kSectorBytes) / 4 * 12);
}

TEST(IopParams, EveryKeyIsDocumentedWithItsSource) {
  IopParams p;
  ParamTable t;
  describeParams(t, p);
  const char* root = std::getenv("VBIM_SOURCE_DIR");
  ASSERT_NE(root, nullptr);
  std::ifstream in(std::string(root) + "/docs/timing/iop.md");
  ASSERT_TRUE(in) << "docs/timing/iop.md missing";
  std::stringstream ss;
  ss << in.rdbuf();
  for (const auto& param : t.params()) {
    EXPECT_NE(ss.str().find("`" + param.key + "`"), std::string::npos) << param.key << " is not in docs/timing/iop.md";
    EXPECT_FALSE(param.source.empty()) << param.key;
  }
}

}  // namespace
}  // namespace vbim::iop
