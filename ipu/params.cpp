#include "ipu/params.hpp"

namespace vbim::ipu {

void describeParams(ParamTable& t, IpuParams& p) {
  t.addInt("ipu.mb_base_cycles", &p.mb_base_cycles, 0, 1'000'000, "bus cycles",
           "assumption: no published IPU rate; 400 + 1/bit + 256 (CSC) gives 1,256 cycles for a 600-bit intra "
           "macroblock (~117k MB/s), well above DVD-Video's 40.5k MB/s (docs/hardware.md#ipu-decode-cost)");
  t.addInt("ipu.mb_cycles_per_bit", &p.mb_cycles_per_bit, 0, 1'000, "bus cycles/bit",
           "assumption: VLD at 1 bit per cycle; PCSX2's flat 64 EE cycles per MB is known too fast "
           "(docs/hardware.md#ipu-decode-cost)");
  t.addInt("ipu.csc_cycles_per_mb", &p.csc_cycles_per_mb, 0, 100'000, "bus cycles",
           "assumption: CSC at 1 pixel per cycle, 256 per macroblock (docs/hardware.md#ipu-decode-cost)");
  t.addInt("ipu.idec_start_cycles", &p.idec_start_cycles, 0, 100'000, "bus cycles",
           "PCSX2 IPU.cpp: IDEC/BDEC start delay of 64 EE cycles = 32 bus cycles [E]");
  t.addInt("ipu.slice_restart_cycles", &p.slice_restart_cycles, 0, 1'000'000, "bus cycles",
           "assumption [A]: IDEC stops at each slice start code; the EE sees it stop, reads the start code "
           "(IPU_TOP), skips it and reads quantiser_scale_code with FDEC, and issues IDEC again: about 10 "
           "uncached IPU register accesses and commands, 600 EE cycles = 300 bus cycles (2 us) per slice "
           "after the first, then idec_start_cycles (docs/timing/ipu.md)");
  t.addInt("ipu.in_fifo_qwords", &p.in_fifo_qwords, 1, 64, "qwords",
           "T-IPU IFC 4 bits 0..8; P-IPU IPU_Fifo.h 32 words (docs/hardware.md#ipu-fifos-and-dma)");
  t.addInt("ipu.in_buffer_qwords", &p.in_buffer_qwords, 0, 8, "qwords",
           "T-IPU IPU_BP.FP 0..2: internal bit buffer (docs/hardware.md#ipu-fifos-and-dma)");
  t.addInt("ipu.out_fifo_qwords", &p.out_fifo_qwords, 1, 64, "qwords",
           "T-IPU OFC 4 bits; P-IPU IPU_Fifo.h 32 words (docs/hardware.md#ipu-fifos-and-dma)");
  t.addInt("ipu.toipu_cycles_per_qword", &p.toipu_cycles_per_qword, 1, 1'000, "bus cycles/qword",
           "T-DMA: DMAC moves 1 qword per bus cycle while the FIFO has room (docs/hardware.md#ipu-dma)");
  t.addInt("ipu.fromipu_cycles_per_qword", &p.fromipu_cycles_per_qword, 1, 1'000, "bus cycles/qword",
           "T-DMA: DMAC moves 1 qword per bus cycle (docs/hardware.md#ipu-dma)");
  t.addChoice("ipu.idct", &p.idct, {"pcsx2", "libmpeg2", "exact"},
              "the inverse DCT, not known from a hardware capture [A]: pcsx2 = PCSX2's IPU (libmpeg2 0.4's "
              "integer IDCT), libmpeg2 = libmpeg2 0.5.1's C IDCT (mpeg2dec -c), exact = exact-rounded "
              "(docs/timing/ipu.md#idct)");
  t.addInt("ipu.vdec_cycles", &p.vdec_cycles, 0, 100'000, "bus cycles",
           "assumption [A]: VDEC decodes one variable-length symbol (address increment, macroblock type, motion "
           "code, dmvector) with the VLD that IDEC and BDEC use; no published figure, PCSX2 answers at once [E]; "
           "8 cycles; the EE's round trip (ee.vdec_cycles) dominates (docs/timing/ipu.md#the-bdec-flow)");
  t.addInt("ipu.fdec_cycles", &p.fdec_cycles, 0, 100'000, "bus cycles",
           "assumption [A]: FDEC shifts out up to 32 bits; PCSX2 answers at once [E]; 4 cycles "
           "(docs/timing/ipu.md#the-bdec-flow)");
  t.addInt("ipu.setiq_cycles", &p.setiq_cycles, 0, 100'000, "bus cycles",
           "assumption [A]: SETIQ reads a 64-byte quantiser matrix from the input FIFO (T-IPU), one byte per cycle "
           "(docs/timing/ipu.md#the-bdec-flow)");
  t.addInt("ipu.setvq_cycles", &p.setvq_cycles, 0, 100'000, "bus cycles",
           "assumption [A]: SETVQ reads a 16-entry RGB16 CLUT, 32 bytes, one byte per cycle; only for PACK to "
           "4-bit indices, which an RGB32 player (libmpeg, vbim) never issues (docs/timing/ipu.md#the-bdec-flow)");
  t.addInt("ipu.bclr_cycles", &p.bclr_cycles, 0, 100'000, "bus cycles",
           "PCSX2 IPU.cpp: BCLR completes at once [E]; T-IPU: clears the input FIFO and sets the bit pointer "
           "(docs/timing/ipu.md#the-bdec-flow)");
}

IdctKind idctKindOf(const IpuParams& p) {
  return idctKindByName(p.idct).value_or(kDefaultIdct);
}

}  // namespace vbim::ipu
