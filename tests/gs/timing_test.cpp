#include "gs/gs_timing.hpp"

#include <gtest/gtest.h>

#include "config/params_toml.hpp"
#include "gs/params.hpp"
#include "runtime/param_table.hpp"

namespace vbim::gs {
namespace {

TEST(GsTiming, UploadAndDrawFromTheParameters) {
  const GsParams p;
  const GsTiming t(p);
  // IMAGE transfer of a 256x256 PSMCT32 frame: (6 qw * 16 + 262,144 B) / 8 B per tick.
  EXPECT_EQ(t.imageTransfer(256 * 256 * 4), (6 * 16 + 262144) / 8);
  // About 222 us at GIF peak (docs/hardware.md#gs-rates).
  EXPECT_NEAR(toMs(t.imageTransfer(256 * 256 * 4)) * 1000.0, 222.0, 1.0);
  // Sprite: 20 qw of register writes (gs/draw_setup.hpp), then 65,536 px / 8 per clock * 1.25.
  EXPECT_EQ(t.spriteDraw(256, 256), 40 + 10240);
  GsParams q;
  q.page_break_overhead_pct = 0;
  EXPECT_EQ(GsTiming(q).spriteDraw(256, 256), 40 + 8192);  // ~56 us at peak fill
  EXPECT_EQ(GsTiming(q).spriteDraw(1, 1), 40 + 1);         // rounds up
}

TEST(GsTiming, MacroblockTransfersShareOneFullSetup) {
  const GsTiming t{GsParams{}};
  EXPECT_EQ(t.setupQwords(0), 0);
  EXPECT_EQ(t.setupQwords(1), 6);
  // 256 macroblocks of a 256x256 frame: 6 qwords for the first, 4 (GIFtag, TRXPOS, TRXDIR, IMAGE
  // GIFtag) for each further one.
  EXPECT_EQ(t.setupQwords(256), 6 + 255 * 4);
  EXPECT_EQ(t.imageTransfer(256 * 256 * 4, 256), (1'026 * 16 + 262'144) / 8);  // 34,820 ticks, 236 us
  EXPECT_EQ(t.imageTransfer(256 * 256 * 4, 1), t.imageTransfer(256 * 256 * 4));
  GsParams q;
  q.macroblock_setup_qwords = 6;  // every transfer with its full setup: 1,536 qwords
  EXPECT_EQ(GsTiming(q).setupQwords(256), 1'536);
}

// An IMAGE GIFtag's NLOOP has 15 bits (T-GS GIF; SDK-GS GIF_SET_TAG): a raster transfer of more than
// 0x7FFF qwords carries one more GIFtag qword per further 0x7FFF, as uploadPacket sends it.
TEST(GsTiming, RasterUploadsOverNloopChargeTheirFurtherGifTags) {
  const GsTiming t{GsParams{}};
  // 512x512 PSMCT16 (the 16-bit path): 32,768 qwords, one over 0x7FFF: 2 IMAGE GIFtags.
  const std::int64_t ct16 = 512 * 512 * 2;
  EXPECT_EQ(t.setupQwords(1, ct16), 7);
  EXPECT_EQ(t.imageTransfer(ct16), (7 * 16 + 524'288) / 8);  // 65,550 ticks (65,548 before)
  // Exactly 0x7FFF qwords: one GIFtag; one qword more: two.
  EXPECT_EQ(t.setupQwords(1, 0x7FFF * 16), 6);
  EXPECT_EQ(t.setupQwords(1, 0x7FFF * 16 + 1), 7);
  // 512x512 PSMCT32: 65,536 qwords, 3 GIFtags.
  EXPECT_EQ(t.setupQwords(1, 512 * 512 * 4), 8);
  EXPECT_EQ(t.imageTransfer(512 * 512 * 4), (8 * 16 + 1'048'576) / 8);
  // Macroblock transfers (64 qwords each) never need a second tag.
  EXPECT_EQ(t.setupQwords(1024, 512 * 512 * 4), 6 + 1023 * 4);
  // The charge is the packet's size.
  for (const int bpp : {2, 4}) {
    const VramRegion staging{"staging", bpp == 2 ? Psm::Ct16 : Psm::Ct32, 512, 512, 0, 512};
    const GifPacket up = uploadPacket(staging, 0, 0, 512, 512, bpp, true, "raster", "");
    EXPECT_EQ(t.setupQwords(1, std::int64_t{512} * 512 * bpp), up.setupQwords()) << bpp;
  }
}

TEST(GsTiming, ParamsLoadFromTomlAndRejectBadValues) {
  ParamTable table;
  GsParams p;
  describeParams(table, p);
  config::applyToml(table, "[gs]\nfix = 96\ncatchup = \"hard-skip\"\nupload_mode = \"strips\"\n", "<test>");
  EXPECT_EQ(p.fix, 96);
  EXPECT_EQ(p.catchup, "hard-skip");
  EXPECT_EQ(p.upload_mode, "strips");
  EXPECT_THROW(config::applyToml(table, "[gs]\nfix = 256\n", "<test>"), ConfigError);
  EXPECT_THROW(config::applyToml(table, "[gs]\ncatchup = \"rewind\"\n", "<test>"), ConfigError);
  config::applyToml(table, "[gs]\nupload_strategy = \"ee-reorder\"\n", "<test>");
  EXPECT_EQ(p.upload_strategy, "ee-reorder");
  EXPECT_THROW(config::applyToml(table, "[gs]\nupload_strategy = \"rows\"\n", "<test>"), ConfigError);
  for (const auto& param : table.params()) {
    EXPECT_EQ(param.key.rfind("gs.", 0), 0u) << param.key;
    EXPECT_FALSE(param.source.empty()) << param.key;
  }
}

}  // namespace
}  // namespace vbim::gs
