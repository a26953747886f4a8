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
}

}  // namespace vbim::ee
