#include "ee/params.hpp"

namespace vbim::ee {

void describeParams(ParamTable& t, EeParams& p) {
  t.addInt("ee.read_sectors", &p.read_sectors, 1, 512, "sectors",
           "assumption: half a 32-sector bank per sceCdStRead, so a bank drains in two calls (SDK-ST reads are "
           "bank-bounded chunks)");
  t.addInt("ee.poll_us", &p.poll_us, 1, 1'000'000, "us",
           "assumption: the demux thread yields and retries 1 ms after a read returned nothing (an EE thread "
           "waiting on an alarm)");
  t.addInt("ee.cycles_per_pack", &p.cycles_per_pack, 0, 10'000'000, "EE cycles",
           "assumption: pack header, system header and 1-2 PES headers parsed field by field, a few hundred "
           "instructions");
  t.addInt("ee.cycles_per_byte", &p.cycles_per_byte, 0, 1'000, "EE cycles",
           "assumption: a byte-wise start-code scan plus the copy into the stream buffer, about 2 cycles a byte");
  t.addInt("ee.copy_cycles_per_qword", &p.copy_cycles_per_qword, 0, 1'000, "EE cycles",
           "assumption: a quadword memcpy from cached to uncached EE RAM, 4 cycles per 16 bytes");
  t.addInt("ee.reorder_cycles_per_qword", &p.reorder_cycles_per_qword, 0, 1'000, "EE cycles",
           "assumption: with gs.upload_strategy = ee-reorder, the EE copies each decoded macroblock's 16 rows of 4 "
           "quadwords into a raster image: twice ee.copy_cycles_per_qword, since the fromIPU output is read back "
           "from memory uncached (docs/timing/ee.md)");
  t.addInt("ee.compressed_frames", &p.compressed_frames, 1, 64, "pictures",
           "Hoffman & Mitchell, GDC 2001: one complete picture waits in the compressed frame buffer while the next "
           "loads; 2 per stream");
  t.addInt("ee.compressed_budget_kib", &p.compressed_budget_kib, 1, std::int64_t{32} * 1'024, "KiB",
           "assumption: 4 MiB of the EE's 32 MiB per stream for compressed pictures, including those stored "
           "beyond ee.compressed_frames while the other stream is behind in the mux; a picture that would exceed "
           "it is dropped and its frame counted lost");
  t.addInt("ee.decoded_frames", &p.decoded_frames, 1, 64, "frames",
           "assumption: double-buffered decoded frames per stream (the shown target and the next one)");
  t.addInt("ee.decode_setup_cycles", &p.decode_setup_cycles, 0, 10'000'000, "EE cycles",
           "assumption: building the toIPU/fromIPU DMA chains and issuing IDEC, about 2,000 cycles");
  t.addInt("ee.start_lead_ms", &p.start_lead_ms, 0, 3'600'000, "ms",
           "assumption: the game starts the stream 500 ms before frame 0 is due (spin-up 333 ms + a seek + a bank)");
  ipu::EeFlowCosts& m = p.mc;
  t.addInt("ee.vdec_cycles", &m.vdec_cycles, 0, 1'000'000, "EE cycles",
           "assumption [A]: libmpeg's _MPEG_GetMBAI/GetMBType/GetMotionCode: write IPU_CMD, poll IPU_CTRL and "
           "IPU_CMD until not busy, read IPU_TOP: 4 uncached accesses of ~60 EE cycles (the figure of "
           "ipu.slice_restart_cycles), 240 (docs/timing/ee.md#p-and-b-pictures)");
  t.addInt("ee.fdec_cycles", &m.fdec_cycles, 0, 1'000'000, "EE cycles",
           "assumption [A]: libmpeg's _MPEG_GetBits: a sync poll and an FDEC write, 2 uncached accesses, 120 "
           "(docs/timing/ee.md#p-and-b-pictures)");
  t.addInt("ee.bdec_issue_cycles", &m.bdec_issue_cycles, 0, 1'000'000, "EE cycles",
           "assumption [A]: libmpeg's _MPEG_BDEC: D3_MADR, D3_QWC, D3_CHCR, a sync poll and IPU_CMD, 5 uncached "
           "accesses, 300 (docs/timing/ee.md#p-and-b-pictures)");
  t.addInt("ee.mb_cycles", &m.mb_cycles, 0, 1'000'000, "EE cycles",
           "assumption [A]: per macroblock, libmpeg's _mpeg12_dec_mb/_mpeg2_mc bookkeeping, vector arithmetic and "
           "the toSPR DMA tags that fetch the reference area (_MPEG_dma_ref_image), ~400 "
           "(docs/timing/ee.md#p-and-b-pictures)");
  t.addInt("ee.mc_cycles_per_mb", &m.mc_cycles_per_mb, 0, 1'000'000, "EE cycles",
           "assumption [A]: per macroblock, the block op that stores its 384 samples into the frame through "
           "uncached writes (24 qwords, ~16 cycles each with the write-back buffer), 400 "
           "(docs/timing/ee.md#p-and-b-pictures)");
  t.addInt("ee.mc_cycles_per_prediction", &m.mc_cycles_per_prediction, 0, 1'000'000, "EE cycles",
           "assumption [A]: one block prediction from scratchpad with MMI (16x16 luma and two 8x8 chroma, "
           "half-sample interpolation of up to 4 neighbours in 8 16-bit lanes), ~500 "
           "(docs/timing/ee.md#p-and-b-pictures)");
  t.addInt("ee.mc_average_cycles", &m.mc_average_cycles, 0, 1'000'000, "EE cycles",
           "assumption [A]: averaging a second prediction into the first (bidirectional, dual prime), 384 samples "
           "with PAVGB-style MMI ops, ~200 (docs/timing/ee.md#p-and-b-pictures)");
  t.addInt("ee.residual_add_cycles", &m.residual_add_cycles, 0, 1'000'000, "EE cycles",
           "assumption [A]: adding BDEC's 16-bit residual (48 qwords) to the prediction with the clip, MMI, ~300 "
           "(docs/timing/ee.md#p-and-b-pictures)");
  t.addInt("ee.csc_setup_cycles", &m.csc_setup_cycles, 0, 1'000'000, "EE cycles",
           "assumption [A]: libmpeg's _MPEG_CSCImage: suspend the IPU (stop toIPU, drain, stop fromIPU), BCLR, "
           "set up both DMA channels, CSC, then resume (BCLR with the saved bit pointer), ~10 uncached accesses, "
           "600 (docs/timing/ee.md#p-and-b-pictures)");
}

}  // namespace vbim::ee
