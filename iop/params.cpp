#include "iop/params.hpp"

namespace vbim::iop {

void describeParams(ParamTable& t, DriveParams& p) {
  t.addChoice("drive.spindle", &p.spindle, {"cav", "clv"},
              "SDK-CD spindle modes: SpinMax/SpinStm = DVD 4x CAV (cav), Spin1p6 = DVD 1.6x CLV (clv)");
  t.addInt("drive.cav_outer_sectors_per_s", &p.cav_outer_sectors_per_s, 1, 100'000, "sectors/s",
           "P-CDVDi DVD_SECTORS_PERSECOND 675 x 4 (DVD 4x at the outer edge) [E]");
  t.addInt("drive.cav_inner_percent", &p.cav_inner_percent, 1, 100, "%",
           "P-CDVD CAV factor 0.40 + 0.60 * LSN / layer: 40 % of the outer rate at LSN 0 (1080 sectors/s) [E]");
  t.addInt("drive.clv_sectors_per_s", &p.clv_sectors_per_s, 1, 100'000, "sectors/s",
           "P-CDVD CLV speed capped at 1.6x: 675 x 1.6 [E]");
  t.addInt("drive.layer_sectors", &p.layer_sectors, 1, 1'000'000'000, "sectors",
           "P-CDVD single-layer DVD size, the scale of the CAV position factor [E]");
  t.addInt("drive.contiguous_window_sectors", &p.contiguous_window_sectors, 0, 1'000'000, "sectors",
           "P-CDVDi: a jump under 16 sectors is no seek (source calls it an arbitrary assumption); here forward jumps "
           "only [E]");
  t.addInt("drive.fast_seek_window_sectors", &p.fast_seek_window_sectors, 0, 1'000'000'000, "sectors",
           "P-CDVDi DVD single layer fast-seek range 14,764 sectors [E]");
  t.addInt("drive.fast_seek_us", &p.fast_seek_us, 0, 10'000'000, "us",
           "P-CDVDi Cdvd_FastSeek_Cycles = 30 ms [E]; PCSX2's own comment estimates a real fast seek at 35-40 ms "
           "(unmeasured)");
  t.addInt("drive.full_seek_us", &p.full_seek_us, 0, 10'000'000, "us",
           "P-CDVDi Cdvd_FullSeek_Cycles = 100 ms [E]; PCSX2's own comment estimates a real seek at 120-160 ms "
           "(unmeasured)");
  t.addInt("drive.revolution_us", &p.revolution_us, 1, 1'000'000, "us",
           "assumption: latency drawn uniform in [0, 1 revolution); 16 ms gives an 8 ms mean, between PCSX2's "
           "4.95 ms and the ~13 ms physical estimate (docs/hardware.md#rotational-latency)");
  t.addInt("drive.spin_up_ms", &p.spin_up_ms, 0, 100'000, "ms", "P-CDVD spin-up from stopped PSXCLK/3 = 333 ms [E]");
  t.addBool("drive.initially_spinning", &p.initially_spinning,
            "assumption: a run starts with the disc stopped, so the first read pays the spin-up");
  t.addInt("drive.read_ahead_sectors", &p.read_ahead_sectors, 0, 4096, "sectors",
           "P-CDVD nextSectorsBuffered < 16: the drive buffers up to 16 sectors ahead while idle [E]");
  t.addInt("drive.dma_iop_cycles_per_sector", &p.dma_iop_cycles_per_sector, 0, 10'000'000, "IOP cycles",
           "P-CDVD IOP DMA ch3 at 12 IOP cycles per word: (2048 / 4) x 12 = 6,144 IOP cycles (167 us) per "
           "2,048-byte streamed sector (SDK-ST reads with datapattern SCECdSecS2048; P-CDVD N_CD_READ BlockSize "
           "2048), overlapping the next read [E]; the 2,064-byte raw sector is sceCdReadDVDV's only");
  t.addInt("drive.retry_count", &p.retry_count, 0, 255, "retries",
           "P-CDVD N_DVD_READ param 8 (sceCdRMode.trycount): retries per failing sector, 0 means 256; each costs a "
           "revolution");
  t.addInt("drive.sector_error_ppm", &p.sector_error_ppm, 0, 1'000'000, "per million sector reads",
           "assumption: 0 on a clean disc (100 is a test value, docs/hardware.md#read-errors); an error fails one "
           "attempt");
}

void describeParams(ParamTable& t, RingParams& p) {
  t.addInt("ring.bufmax_sectors", &p.bufmax_sectors, 1, 1024, "sectors",
           "assumption: sceCdStInit bufmax 160 sectors = 320 KiB of the 2 MB IOP RAM "
           "(docs/hardware.md#stream-ring-size)");
  // At least 3: with 2 banks the driver's rules deadlock. The producer holds its bank while the next
  // bank is the reader's, and the reader, having drained its bank, waits for the held one.
  t.addInt("ring.bankmax", &p.bankmax, 3, 512, "banks",
           "assumption: 5 banks of 32 sectors, about 30 ms of 1.6x reading each (docs/hardware.md#stream-ring-size); "
           "SDK-ST keeps at most bankmax - 1 visible; at least 3, since 2 banks deadlock under SDK-ST's hold rule");
  t.addInt("ring.repoll_ms", &p.repoll_ms, 1, 10'000, "ms", "SDK-ST read-Full alarm 0x48000 IOP cycles = 8 ms");
  t.addInt("ring.issue_retry_ms", &p.issue_retry_ms, 1, 10'000, "ms",
           "SDK-ST alarm 0x708000 IOP cycles = 200 ms after sceCdRE fails (drive busy)");
  t.addInt("ring.read_timeout_ms", &p.read_timeout_ms, 1, 1'000'000, "ms",
           "SDK-CD g_cdvdman_stream_timeout default 5000 ms; on expiry sceCdBreak (error 0x01)");
  t.addInt("ring.first_read_timeout_ms", &p.first_read_timeout_ms, 1, 1'000'000, "ms",
           "SDK-ST 0x20F58000 IOP cycles = 15 s for the first read after start, an error or during retries");
  t.addInt("ring.read_error_retries", &p.read_error_retries, 1, 16, "retries",
           "SDK-ST: 3 retries on error 0x30 or 0x01 (1 on other errors)");
  t.addInt("ring.runup_step_sectors", &p.runup_step_sectors, 0, 1024, "sectors",
           "SDK-ST: retry k starts 16 x (remaining retries) sectors before the target: -32, -16, 0");
}

void describeParams(ParamTable& t, SifParams& p) {
  t.addInt("sif.bandwidth_bytes_per_s", &p.bandwidth_bytes_per_s, 1'000, 2'400'000'000, "bytes/s",
           "assumption: no measured SIF0 rate exists; 20 MB/s sits between the >= 11.5 MB/s observed (FASTNET) and "
           "the 147 MB/s IOP-bus ceiling (docs/hardware.md#sif-rate)");
  t.addInt("sif.setup_us", &p.setup_us, 0, 100'000, "us",
           "assumption: per-sceSifSetDma latency is undocumented; 30 us per chunk (docs/hardware.md#sif-rate)");
}

void describeParams(ParamTable& t, IopParams& p) {
  describeParams(t, p.drive);
  describeParams(t, p.ring);
  describeParams(t, p.sif);
}

void validate(const IopParams& p) {
  if (p.ring.bufmax_sectors < p.ring.bankmax) {
    throw ConfigError("ring.bufmax_sectors (" + std::to_string(p.ring.bufmax_sectors) +
                      ") must be at least ring.bankmax (" + std::to_string(p.ring.bankmax) +
                      "): a bank needs one sector or more");
  }
  if (p.drive.fast_seek_window_sectors < p.drive.contiguous_window_sectors) {
    throw ConfigError("drive.fast_seek_window_sectors must not be below drive.contiguous_window_sectors");
  }
}

}  // namespace vbim::iop
